// singlestrip — the whole pipeline in one call, shared by every front end (CLI, batch, Python,
// render, fuzz targets, test support):
//
//   soup -> prepare_soup (checks, optional re-orientation) -> constraint file -> Mesh::from_soup
//        -> build_strip (StripOptions::engine) -> strip_arrays -> encode_triangle_strip
//        -> optional fundamental cycles,
//
// with the time of each stage. report.hpp turns a PipelineResult into the report JSON.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "singlestrip/cycles.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/soup.hpp"
#include "singlestrip/strip.hpp"

namespace singlestrip {

/// The built-in model names accepted by read_input().
inline constexpr const char* kBuiltinGenus2 = "builtin:genus2";

/// True when `input` names a built-in model ("builtin:..."), not a file.
bool is_builtin_input(const std::string& input) noexcept;

/// Reads INPUT: a mesh file (read_mesh_file with `options`) or `builtin:genus2` (the demo model
/// of generators.hpp). \throw InputError as read_mesh_file(); RequestError for an unknown
/// built-in name. Complexity O(file size).
TriangleSoup read_input(const std::string& input, const ReadOptions& options = {});

struct PipelineOptions {
    /// Engine, seed face, greedy turns, constraint pairs, source and target.
    StripOptions strip;
    /// Re-orient an inconsistently oriented (orientable) soup instead of refusing it.
    bool orient = false;
    /// Also compute the fundamental cycles (cycles.hpp).
    bool cycles = false;
    /// Prefix of input error messages (the file name).
    std::string name = "input";
    /// Constraint file (io.hpp format), read after the input checks; its pairs are appended to
    /// strip.constraint_edges and each must be a mesh edge (messages name the file line).
    std::optional<std::string> constraints_file;
    /// Vertex numbers in constraints_file start at this: 0 (default) or 1 (`--index-base 1`).
    /// strip.source, strip.target and strip.constraint_edges are always 0-based.
    uint32_t index_base = 0;
    /// Tests and fuzzing: Mesh::validate() and a one-component check after Mesh::from_soup,
    /// Mesh::validate() after the strip; O(F) each.
    bool self_check = false;
};

/// Seconds spent per stage. stripify() fills `build` (checks, constraints, corner table) and
/// `strip` (strip, arrays, encoding, cycles); callers that read or write files fill the others.
struct StageSeconds {
    double read = 0, build = 0, strip = 0, write = 0;
};

struct PipelineResult {
    TriangleSoup input;             ///< the soup after the checks (re-oriented if asked)
    PipelineOptions options;        ///< as run: constraint_edges include the file's pairs
    StripResult strip;              ///< split mesh, strip order, stats (stats.engine)
    StripArrays arrays;             ///< output in strip order
    std::vector<uint32_t> indices;  ///< shortest GL_TRIANGLE_STRIP encoding of arrays.faces
    std::optional<Cycles> cycles;   ///< when options.cycles
    StageSeconds seconds;
};

/// Where stripify() is (or stopped): lets a caller that catches an exception tell an expected
/// refusal (InputError in Checks, RequestError in Strip) from a bug.
enum class PipelineStage : uint8_t { Checks, Constraints, Mesh, Strip, Encode, Cycles, Done };

/// "prepare_soup", "constraints", "Mesh::from_soup", "build_strip", "encode_triangle_strip",
/// "compute_fundamental_cycles" or "done".
const char* stage_name(PipelineStage stage) noexcept;

/// Runs the pipeline above on `soup`. `stage` (optional) is updated as each stage starts.
/// \pre none: any soup is accepted, invalid ones are refused.
/// \throw InputError for an invalid mesh (message "<options.name>: ...", validate.hpp) or an
///        unreadable / malformed constraint file; RequestError for an impossible request (seed
///        face, source, target, a constraint pair that is not an edge, constraints that cut the
///        surface apart); InternalError on a bug, including a soup prepare_soup() accepts and
///        Mesh::from_soup() rejects.
/// Complexity: that of the stages, O(V + F log F) for the checks plus build_strip()'s
/// (strip.hpp) plus compute_fundamental_cycles()'s when asked.
PipelineResult stripify(TriangleSoup soup, const PipelineOptions& options, PipelineStage* stage = nullptr);

/// 100 * (output - input) / input triangles (input 0 counts as 1).
double extra_percent(const StripStats& stats) noexcept;

/// GL indices per input triangle (input 0 counts as 1).
double indices_per_triangle(const StripStats& stats, size_t strip_indices) noexcept;

}  // namespace singlestrip
