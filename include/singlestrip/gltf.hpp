// singlestrip — glTF 2.0 export of one strip (and a reader for checking it back). A glTF scene
// in and out, primitive by primitive, is gltf_scene.hpp.
//
// The file holds one scene, one node, one mesh with ONE primitive in mode 5 (TRIANGLE_STRIP)
// whose index accessor is exactly our GL_TRIANGLE_STRIP index sequence (encode.hpp). Core glTF
// has no primitive restart, and a single strip needs none; swaps are repeated indices, which
// every GL decodes as skipped degenerate triangles.
//   * indices: UNSIGNED_SHORT when every index < 65535 (65535 would be the restart value,
//     forbidden by the spec), else UNSIGNED_INT;
//   * POSITION: float32 VEC3 with exact min/max (computed on the float values);
//   * NORMAL: float32 VEC3, unit, per vertex: the strip's NORMAL attribute when it has one
//     (StripArrays::attributes, renormalised), else the area-weighted sum of the normals of the
//     output faces around it (midpoints lie in their parents' planes, so this equals the input's
//     implied normals); vertices without faces, or whose sum vanishes, get (0, 0, 1).
//   * every other attribute of StripArrays::attributes as a float32 accessor: TEXCOORD_n (2
//     components), COLOR_n (3 or 4, clamped to [0, 1]), TANGENT (4) under their names; any
//     other (a PLY property, JOINTS_n, WEIGHTS_n) as a custom "_NAME" accessor (glTF's rule).
// All vertices are written in order (unreferenced ones included) so the indices are unchanged.
// Written with tinygltf (Debian libtinygltf-dev); .glb = binary container, .gltf = JSON with the
// buffer embedded as a base64 data URI. The file is written atomically (temporary + rename).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip {

/// True when `path` ends with .glb or .gltf (case-insensitive).
bool is_gltf_path(const std::string& path);

/// Per-vertex unit normals as described above (double precision). O(V + F).
std::vector<Point3> vertex_normals(const std::vector<Point3>& points, const std::vector<Triangle>& faces);

/// Writes the strip as glTF (.glb or .gltf by extension, see the top of this header).
/// \pre strip_indices == encode_triangle_strip(a.faces) (not re-checked), every index <
///      a.points.size().
/// \throw RequestError for an extension other than .glb/.gltf, for an empty strip, or an index
///        out of range; OutputError when the file cannot be written (no partial file is left).
/// Complexity O(V + F).
void write_gltf_strip(const std::string& path, const StripArrays& a, const std::vector<uint32_t>& strip_indices);

/// glTF INPUT for the plain pipeline: the positions and triangles of every primitive in mode
/// TRIANGLES of every mesh, primitives one after the other (each with its own vertices, in file
/// order; node transforms are not applied; faces re-pointed to the first vertex equal in every
/// attribute, as strip_gltf_file() does, so seams stay apart), and their attributes (decoded to numbers, blend
/// rule blend_for(), attributes.hpp): a primitive without one gets 0 (COLOR_n: 1, white); an
/// attribute with different component counts in two primitives is not kept. \throw InputError naming the file when it cannot be
/// read, an accessor is sparse, compressed or out of bounds, or there is no triangle primitive.
/// O(file size).
TriangleSoup read_gltf_soup(const std::string& path);

/// What read_gltf_strip() found in the first primitive of the first mesh.
struct GltfStrip {
    int mode = -1;                 ///< glTF primitive mode (5 = TRIANGLE_STRIP)
    int index_component_type = 0;  ///< 5123 (UNSIGNED_SHORT) or 5125 (UNSIGNED_INT)
    std::vector<uint32_t> indices;
    std::vector<Point3> positions;  ///< float values widened to double
    std::vector<Point3> normals;    ///< empty when the primitive has no NORMAL
};

/// Reads back a .glb/.gltf written by write_gltf_strip() (tightly packed float VEC3 attributes,
/// unsigned byte/short/int indices). \throw InputError naming the file when it cannot be parsed
/// or is not of that shape.
GltfStrip read_gltf_strip(const std::string& path);

}  // namespace singlestrip
