// singlestrip — the report of one stripped input as JSON: `strip --report`, batch mode's
// <stem>.report.json and the Python result's "report" all come from report_json().
//
// Keys: input, output (when given); engine (the engine that built the strip, or the requested
// one for a failed run); input_triangles, output_triangles, splits, swaps, strip_indices,
// indices_per_triangle, extra_percent, genus, boundary_loops, fundamental_triangles,
// deferred_regions (when there is a result); cycles, cycle_lengths, cycle_faces_total (when cycles were computed);
// options {engine, greedy, orient, constraint_edges, seed_face, source, target (the last three
// when set)}; seconds {read, build, strip, write} (when asked); and for batch mode ok,
// exit_code, error (when failed) and seconds (the file's total time).
#pragma once

#include <optional>
#include <string>

#include "singlestrip/pipeline.hpp"

namespace singlestrip {

/// Batch mode: how one file ended.
struct RunOutcome {
    bool ok = false;
    int exit_code = 0;   ///< errors.hpp exit code (0 when ok)
    std::string error;   ///< message when !ok
    double seconds = 0;  ///< the file's total time
};

struct ReportInput {
    std::string input;                         ///< "input" (omitted when empty)
    std::string output;                        ///< "output" (omitted when empty)
    const PipelineOptions* options = nullptr;  ///< the request; result->options when null
    const PipelineResult* result = nullptr;    ///< null for a failed run
    bool stage_seconds = false;                ///< "seconds": result->seconds per stage
    std::optional<RunOutcome> outcome;         ///< batch: ok, exit_code, error, seconds
};

/// The report as pretty-printed JSON (2-space indent) ending in a newline.
/// \pre options or result is set. \throw InternalError if neither is. O(cycles).
std::string report_json(const ReportInput& report);

}  // namespace singlestrip
