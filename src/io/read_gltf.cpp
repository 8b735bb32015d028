// glTF input (.glb / .gltf): the accessor reader shared with the scene rewriter, and
// read_gltf_soup() for the plain pipeline (info, strip to .ply/.obj/.off, verify).
#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "gltf_access.hpp"
#include "singlestrip/attributes.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/gltf.hpp"

namespace singlestrip {
namespace gltf_detail {
namespace {

// Keeps the encoded image bytes untouched: singlestrip never needs pixels, and the writer then
// stores them back as they were.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes, int size,
                      void*) {
    image->as_is = true;
    image->image.assign(bytes, bytes + size);
    return true;
}

float decode_component(const unsigned char* p, int component_type, bool normalized) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float f;
            std::memcpy(&f, p, 4);
            return f;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return normalized ? static_cast<float>(*p) / 255.0f : static_cast<float>(*p);
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const auto v = static_cast<signed char>(*p);
            return normalized ? std::max(static_cast<float>(v) / 127.0f, -1.0f) : static_cast<float>(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? static_cast<float>(v) / 65535.0f : static_cast<float>(v);
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(static_cast<float>(v) / 32767.0f, -1.0f) : static_cast<float>(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            uint32_t v;
            std::memcpy(&v, p, 4);
            return static_cast<float>(v);
        }
        default:
            return 0.0f;
    }
}

/// A compressed file fails in tinygltf with a message about buffer sizes; name the cause.
std::string compression_hint(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(1 << 20, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    for (const char* ext : {"EXT_meshopt_compression", "KHR_meshopt_compression", "KHR_draco_mesh_compression"})
        if (head.find(ext) != std::string::npos)
            return std::string(" (the file uses ") + ext + ", which singlestrip cannot decode: write it uncompressed first)";
    return {};
}

}  // namespace

tinygltf::Model load_model(const std::string& path) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&keep_image_bytes, nullptr);
    std::string err, warn;
    bool ok = false;
    if (!is_gltf_path(path)) throw InputError(path + ": not a .glb or .gltf file");
    const std::string ext = path.substr(path.find_last_of('.'));
    if (ext.size() == 4)  // ".glb" in any case
        ok = loader.LoadBinaryFromFile(&model, &err, &warn, path);
    else
        ok = loader.LoadASCIIFromFile(&model, &err, &warn, path);
    std::string why = err.empty() ? warn : err;
    while (!why.empty() && std::isspace(static_cast<unsigned char>(why.back()))) why.pop_back();
    if (!ok) throw InputError(path + ": cannot read glTF: " + why + compression_hint(path));
    return model;
}

AccessorData read_accessor(const tinygltf::Model& model, int index, const std::string& path) {
    const std::string who = path + ": accessor " + std::to_string(index);
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) throw InputError(who + " does not exist");
    const tinygltf::Accessor& acc = model.accessors[static_cast<std::size_t>(index)];
    if (acc.sparse.isSparse) throw InputError(who + " is sparse (not supported)");
    if (acc.bufferView < 0 || static_cast<std::size_t>(acc.bufferView) >= model.bufferViews.size())
        throw InputError(who + " has no buffer view (compressed data is not supported)");
    AccessorData d;
    d.count = acc.count;
    d.type = acc.type;
    d.components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(acc.type));
    d.component_type = acc.componentType;
    d.normalized = acc.normalized;
    const int csize = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(acc.componentType));
    if (d.components <= 0 || csize <= 0) throw InputError(who + " has an unknown type");
    d.elem_size = static_cast<std::size_t>(d.components * csize);
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(acc.bufferView)];
    const std::size_t stride = view.byteStride ? view.byteStride : d.elem_size;
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) throw InputError(who + ": no buffer");
    const auto& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::size_t start = view.byteOffset + acc.byteOffset;
    if (d.count && (start + (d.count - 1) * stride + d.elem_size > data.size() ||
                    acc.byteOffset + (d.count - 1) * stride + d.elem_size > view.byteLength))
        throw InputError(who + " runs past its buffer");
    d.raw.resize(d.count * d.elem_size);
    d.values.resize(d.count * static_cast<std::size_t>(d.components));
    for (std::size_t i = 0; i < d.count; ++i) {
        const unsigned char* p = data.data() + start + i * stride;
        std::memcpy(d.raw.data() + i * d.elem_size, p, d.elem_size);
        for (int c = 0; c < d.components; ++c)
            d.values[i * static_cast<std::size_t>(d.components) + static_cast<std::size_t>(c)] =
                decode_component(p + c * csize, acc.componentType, acc.normalized);
    }
    return d;
}

bool is_triangle_primitive(const tinygltf::Primitive& prim) {
    return prim.mode == TINYGLTF_MODE_TRIANGLES && prim.attributes.count("POSITION") != 0;
}

std::string why_not_stripped(const tinygltf::Model& model, const tinygltf::Primitive& prim) {
    if (!is_triangle_primitive(prim)) return "not a TRIANGLES primitive with POSITION";
    if (!prim.targets.empty()) return "has morph targets (not stripped)";
    if (prim.extensions.count("KHR_draco_mesh_compression")) return "Draco-compressed (not stripped)";
    auto usable = [&](int i) {
        if (i < 0 || static_cast<std::size_t>(i) >= model.accessors.size()) return false;
        const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(i)];
        return !a.sparse.isSparse && a.bufferView >= 0 && static_cast<std::size_t>(a.bufferView) < model.bufferViews.size();
    };
    for (const auto& [name, index] : prim.attributes)
        if (!usable(index)) return "attribute " + name + " is sparse or has no buffer view (not stripped)";
    if (prim.indices >= 0 && !usable(prim.indices)) return "indices are sparse or have no buffer view (not stripped)";
    if (model.accessors[static_cast<std::size_t>(prim.attributes.at("POSITION"))].type != TINYGLTF_TYPE_VEC3)
        return "POSITION is not VEC3 (not stripped)";
    return {};
}

std::vector<Point3> primitive_positions(const tinygltf::Model& model, const tinygltf::Primitive& prim, const std::string& path) {
    const AccessorData d = read_accessor(model, prim.attributes.at("POSITION"), path);
    // Quantized positions (KHR_mesh_quantization) are decoded; the node transform is not applied.
    if (d.type != TINYGLTF_TYPE_VEC3) throw InputError(path + ": POSITION is not a VEC3 accessor");
    std::vector<Point3> pts(d.count);
    for (std::size_t i = 0; i < d.count; ++i)
        for (int k = 0; k < 3; ++k) pts[i][static_cast<std::size_t>(k)] = d.values[3 * i + static_cast<std::size_t>(k)];
    return pts;
}

std::vector<Triangle> primitive_triangles(const tinygltf::Model& model, const tinygltf::Primitive& prim, std::size_t vertices,
                                          const std::string& path) {
    std::vector<uint32_t> idx;
    if (prim.indices >= 0) {
        const AccessorData d = read_accessor(model, prim.indices, path);
        for (float v : d.values) idx.push_back(static_cast<uint32_t>(v));
        if (d.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)  // floats lose bits above 2^24
            for (std::size_t i = 0; i < d.count; ++i) std::memcpy(&idx[i], d.raw.data() + 4 * i, 4);
    } else {
        for (std::size_t i = 0; i < vertices; ++i) idx.push_back(static_cast<uint32_t>(i));
    }
    std::vector<Triangle> tris;
    for (std::size_t i = 0; i + 2 < idx.size(); i += 3) {
        for (std::size_t k = 0; k < 3; ++k)
            if (idx[i + k] >= vertices)
                throw InputError(path + ": index " + std::to_string(idx[i + k]) + " is out of range (" + std::to_string(vertices) +
                                 " vertices)");
        tris.push_back({idx[i], idx[i + 1], idx[i + 2]});
    }
    return tris;
}

TriangleSoup primitive_soup(const tinygltf::Model& model, const tinygltf::Primitive& prim, const std::string& path, uint64_t* welded) {
    TriangleSoup soup;
    soup.points = primitive_positions(model, prim, path);
    soup.triangles = primitive_triangles(model, prim, soup.points.size(), path);
    std::vector<AccessorData> attrs;
    for (const auto& [name, index] : prim.attributes) attrs.push_back(read_accessor(model, index, path));
    std::map<std::string, uint32_t> first;
    std::vector<uint32_t> rep(soup.points.size());
    uint64_t merged = 0;
    for (uint32_t v = 0; v < rep.size(); ++v) {
        std::string key;
        for (const AccessorData& d : attrs) key.append(reinterpret_cast<const char*>(d.raw.data() + v * d.elem_size), d.elem_size);
        const auto [it, fresh] = first.emplace(std::move(key), v);
        rep[v] = it->second;
        merged += fresh ? 0 : 1;
    }
    for (Triangle& t : soup.triangles)
        for (uint32_t& v : t) v = rep[v];
    if (welded) *welded = merged;
    return soup;
}

}  // namespace gltf_detail

namespace {

/// What a primitive without the attribute means: glTF draws a missing COLOR_n as white.
double absent_value(const std::string& name) {
    return name.rfind("COLOR_", 0) == 0 ? 1.0 : 0.0;
}

/// Appends `count` vertices' values of `name` to the soup's attribute of that name (created
/// with zeros for the vertices before); a primitive without it gets zeros. An attribute whose
/// component count differs between primitives is marked with components 0 (dropped at the end).
void append_attribute(TriangleSoup& soup, std::size_t before, std::size_t count, const std::string& name,
                      const gltf_detail::AccessorData* d) {
    auto it = std::find_if(soup.attributes.begin(), soup.attributes.end(), [&](const VertexAttribute& a) { return a.name == name; });
    if (it == soup.attributes.end()) {
        soup.attributes.push_back(
            {name, static_cast<uint32_t>(d->components), blend_for(name), std::vector<double>(before * d->components, absent_value(name))});
        it = soup.attributes.end() - 1;
    }
    if (it->components == 0) return;
    if (d && d->components != static_cast<int>(it->components)) {
        it->components = 0;
        return;
    }
    if (d)
        it->values.insert(it->values.end(), d->values.begin(), d->values.end());
    else
        it->values.resize(it->values.size() + count * it->components, absent_value(name));
}

}  // namespace

TriangleSoup read_gltf_soup(const std::string& path) {
    using namespace gltf_detail;
    const tinygltf::Model model = load_model(path);
    TriangleSoup soup;
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            const tinygltf::Primitive& prim = model.meshes[m].primitives[p];
            if (!why_not_stripped(model, prim).empty()) continue;
            const std::size_t base = soup.points.size();
            // As strip_gltf_file() sees it: vertices equal in every attribute merged, seams apart.
            const TriangleSoup part = primitive_soup(model, prim, path);
            const std::vector<Point3>& pts = part.points;
            soup.points.insert(soup.points.end(), pts.begin(), pts.end());
            for (Triangle t : part.triangles)
                soup.triangles.push_back(
                    {t[0] + static_cast<uint32_t>(base), t[1] + static_cast<uint32_t>(base), t[2] + static_cast<uint32_t>(base)});
            for (const auto& [name, index] : prim.attributes)
                if (name != "POSITION") {
                    const AccessorData d = read_accessor(model, index, path);
                    if (d.count == pts.size()) append_attribute(soup, base, pts.size(), name, &d);
                }
            for (VertexAttribute& a : soup.attributes)  // attributes this primitive lacks
                if (a.components && a.values.size() < soup.points.size() * a.components)
                    append_attribute(soup, base, pts.size(), a.name, nullptr);
        }
    if (soup.triangles.empty()) throw InputError(path + ": no faces (no mesh primitive in mode TRIANGLES (4) with a POSITION attribute)");
    std::erase_if(soup.attributes,
                  [&](const VertexAttribute& a) { return a.components == 0 || a.values.size() != soup.points.size() * a.components; });
    return soup;
}

}  // namespace singlestrip
