// glTF in, glTF out (gltf_scene.hpp strip_gltf_file): each triangle primitive is stripped through
// stripify() and rewritten in place as a TRIANGLE_STRIP primitive with new accessors; the rest
// of the model is left as tinygltf read it.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/gltf_access.hpp"
#include "singlestrip/attributes.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/gltf.hpp"
#include "singlestrip/gltf_scene.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/pipeline.hpp"

namespace singlestrip {
namespace {

using gltf_detail::AccessorData;

/// The whole model in buffer 0 (views re-pointed), so new data can be appended to one buffer
/// and a .glb holds everything in its BIN chunk.
void merge_buffers(tinygltf::Model& model) {
    if (model.buffers.empty()) model.buffers.emplace_back();
    std::vector<std::size_t> offset(model.buffers.size(), 0);
    for (std::size_t b = 1; b < model.buffers.size(); ++b) {
        auto& data = model.buffers[0].data;
        while (data.size() % 4) data.push_back(0);
        offset[b] = data.size();
        data.insert(data.end(), model.buffers[b].data.begin(), model.buffers[b].data.end());
    }
    model.buffers.resize(1);
    model.buffers[0].uri.clear();
    for (auto& v : model.bufferViews) {
        if (v.buffer < 0 || static_cast<std::size_t>(v.buffer) >= offset.size()) continue;
        v.byteOffset += offset[static_cast<std::size_t>(v.buffer)];
        v.buffer = 0;
    }
}

int add_view(tinygltf::Model& model, const std::vector<unsigned char>& bytes, int target) {
    auto& data = model.buffers[0].data;
    while (data.size() % 4) data.push_back(0);
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = data.size();
    v.byteLength = bytes.size();
    v.target = target;
    data.insert(data.end(), bytes.begin(), bytes.end());
    model.bufferViews.push_back(v);
    return static_cast<int>(model.bufferViews.size() - 1);
}

/// Embedded (data URI) images move into the buffer: the writer cannot re-encode them otherwise.
void images_to_buffer(tinygltf::Model& model) {
    for (auto& img : model.images)
        if (img.bufferView < 0 && img.uri.empty() && !img.image.empty()) {
            img.bufferView = add_view(model, img.image, 0);
            if (img.mimeType.empty()) img.mimeType = "image/png";
            img.image.clear();
        }
}

// Skin influences stay paired (nearest corner); custom integer attributes may be ids. Everything
// else is interpolated and written as float, which every core attribute (and
// KHR_mesh_quantization's) accepts with the same meaning.
bool interpolated(const std::string& name, const AccessorData& d) {
    if (name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0) return false;
    if (name.rfind('_', 0) == 0) return d.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT || d.normalized;
    return true;
}

/// Internal attribute: the primitive vertex each output vertex copies its non-interpolated
/// attributes from, byte for byte (the Nearest blend of the vertex number).
const char* const kSourceVertex = "\x01source vertex";

/// The primitive's attributes as the pipeline carries them (attributes.hpp): the interpolated
/// ones by value, the others through kSourceVertex.
std::vector<VertexAttribute> soup_attributes(const std::map<std::string, AccessorData>& attrs, std::size_t vertices) {
    std::vector<VertexAttribute> out;
    for (const auto& [name, d] : attrs) {
        if (name == "POSITION" || !interpolated(name, d)) continue;
        out.push_back({name, static_cast<uint32_t>(d.components), blend_for(name), std::vector<double>(d.values.begin(), d.values.end())});
    }
    VertexAttribute source{kSourceVertex, 1, AttributeBlend::Nearest, std::vector<double>(vertices)};
    for (std::size_t v = 0; v < vertices; ++v) source.values[v] = static_cast<double>(v);
    out.push_back(std::move(source));
    return out;
}

/// A new accessor for one attribute over the output vertices: `carried` blended (written as
/// float, TANGENT's w included), or the bytes of vertex `source[v]` for what is not interpolated.
int write_attribute(tinygltf::Model& model, const AccessorData& d, const VertexAttribute* carried, const VertexAttribute& source) {
    tinygltf::Accessor acc;
    acc.count = source.values.size();
    acc.type = d.type;
    std::vector<unsigned char> bytes;
    if (!carried) {
        acc.componentType = d.component_type;
        acc.normalized = d.normalized;
        for (double x : source.values) {
            const auto v = static_cast<std::size_t>(x);
            bytes.insert(bytes.end(), d.raw.begin() + static_cast<std::ptrdiff_t>(v * d.elem_size),
                         d.raw.begin() + static_cast<std::ptrdiff_t>((v + 1) * d.elem_size));
        }
    } else {
        acc.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        for (double x : carried->values) {
            const auto f = static_cast<float>(x);
            const auto* p = reinterpret_cast<const unsigned char*>(&f);
            bytes.insert(bytes.end(), p, p + 4);
        }
    }
    acc.bufferView = add_view(model, bytes, TINYGLTF_TARGET_ARRAY_BUFFER);
    model.accessors.push_back(acc);
    return static_cast<int>(model.accessors.size() - 1);
}

int write_positions(tinygltf::Model& model, const std::vector<Point3>& points) {
    std::vector<unsigned char> bytes;
    tinygltf::Accessor acc;
    acc.minValues.assign(3, std::numeric_limits<double>::infinity());
    acc.maxValues.assign(3, -std::numeric_limits<double>::infinity());
    for (const Point3& p : points)
        for (std::size_t d = 0; d < 3; ++d) {
            const auto f = static_cast<float>(p[d]);  // exact for the input's own (float) vertices
            const auto* b = reinterpret_cast<const unsigned char*>(&f);
            bytes.insert(bytes.end(), b, b + 4);
            acc.minValues[d] = std::min(acc.minValues[d], static_cast<double>(f));
            acc.maxValues[d] = std::max(acc.maxValues[d], static_cast<double>(f));
        }
    acc.count = points.size();
    acc.type = TINYGLTF_TYPE_VEC3;
    acc.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    acc.bufferView = add_view(model, bytes, TINYGLTF_TARGET_ARRAY_BUFFER);
    model.accessors.push_back(acc);
    return static_cast<int>(model.accessors.size() - 1);
}

int write_indices(tinygltf::Model& model, const std::vector<uint32_t>& idx) {
    const uint32_t max = idx.empty() ? 0 : *std::max_element(idx.begin(), idx.end());
    const bool shorts = max < 65535u;  // 65535 would be the (forbidden) restart value
    std::vector<unsigned char> bytes;
    for (uint32_t i : idx) {
        if (shorts) {
            const auto h = static_cast<uint16_t>(i);
            bytes.insert(bytes.end(), reinterpret_cast<const unsigned char*>(&h), reinterpret_cast<const unsigned char*>(&h) + 2);
        } else {
            bytes.insert(bytes.end(), reinterpret_cast<const unsigned char*>(&i), reinterpret_cast<const unsigned char*>(&i) + 4);
        }
    }
    tinygltf::Accessor acc;
    acc.count = idx.size();
    acc.type = TINYGLTF_TYPE_SCALAR;
    acc.componentType = shorts ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    acc.bufferView = add_view(model, bytes, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    model.accessors.push_back(acc);
    return static_cast<int>(model.accessors.size() - 1);
}

GltfPrimitiveResult strip_primitive(tinygltf::Model& model, tinygltf::Primitive& prim, const PipelineOptions& base,
                                    const std::string& name) {
    GltfPrimitiveResult res;
    std::map<std::string, AccessorData> attrs;
    for (const auto& [attr, index] : prim.attributes) attrs.emplace(attr, gltf_detail::read_accessor(model, index, name));
    TriangleSoup soup = gltf_detail::primitive_soup(model, prim, name, &res.welded);
    soup.attributes = soup_attributes(attrs, soup.points.size());
    PipelineOptions o = base;
    o.name = name;
    o.weld = false;  // positions alone would weld across attribute seams
    o.repair_weld = false;
    o.cycles = false;
    o.join = JoinMode::Degenerate;
    o.constraints_file.reset();
    o.strip.constraint_edges.clear();
    o.strip.source.reset();
    o.strip.target.reset();
    o.strip.seed_face.reset();
    const PipelineResult r = stripify(std::move(soup), o);
    const VertexAttribute& source = *find_attribute(r.arrays.attributes, kSourceVertex);
    for (const auto& [attr, d] : attrs) {
        prim.attributes[attr] = attr == "POSITION" ? write_positions(model, r.arrays.points)
                                                   : write_attribute(model, d, find_attribute(r.arrays.attributes, attr), source);
        res.attributes.push_back(attr);
    }
    prim.indices = write_indices(model, degenerate_joined_indices(r));
    prim.mode = TINYGLTF_MODE_TRIANGLE_STRIP;
    const StripStats& st = r.strip.stats;
    res.stripped = true;
    res.input_triangles = st.input_triangles;
    res.output_triangles = st.output_triangles;
    res.splits = st.splits;
    res.strips = static_cast<uint32_t>(r.components.size());
    res.strip_indices = model.accessors[static_cast<std::size_t>(prim.indices)].count;
    if (r.repair) res.repair = r.repair->summary();
    return res;
}

}  // namespace

std::vector<GltfPrimitiveResult> strip_gltf_file(const std::string& in_path, const std::string& out_path, const PipelineOptions& options) {
    if (!is_gltf_path(out_path))
        throw RequestError(out_path + ": glTF input is written as glTF: the output needs the extension .glb or .gltf");
    tinygltf::Model model = gltf_detail::load_model(in_path);
    merge_buffers(model);
    images_to_buffer(model);
    std::vector<GltfPrimitiveResult> out;
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& prim = model.meshes[m].primitives[p];
            const std::string name = in_path + ": mesh " + std::to_string(m) + " primitive " + std::to_string(p);
            GltfPrimitiveResult res;
            res.note = gltf_detail::why_not_stripped(model, prim);
            if (res.note.empty()) res = strip_primitive(model, prim, options, name);
            res.mesh = static_cast<int>(m);
            res.primitive = static_cast<int>(p);
            out.push_back(std::move(res));
        }
    if (std::none_of(out.begin(), out.end(), [](const GltfPrimitiveResult& r) { return r.stripped; })) {
        std::string why;
        for (const auto& r : out) why += "; mesh " + std::to_string(r.mesh) + " primitive " + std::to_string(r.primitive) + ": " + r.note;
        throw InputError(in_path + ": no primitive to strip (none in mode TRIANGLES (4) with a usable POSITION" + why + ")");
    }
    tinygltf::TinyGLTF writer;
    std::ostringstream os(std::ios::binary);
    const bool glb = lower_extension(out_path) == ".glb";
    if (!writer.WriteGltfSceneToStream(&model, os, /*prettyPrint=*/false, /*writeBinary=*/glb))
        throw OutputError(out_path + ": glTF serialisation failed");
    write_text_atomic(out_path, os.str());
    return out;
}

}  // namespace singlestrip
