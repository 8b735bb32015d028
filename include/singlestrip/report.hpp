// singlestrip — the report of one stripped input as JSON: `strip --report`, batch mode's
// <stem>.report.json and the Python result's "report" all come from report_json(); a glTF scene
// stripped primitive by primitive has gltf_report_json().
//
// Keys: input, output (when given); engine (the engine that built the strip, or the requested
// one for a failed run); input_triangles, output_triangles, splits, swaps, strip_indices,
// indices_per_triangle, extra_percent, genus, boundary_loops, fundamental_triangles,
// deferred_regions, strips (one per edge-connected component), components [{input_triangles,
// output_triangles, splits, genus, boundary_loops, first_face, strip_indices}, ...] (output order),
// repair (when --repair: repair_json() below), welded_vertices (when --weld), warnings (when
// any) (all when there is a result); cycles, cycle_lengths, cycle_faces_total (when cycles were computed);
// options {engine, greedy, orient, repair, weld, join, restart_index (restart joins), constraint_edges,
// seed_face, source, target (the last three when set)}; seconds {read, build, strip, write} (when asked); and for batch mode ok,
// exit_code, error (when failed) and seconds (the file's total time).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "singlestrip/gltf_scene.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/repair.hpp"
#include "singlestrip/validate.hpp"

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

/// What repair changed as JSON: summary (text), changed, counts (welded_vertices,
/// invalid_faces, degenerate_faces, duplicate_faces, non_manifold_edges, split_vertices,
/// vertex_copies, orientation_cuts, non_orientable_components, flipped_faces, turned_outward,
/// components) and "elements" with the lists (repair.hpp RepairReport). O(elements).
std::string repair_json(const RepairReport& report);

/// The report as pretty-printed JSON (2-space indent) ending in a newline.
/// \pre options or result is set. \throw InternalError if neither is. O(cycles).
std::string report_json(const ReportInput& report);

/// `info --json`: the counts and problems of mesh_info() (validate.hpp) under the keys file,
/// vertices, referenced_vertices, faces, polygons, edges, boundary_edges, non_manifold_edges,
/// components, component_sizes, boundary_loops, euler_characteristic, genus (null when not
/// meaningful), orientable, oriented, faces_flipped_by_orient (when flipped >= 0),
/// unwelded_vertices, valid, problems [{kind, message}], and repair (repair_json()) when given.
std::string info_json(const std::string& input, const MeshInfo& info, long long flipped, const RepairReport* repair,
                      const std::vector<std::string>& attributes = {});

/// `strip --report` of a glTF scene (strip_gltf_file(), gltf_scene.hpp) as pretty-printed JSON:
/// input, output, primitives [{mesh, primitive, stripped, note, input_triangles,
/// output_triangles, splits, strips, strip_indices, welded_vertices, attributes, repair}, ...].
/// O(primitives).
std::string gltf_report_json(const std::string& input, const std::string& output, const std::vector<GltfPrimitiveResult>& primitives);

}  // namespace singlestrip
