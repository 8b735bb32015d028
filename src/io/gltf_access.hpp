// Internal: reading glTF models and accessors through tinygltf, shared by the glTF reader
// (read_gltf.cpp) and the scene rewriter (gltf_scene.cpp).
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <cstddef>
#include <string>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip::gltf_detail {

/// Loads .glb / .gltf. Images are kept as their encoded bytes (never decoded); external image
/// files are not read (their URI is kept). \throw InputError naming the file.
tinygltf::Model load_model(const std::string& path);

/// One accessor, element by element: `raw` tightly packed (elem_size bytes each, byte stride
/// removed) and `values` decoded to floats (normalized integers mapped to [0,1] / [-1,1]).
struct AccessorData {
    std::size_t count = 0;
    int components = 0;
    int component_type = 0;
    int type = 0;
    bool normalized = false;
    std::size_t elem_size = 0;
    std::vector<unsigned char> raw;
    std::vector<float> values;
};

/// \throw InputError (naming `path` and the accessor) for a missing, sparse or out-of-bounds
/// accessor. O(count).
AccessorData read_accessor(const tinygltf::Model& model, int index, const std::string& path);

/// True for a primitive singlestrip strips: mode TRIANGLES (4) with POSITION.
bool is_triangle_primitive(const tinygltf::Primitive& prim);

/// Why a primitive is left as it is ("" when it can be stripped): not triangles, morph targets,
/// Draco, a POSITION that is not VEC3, a sparse or buffer-less accessor.
std::string why_not_stripped(const tinygltf::Model& model, const tinygltf::Primitive& prim);

/// The primitive's triangles (its indices, or 0,1,2, 3,4,5, ... without indices).
/// \throw InputError for an index out of range of POSITION.
std::vector<Triangle> primitive_triangles(const tinygltf::Model& model, const tinygltf::Primitive& prim, std::size_t vertices,
                                          const std::string& path);

/// Positions of the primitive widened to double (quantized ones decoded, node transform not
/// applied). \throw InputError unless VEC3.
std::vector<Point3> primitive_positions(const tinygltf::Model& model, const tinygltf::Primitive& prim, const std::string& path);

/// The primitive as the strip sees it: its positions, and its triangles re-pointed to the first
/// vertex equal to theirs in EVERY attribute (byte-wise; `welded` gets how many vertices were
/// merged), so attribute seams stay apart. \throw InputError as the readers above.
TriangleSoup primitive_soup(const tinygltf::Model& model, const tinygltf::Primitive& prim, const std::string& path,
                            uint64_t* welded = nullptr);

}  // namespace singlestrip::gltf_detail
