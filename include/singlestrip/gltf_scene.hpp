// singlestrip — glTF in, glTF out: every triangle primitive of a scene through stripify()
// (pipeline.hpp), everything else kept; the file formats are gltf.hpp's.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "singlestrip/pipeline.hpp"

namespace singlestrip {

/// What strip_gltf_file() did with one primitive.
struct GltfPrimitiveResult {
    int mesh = 0, primitive = 0;
    bool stripped = false;
    std::string note;  ///< why it was kept as it was (not triangles, morph targets, compressed)
    uint32_t input_triangles = 0, output_triangles = 0, splits = 0, strips = 0;
    size_t strip_indices = 0;
    uint64_t welded = 0;                  ///< vertices equal in every attribute, merged
    std::vector<std::string> attributes;  ///< attributes carried to the new vertices
    std::string repair;                   ///< RepairReport::summary() with --repair
};

/// glTF in, glTF out: every primitive in mode TRIANGLES of every mesh of `in_path` becomes one
/// TRIANGLE_STRIP primitive (mode 5; several components joined by degenerate triangles) through
/// stripify() with `options` (constraints, source, target and cycles are not applied: vertex ids
/// are per primitive); everything else — nodes, materials, textures, images, other primitives,
/// extensions tinygltf keeps — is written back unchanged to `out_path` (.glb or .gltf).
/// Vertices: a glTF vertex is a position plus all its attributes, so vertices are merged only
/// when every attribute is byte-equal, and attribute seams stay boundaries (the picture is
/// unchanged; --repair never welds across them). Inserted midpoints get their parent face's
/// attributes interpolated barycentrically (NORMAL renormalised; TANGENT xyz renormalised, w
/// copied); integer attributes that cannot be interpolated (JOINTS_n, and WEIGHTS_n with them,
/// non-normalised integers) are copied from the nearest corner. Embedded images are kept as
/// their bytes in the single output buffer; external image URIs are kept as written.
/// \throw InputError as read_gltf_soup() or stripify() (naming mesh and primitive); RequestError
/// for an output that is not .glb/.gltf; OutputError when it cannot be written.
/// Complexity: stripify() per primitive plus O(file size).
std::vector<GltfPrimitiveResult> strip_gltf_file(const std::string& in_path, const std::string& out_path, const PipelineOptions& options);

}  // namespace singlestrip
