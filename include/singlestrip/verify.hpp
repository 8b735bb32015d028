// singlestrip — the independent verifier behind `singlestrip verify`.
//
// Independence. This checker shares no code with the strip builder, the mesh core (mesh.cpp)
// or the encoder: it has its own adjacency (hash maps over vertex pairs), its own
// GL_TRIANGLE_STRIP decoder and its own readers for the OUTPUT files (.ply/.obj/.off). Only
// verify_files() uses the project's input readers (io.hpp), to read the INPUT mesh and the
// constraint file.
//
// What verify() checks (every failure message names the property and the face numbers):
//   * original vertices unchanged: out_points[0..n) == in_points exactly (n = in_points.size());
//   * geometry: each output face lies in its parent's plane and inside the parent (barycentric,
//     tolerance 1e-9 relative to the parent's size, plus 16 ulps of its largest coordinate
//     turned into barycentric terms by its shape: a midpoint's rounding in a thin face far
//     from the origin), is not degenerate, and has the parent's
//     orientation; per parent the children's areas sum to the parent's area (relative 1e-9);
//     every input face has at least one child;
//     Nearly degenerate parents (|normal| <= 1e-6 size^2, where barycentric coordinates are
//     ill-conditioned, or a height within 16 roundings of the coordinates (float32 outputs: a
//     float32 step); zero-area faces included) get a robust test instead: every child vertex
//     within the parent's bounding box and within its height of its longest edge, no child
//     larger than the parent, areas unsigned, orientation not checked (reported as a note).
//     Coordinates are scaled by a power of two per face first, so huge or tiny ones are exact.
//   * conforming oriented manifold: no repeated vertex in a face, no duplicate face, every edge
//     in at most two faces traversed in opposite directions, every vertex one fan, no
//     T-junction (every output edge with one face lies on an input boundary edge and the output
//     boundary edges tile each input boundary edge exactly); same Euler characteristic and
//     number of boundary loops as the input (referenced vertices only);
//   * strips: one per edge-connected component of the output, each a contiguous run of faces
//     in which consecutive faces share an edge (two common vertices);
//   * indices (optional): the standard GL_TRIANGLE_STRIP decoding (triangle i = s[i],s[i+1],
//     s[i+2], odd i flipped, triangles with a repeated index skipped; `restart_index` ends a
//     strip and the next starts at even parity) gives exactly out_faces, in order, each with the
//     same cyclic vertex order (degenerate joins between strips decode to nothing);
//   * constraints (optional): every pair is an input edge; no two consecutive faces share a
//     constraint edge or a piece of one; no constraint edge is split (the edge is an output
//     edge and no output vertex lies strictly inside it);
//   * source/target (optional): the first face has vertex `source`, the last face of the first
//     strip has `target`;
//   * attributes (when both sides carry some; matched by name, others noted): every referenced
//     output vertex's values: an input vertex (index < n) has the input's values; any other
//     vertex lies in its parent face and has the blend of the parent's corners at its
//     barycentric coordinates (the verifier's own): Linear the weighted average (a midpoint:
//     its edge's two ends averaged), Unit that average renormalised (a TANGENT's w and a
//     Nearest attribute: the values of one corner of largest weight). Tolerance per component:
//     abs + rel * |expected|, from how the file stores the attribute (OutputAttribute), stated
//     in each failure, which names the vertex, the attribute and both values;
//   * cycles (optional; one-component outputs only, else a note): each cycle is a closed chain of edge-adjacent output faces; there are
//     2g+h-1 of them (2g for a closed surface); they are linearly independent in H1(M; Z2),
//     tested by their intersection parities with a basis of H1(M, dM) built by tree-cotree on
//     the output mesh, Gaussian elimination over Z2 (rank must equal the count).
//
// Parent inference. When out_parent is empty (glTF, OBJ, OFF outputs) the parents come from the
// split structure first, with no tolerance: an output face that is an input face is its own
// parent; one with two input vertices lies in the input face holding the directed edge between
// them; every inserted vertex is matched to the two earlier vertices it is the midpoint of
// (exactly, or after rounding to float32), which gives its carrier (the input vertex, edge or
// face holding it), and a face lies in the input face holding its three carriers. Faces this
// cannot place get the input face containing their centroid, among the input faces around their
// input vertices or around a neighbouring face's parent (breadth-first over output faces). The
// geometry checks then test the parents found like given ones. Geometry alone cannot place
// needles thinner than a float32 step (a polygon's ears far from the origin), combinatorics can.
//
// Complexity: O((V + F) * (1 + average hashing cost)) for everything except the cycle check,
// which costs O(L + (V + E) * m / 64 + m^3 / 64) for m cycles of total length L, and the
// parent inference: O(F log F), plus for each inserted vertex the pairs among at most 128
// earlier vertices reachable from it, and the geometric fallback's stars (degree^2 around a fan's apex).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip {

/// One vertex attribute of the output as read back from a file, and how exactly the file holds it.
struct OutputAttribute {
    std::string name;  ///< glTF name as the readers give it (NORMAL, COLOR_0, TEXCOORD_0, custom)
    uint32_t components = 1;
    std::vector<double> values;  ///< components per output vertex; NaN where the file gives none
    double abs_tol = 1e-9;       ///< allowed |got - expected| = abs_tol + rel_tol * |expected|
    double rel_tol = 1e-9;
    std::string storage = "double";  ///< named in messages: "double", "float32", "8-bit", "integer", "decimal text"
};

/// Everything verify() looks at. Indices are 0-based; vertex ids of `constraints`, `source`,
/// `target` are input vertex ids (== output vertex ids, by the output contract).
struct VerifyInput {
    std::vector<Point3> in_points;
    std::vector<Triangle> in_faces;
    std::vector<Point3> out_points;
    std::vector<Triangle> out_faces;               ///< in strip order
    std::vector<uint32_t> out_parent;              ///< parent input face per output face; empty = infer
    std::optional<std::vector<uint32_t>> indices;  ///< GL_TRIANGLE_STRIP indices
    std::vector<std::pair<uint32_t, uint32_t>> constraints;
    std::optional<uint32_t> source;
    std::optional<uint32_t> target;
    std::optional<std::vector<std::vector<uint32_t>>> cycles;  ///< face-index chains into out_faces
    uint32_t restart_index = 0xffffffffu;                      ///< primitive restart value in `indices`
    /// out_points are float32 (a glTF output): input vertices are compared after rounding to
    /// float32 and every geometric tolerance is 1e-5 (relative) instead of 1e-9; a note says so.
    bool float32 = false;
    /// The input's vertex attributes (blend rules from here) and the output's as read back;
    /// either empty: attributes are not checked.
    std::vector<VertexAttribute> in_attributes;
    std::vector<OutputAttribute> out_attributes;
};

/// The VerifyInput of one strip: `input` against `output` (points, faces in strip order, parents)
/// and its `indices`; constraints, source, target and cycles are the caller's. O(V + F).
VerifyInput verify_input(const TriangleSoup& input, const StripArrays& output, const std::vector<uint32_t>& indices);

/// The verifier's own GL_TRIANGLE_STRIP decoder (see "indices" above). O(n).
std::vector<Triangle> verify_decode_strip(const std::vector<uint32_t>& indices, uint32_t restart_index = 0xffffffffu);

struct VerifyReport {
    std::vector<std::string> failures;  ///< one line per violated property (capped per check)
    std::vector<std::string> notes;     ///< checks skipped because an earlier one failed, etc.
    size_t faces_checked = 0;           ///< output faces examined
    size_t input_faces = 0;
    size_t output_faces = 0;
    size_t output_vertices = 0;          ///< referenced output vertices
    long long euler_characteristic = 0;  ///< of the output (referenced vertices)
    size_t boundary_loops = 0;           ///< of the output
    long long genus = 0;                 ///< of the output (summed over components), from Euler characteristic and loops
    size_t strips = 0;                   ///< strips found (one per edge-connected component)
    size_t cycles_checked = 0;
    size_t cycle_rank = 0;  ///< Z2 rank of the cycles (when computed)
    [[nodiscard]] bool ok() const noexcept { return failures.empty(); }
    /// Human-readable multi-line summary: "OK ..." or the failures.
    [[nodiscard]] std::string to_string() const;
};

/// Checks every property listed at the top of this header. Pure; never throws on bad data
/// (out-of-range indices, NaN, empty arrays): each problem becomes a failure line.
/// \throw std::bad_alloc only.
VerifyReport verify(const VerifyInput& input);

/// The input steps a strip run was asked for (`strip --weld / --repair / --orient`).
struct InputSteps {
    bool weld = false, repair = false, orient = false;
    bool repair_weld = true;  ///< RepairOptions::weld (off for glTF primitives)
};

/// Makes vi.in_points / vi.in_faces the input the strip was built from: the SAME steps replayed
/// with the library's own weld_soup / repair_soup / orient_soup (repair.hpp, validate.hpp) —
/// this part of the check depends on the library, not on independent code. vi.out_parent
/// (input face ids) is mapped to the repaired faces (a dropped face maps out of range, which
/// verify() reports). `attributes` are the input's vertex attributes (soup.hpp): the weld keeps
/// their seams apart, as the strip run did. Returns notes saying what the replay changed.
/// Complexity: repair_soup().
std::vector<std::string> replay_input_steps(VerifyInput& vi, const InputSteps& steps, std::vector<VertexAttribute> attributes = {});

/// Optional extra files for verify_files().
struct VerifyFileOptions {
    std::optional<std::string> indices_path;      ///< whitespace-separated GL_TRIANGLE_STRIP indices
    std::optional<std::string> constraints_path;  ///< polylines, as for `strip --constraints`
    std::optional<uint32_t> source;
    std::optional<uint32_t> target;
    std::optional<std::string> cycles_path;  ///< JSON {"cycles": [[face, ...], ...]}
    std::string input_format;                ///< ReadOptions::format for the input mesh
    uint32_t restart_index = 0xffffffffu;    ///< restart value in the indices file
    InputSteps steps;                        ///< --weld / --repair / --orient of the strip run
    uint32_t index_base = 0;                 ///< vertex numbers in constraints_path start at 0 or 1
};

/// A glTF OUT (.glb/.gltf written by `strip`, one TRIANGLE_STRIP primitive) is read with
/// read_gltf_strip() (gltf.hpp, tinygltf), its faces decoded by verify_decode_strip(), parents
/// inferred (from the split structure, see above), and checked with VerifyInput::float32.
/// Reads the input mesh (read_mesh_file), the output mesh (read_output_mesh) and the optional
/// files, then runs verify() (after the weld / repair / orient replay asked for). Parents come
/// from the PLY `parent` property when present, else they are inferred (see above).
/// \throw InputError (naming the file) when a file is missing, unreadable or malformed; the
///        verification results themselves are never thrown, they are in the report.
VerifyReport verify_files(const std::string& in_path, const std::string& out_path, const VerifyFileOptions& options = {});

/// The same with the input mesh already read (e.g. a built-in model); options.input_format is
/// not used.
VerifyReport verify_files(TriangleSoup input, const std::string& out_path, const VerifyFileOptions& options = {});

/// An output mesh as read back from a file.
struct OutputMesh {
    std::vector<Point3> points;
    std::vector<Triangle> faces;
    std::vector<uint32_t> parent;  ///< empty unless the PLY has a face property `parent`
    /// PLY vertex properties (grouped as the writer names them: nx ny nz, red green blue [alpha],
    /// s t; name_0 name_1 ...), OBJ vt / vn / "v x y z r g b", OFF normals, colours, s t.
    std::vector<OutputAttribute> attributes;
};

/// Reads an output file by extension: .ply (ascii, binary_little_endian or binary_big_endian;
/// vertex properties x y z of any numeric type; face list `vertex_indices` (or `vertex_index`);
/// optional face property `parent`), .obj (v / vt / vn / f records, "i", "i/t", "i/t/n", "i//n",
/// negative indices relative), .off ([ST][C][N]OFF). This reader is the verifier's own
/// (independent of io.hpp).
/// \throw InputError naming the file and the problem: missing/unreadable, unknown extension,
///        malformed header, truncated data, a face that is not a triangle, an index out of range,
///        an OBJ vertex given two texture coordinates or normals by its corners.
OutputMesh read_output_mesh(const std::string& path);

/// glTF in and glTF out (`strip scene.glb -o out.glb`): every primitive of OUT in mode 5 is
/// checked by verify() against the same primitive of IN as the strip saw it (positions; triangles
/// merged over vertices equal in every attribute; with steps.repair the library's repair without
/// welding — library code, said in a note), with VerifyInput::float32 and parents inferred.
/// Failures are prefixed "mesh M primitive P: "; counts are summed. Primitives left as they were
/// are noted. \throw InputError naming a file that cannot be read or whose meshes differ in shape.
VerifyReport verify_gltf_scene(const std::string& in_path, const std::string& out_path, const InputSteps& steps = {});

/// Reads whitespace-separated non-negative integers (an --indices file).
/// \throw InputError naming the file and the offending token.
std::vector<uint32_t> read_index_file(const std::string& path);

/// Reads a cycles JSON file {"cycles": [[face, ...], ...]}.
/// \throw InputError naming the file when it is missing or not of that shape.
std::vector<std::vector<uint32_t>> read_cycles_file(const std::string& path);

}  // namespace singlestrip
