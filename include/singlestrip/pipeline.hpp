// singlestrip — the whole pipeline in one call, shared by every front end (CLI, batch, Python,
// render, fuzz targets, test support):
//
//   soup -> optional weld / repair (repair.hpp) -> prepare_soup (checks, optional re-orientation)
//        -> constraint file -> per edge-connected component: Mesh::from_soup -> build_strip
//        (StripOptions::engine) -> strip_arrays -> encode_triangle_strip -> optional
//        fundamental cycles; the strips joined (JoinMode, encode.hpp),
//
// with the time of each stage. report.hpp turns a PipelineResult into the report JSON.
//
// Several components. Each edge-connected component gets its own strip; the output holds them
// one after the other (components ordered by their lowest input face, except that the one
// holding `source` / `target` comes first), and the index sequence joins them (JoinMode). Vertex
// numbering stays global: input vertices (and repair copies) first, then the midpoints of each
// strip in strip order. source and target must lie in the same component (RequestError naming
// both otherwise): they are the start and end of the FIRST strip. A seed face seeds its own
// component's strip. Constraint pairs go to the component holding them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "singlestrip/cycles.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/repair.hpp"
#include "singlestrip/soup.hpp"
#include "singlestrip/strip.hpp"

namespace singlestrip {

/// The built-in model names accepted by read_input().
inline constexpr const char* kBuiltinGenus2 = "builtin:genus2";

/// True when `input` names a built-in model ("builtin:..."), not a file.
bool is_builtin_input(const std::string& input) noexcept;

/// Reads INPUT: a mesh file (read_mesh_file with `options`) or `builtin:genus2` (the demo model
/// of models.hpp). \throw InputError as read_mesh_file(); RequestError for an unknown
/// built-in name. Complexity O(file size).
TriangleSoup read_input(const std::string& input, const ReadOptions& options = {});

struct PipelineOptions {
    /// Engine, seed face, greedy turns, constraint pairs, source and target.
    StripOptions strip;
    /// Re-orient an inconsistently oriented (orientable) soup instead of refusing it; each
    /// component keeps the orientation of the majority of its faces.
    bool orient = false;
    /// Merge exactly coincident vertices first (weld_soup(), repair.hpp).
    bool weld = false;
    /// Repair the soup first (repair_soup(), repair.hpp: weld, drop degenerate and duplicate
    /// faces, cut non-manifold and non-orientable parts apart, orient). Output parents stay input
    /// face indices; repair's vertex copies follow the input vertices.
    bool repair = false;
    /// With repair: its weld step (RepairOptions::weld; off for glTF primitives).
    bool repair_weld = true;
    /// How the strips of several components are joined in `indices`.
    JoinMode join = JoinMode::Degenerate;
    /// The restart index for JoinMode::Restart.
    uint32_t restart_index = 0xffffffffu;
    /// Also compute the fundamental cycles (cycles.hpp).
    bool cycles = false;
    /// Prefix of input error messages (the file name).
    std::string name = "input";
    /// Constraint file (io.hpp format), read after the input checks; its pairs are appended to
    /// strip.constraint_edges with their lines. Every pair there, given or read, must be a mesh
    /// edge: checked once, in the Constraints stage (messages name the file line, or the index
    /// of a pair given directly).
    std::optional<std::string> constraints_file;
    /// Vertex numbers in constraints_file start at this: 0 (default) or 1 (`--index-base 1`).
    /// strip.source, strip.target and strip.constraint_edges are always 0-based.
    uint32_t index_base = 0;
    /// Tests and fuzzing: Mesh::validate() and a one-component check after Mesh::from_soup,
    /// Mesh::validate() after the strip; O(F) each.
    bool self_check = false;
    /// Front ends that only write the output (CLI, batch): free each intermediate once used, for
    /// a lower peak (issue 17). One component without attributes: `input` is left empty (its
    /// points move into the mesh), and `strip` keeps only its stats (the mesh's points move into
    /// `arrays`); the cycles are computed before the arrays then.
    bool release_intermediates = false;
};

/// Seconds spent per stage. stripify() fills `build` (checks, constraints, corner table) and
/// `strip` (strip, arrays, encoding, cycles); callers that read or write files fill the others.
struct StageSeconds {
    double read = 0, build = 0, strip = 0, write = 0;
};

/// One strip of the output: an edge-connected component of the (repaired) input.
struct ComponentStrip {
    uint32_t input_triangles = 0, output_triangles = 0, splits = 0;
    long long genus = 0;
    uint32_t boundary_loops = 0;
    size_t first_face = 0;     ///< its faces are arrays.faces[first_face, first_face + output_triangles)
    size_t strip_indices = 0;  ///< length of its own GL_TRIANGLE_STRIP encoding (before joining)
};

struct PipelineResult {
    TriangleSoup input;       ///< the soup after repair and checks (re-oriented if asked)
    PipelineOptions options;  ///< as run: constraint_edges include the file's pairs
    /// One component: the split mesh, strip order, stats (stats.engine). Several: `stats` holds
    /// the totals (genus and boundary loops summed), mesh and order are empty (see `components`).
    StripResult strip;
    StripArrays arrays;                      ///< output in strip order; parent = face of the soup given to stripify()
    std::vector<uint32_t> indices;           ///< shortest GL_TRIANGLE_STRIP encoding per strip, joined (options.join)
    std::vector<ComponentStrip> components;  ///< one per strip, in output order
    std::optional<Cycles> cycles;            ///< when options.cycles (face indices into arrays.faces)
    std::optional<RepairReport> repair;      ///< when options.repair
    uint64_t welded = 0;                     ///< options.weld: vertices merged
    /// input face (of the soup given to stripify()) of each face of `input`; empty = identity.
    std::vector<uint32_t> face_origin;
    std::vector<std::string> warnings;  ///< e.g. many components that --weld would join
    StageSeconds seconds;
};

/// The index sequence for a glTF TRIANGLE_STRIP primitive: `indices` joined by degenerate
/// triangles (glTF core has no primitive restart). O(indices).
std::vector<uint32_t> degenerate_joined_indices(const PipelineResult& result);

/// Where stripify() is (or stopped): lets a caller that catches an exception tell an expected
/// refusal (InputError in Checks; a constraint file's InputError or a constraint pair's
/// RequestError in Constraints; RequestError in Strip) from a bug.
enum class PipelineStage : uint8_t { Checks, Constraints, Mesh, Strip, Encode, Cycles, Done };

/// "prepare_soup", "constraints", "Mesh::from_soup", "build_strip", "encode_triangle_strip",
/// "compute_fundamental_cycles" or "done".
const char* stage_name(PipelineStage stage) noexcept;

/// Runs the pipeline above on `soup`. `stage` (optional) is updated as each stage starts.
/// \pre none: any soup is accepted, invalid ones are refused.
/// \throw InputError for an invalid mesh (message "<options.name>: ...", validate.hpp, naming
///        the option that fixes it) or an
///        unreadable / malformed constraint file; RequestError for an impossible request (seed
///        face, source, target, a constraint pair that is not an edge, constraints that cut the
///        surface apart, source and target in different components); InternalError on a bug, including a soup prepare_soup() accepts and
///        Mesh::from_soup() rejects.
/// Complexity: that of the stages, O(V + F log F) for the checks plus build_strip()'s
/// (strip.hpp) plus compute_fundamental_cycles()'s when asked.
PipelineResult stripify(TriangleSoup soup, const PipelineOptions& options, PipelineStage* stage = nullptr);

/// 100 * (output - input) / input triangles (input 0 counts as 1).
double extra_percent(const StripStats& stats) noexcept;

/// GL indices per input triangle (input 0 counts as 1).
double indices_per_triangle(const StripStats& stats, size_t strip_indices) noexcept;

}  // namespace singlestrip
