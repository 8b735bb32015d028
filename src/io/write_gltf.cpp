// glTF export of one strip through tinygltf. This is the one translation unit that compiles
// tinygltf's implementation; images are never used, so stb_image is left out.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "float32_range.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/gltf.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/vec3.hpp"

namespace singlestrip {
namespace {

template <class T>
void append_bytes(std::vector<unsigned char>& buf, const T& v) {
    const auto* p = reinterpret_cast<const unsigned char*>(&v);
    buf.insert(buf.end(), p, p + sizeof(T));
}

constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

/// The glTF name attribute `a` is written under: its own when it has the components glTF asks
/// for that name, else a custom "_NAME" (custom names must start with '_'); "" for NORMAL
/// (written separately) and for what no accessor type holds.
std::string gltf_name(const VertexAttribute& a) {
    if (a.name == "NORMAL" || a.components < 1 || a.components > 4) return {};
    auto starts = [&](const char* p) { return a.name.rfind(p, 0) == 0; };
    const bool fits =
        (starts("TEXCOORD_") && a.components == 2) || (starts("COLOR_") && a.components >= 3) || (a.name == "TANGENT" && a.components == 4);
    if (fits || starts("_")) return a.name;
    std::string custom = "_" + a.name;
    for (char& c : custom) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return custom;
}

/// Unit normals from a NORMAL attribute (zero or missing ones become (0, 0, 1)).
std::vector<Point3> attribute_normals(const VertexAttribute& a, std::size_t nv) {
    std::vector<Point3> n(nv, Point3{0, 0, 1});
    for (std::size_t v = 0; v < nv && (v + 1) * 3 <= a.values.size(); ++v) {
        const double* x = &a.values[3 * v];
        const double len = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        if (len > 0 && std::isfinite(len)) n[v] = {x[0] / len, x[1] / len, x[2] / len};
    }
    return n;
}

/// Appends attribute `a` as a float accessor (colours clamped to [0, 1]) with its own view.
void add_attribute(tinygltf::Model& model, tinygltf::Primitive& prim, const std::string& name, const VertexAttribute& a) {
    auto& buf = model.buffers[0].data;
    while (buf.size() % 4 != 0) buf.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buf.size();
    view.target = kArrayBuffer;
    const bool colour = name.rfind("COLOR_", 0) == 0;
    for (double x : a.values) append_bytes(buf, static_cast<float>(colour ? std::clamp(x, 0.0, 1.0) : x));
    view.byteLength = buf.size() - view.byteOffset;
    model.bufferViews.push_back(view);
    tinygltf::Accessor acc;
    acc.bufferView = static_cast<int>(model.bufferViews.size() - 1);
    acc.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    acc.count = a.values.size() / a.components;
    static const int types[] = {TINYGLTF_TYPE_SCALAR, TINYGLTF_TYPE_VEC2, TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4};
    acc.type = types[a.components - 1];
    model.accessors.push_back(acc);
    prim.attributes[name] = static_cast<int>(model.accessors.size() - 1);
}

}  // namespace

bool is_gltf_path(const std::string& path) {
    const std::string ext = lower_extension(path);
    return ext == ".glb" || ext == ".gltf";
}

std::vector<Point3> vertex_normals(const std::vector<Point3>& points, const std::vector<Triangle>& faces) {
    std::vector<Point3> n(points.size(), Point3{0, 0, 0});
    for (const Triangle& f : faces) {
        if (f[0] >= points.size() || f[1] >= points.size() || f[2] >= points.size()) continue;
        const Point3& a = points[f[0]];
        const Point3& b = points[f[1]];
        const Point3& c = points[f[2]];
        // The unnormalised cross product is twice the area times the unit normal: area weighting.
        const Point3 cr = vec3::cross(vec3::sub(b, a), vec3::sub(c, a));
        for (uint32_t k : f)
            for (int d = 0; d < 3; ++d) n[k][d] += cr[d];
    }
    for (Point3& x : n) {
        const double len = vec3::norm(x);
        if (len > 0 && std::isfinite(len)) {
            for (double& c : x) c /= len;
        } else {
            x = Point3{0, 0, 1};  // glTF requires unit normals even on unused vertices
        }
    }
    return n;
}

namespace {

/// The largest strip index; \throw RequestError for an index past the vertices.
uint32_t max_strip_index(const std::string& path, const std::vector<uint32_t>& strip_indices, size_t nv) {
    uint32_t max_index = 0;
    for (uint32_t i : strip_indices) {
        if (i >= nv)
            throw RequestError(path + ": strip index " + std::to_string(i) + " is out of range (" + std::to_string(nv) + " vertices)");
        max_index = std::max(max_index, i);
    }
    return max_index;
}

/// Positions, normals and indices in one buffer, with where each starts.
struct StripBuffer {
    std::vector<unsigned char> bytes;
    size_t normals_offset = 0;
    size_t indices_offset = 0;
    size_t indices_bytes = 0;
    std::array<double, 3> pmin{}, pmax{};
};

StripBuffer pack_strip_buffer(const std::vector<Point3>& points, const std::vector<Point3>& normals,
                              const std::vector<uint32_t>& strip_indices, bool short_indices) {
    StripBuffer b;
    auto& buf = b.bytes;
    buf.reserve(points.size() * 24 + strip_indices.size() * 4 + 4);
    for (int d = 0; d < 3; ++d) {
        b.pmin[d] = std::numeric_limits<double>::infinity();
        b.pmax[d] = -std::numeric_limits<double>::infinity();
    }
    for (const Point3& p : points) {
        for (int d = 0; d < 3; ++d) {
            const float f = static_cast<float>(p[d]);
            append_bytes(buf, f);
            // min/max must equal the stored float values exactly (the validator recomputes them).
            b.pmin[d] = std::min(b.pmin[d], static_cast<double>(f));
            b.pmax[d] = std::max(b.pmax[d], static_cast<double>(f));
        }
    }
    b.normals_offset = buf.size();
    for (const Point3& n : normals)
        for (int d = 0; d < 3; ++d) append_bytes(buf, static_cast<float>(n[d]));
    b.indices_offset = buf.size();  // multiple of 4: aligned for either index type
    for (uint32_t i : strip_indices) {
        if (short_indices)
            append_bytes(buf, static_cast<uint16_t>(i));
        else
            append_bytes(buf, i);
    }
    b.indices_bytes = buf.size() - b.indices_offset;
    while (buf.size() % 4 != 0) buf.push_back(0);
    return b;
}

int add_view(tinygltf::Model& model, size_t offset, size_t length, int target) {
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = offset;
    v.byteLength = length;
    v.target = target;
    model.bufferViews.push_back(v);
    return static_cast<int>(model.bufferViews.size() - 1);
}

tinygltf::Accessor accessor(int view, int component_type, size_t count, int type) {
    tinygltf::Accessor acc;
    acc.bufferView = view;
    acc.componentType = component_type;
    acc.count = count;
    acc.type = type;
    return acc;
}

/// Buffer 0 with its three views and accessors 0 (POSITION), 1 (NORMAL) and 2 (indices).
void add_strip_accessors(tinygltf::Model& model, StripBuffer b, size_t nv, size_t num_indices, bool short_indices) {
    tinygltf::Buffer buffer;
    buffer.data = std::move(b.bytes);
    model.buffers.push_back(std::move(buffer));
    const int pos_view = add_view(model, 0, nv * 12, kArrayBuffer);
    const int nrm_view = add_view(model, b.normals_offset, nv * 12, kArrayBuffer);
    const int idx_view = add_view(model, b.indices_offset, b.indices_bytes, kElementArrayBuffer);

    tinygltf::Accessor pos = accessor(pos_view, TINYGLTF_COMPONENT_TYPE_FLOAT, nv, TINYGLTF_TYPE_VEC3);
    pos.minValues.assign(b.pmin.begin(), b.pmin.end());
    pos.maxValues.assign(b.pmax.begin(), b.pmax.end());
    model.accessors.push_back(pos);
    model.accessors.push_back(accessor(nrm_view, TINYGLTF_COMPONENT_TYPE_FLOAT, nv, TINYGLTF_TYPE_VEC3));
    const int index_type = short_indices ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    model.accessors.push_back(accessor(idx_view, index_type, num_indices, TINYGLTF_TYPE_SCALAR));
}

/// Mesh 0 ("strip", one triangle-strip primitive with the attributes that fit), node 0, scene 0.
void add_strip_scene(tinygltf::Model& model, const std::vector<VertexAttribute>& attributes, size_t nv) {
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = 0;
    prim.attributes["NORMAL"] = 1;
    prim.indices = 2;
    prim.mode = TINYGLTF_MODE_TRIANGLE_STRIP;
    for (const VertexAttribute& at : attributes)
        if (const std::string name = gltf_name(at); !name.empty() && at.values.size() == nv * at.components && !prim.attributes.count(name))
            add_attribute(model, prim, name, at);
    tinygltf::Mesh mesh;
    mesh.name = "strip";
    mesh.primitives.push_back(prim);
    model.meshes.push_back(mesh);

    tinygltf::Node node;
    node.mesh = 0;
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    model.scenes.push_back(scene);
    model.defaultScene = 0;
}

}  // namespace

void write_gltf_strip(const std::string& path, const StripArrays& a, const std::vector<uint32_t>& strip_indices) {
    const std::string ext = lower_extension(path);
    if (ext != ".glb" && ext != ".gltf") throw RequestError(path + ": glTF output needs the extension .glb or .gltf");
    if (strip_indices.empty() || a.faces.empty()) throw RequestError(path + ": nothing to write (empty strip)");
    const size_t nv = a.points.size();
    check_float32_range(path, a.points, "glTF");
    const bool short_indices = max_strip_index(path, strip_indices, nv) < 65535u;  // 65535 is the (forbidden) restart value

    const VertexAttribute* given = find_attribute(a.attributes, "NORMAL");
    const std::vector<Point3> normals = given && given->components == 3 ? attribute_normals(*given, nv) : vertex_normals(a.points, a.faces);

    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "singlestrip";
    add_strip_accessors(model, pack_strip_buffer(a.points, normals, strip_indices, short_indices), nv, strip_indices.size(), short_indices);
    add_strip_scene(model, a.attributes, nv);

    tinygltf::TinyGLTF writer;
    std::ostringstream out(std::ios::binary);
    // To a stream: .gltf gets the buffer as a base64 data URI, .glb a BIN chunk.
    if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/false, /*writeBinary=*/ext == ".glb"))
        throw OutputError(path + ": glTF serialisation failed");
    write_text_atomic(path, out.str());
}

GltfStrip read_gltf_strip(const std::string& path) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    const std::string ext = lower_extension(path);
    bool ok = false;
    if (ext == ".glb")
        ok = loader.LoadBinaryFromFile(&model, &err, &warn, path);
    else if (ext == ".gltf")
        ok = loader.LoadASCIIFromFile(&model, &err, &warn, path);
    else
        throw InputError(path + ": not a .glb or .gltf file");
    if (!ok) throw InputError(path + ": cannot read glTF: " + err);
    if (model.meshes.empty() || model.meshes[0].primitives.empty()) throw InputError(path + ": no mesh primitive");
    const tinygltf::Primitive& prim = model.meshes[0].primitives[0];

    // Returns the bytes of accessor `i` (tightly packed) and its element count.
    auto accessor_bytes = [&](int i, int want_type, size_t elem_size) -> std::pair<const unsigned char*, size_t> {
        if (i < 0 || static_cast<size_t>(i) >= model.accessors.size()) throw InputError(path + ": accessor missing");
        const tinygltf::Accessor& acc = model.accessors[static_cast<size_t>(i)];
        if (acc.type != want_type) throw InputError(path + ": accessor " + std::to_string(i) + " has an unexpected type");
        if (acc.bufferView < 0 || static_cast<size_t>(acc.bufferView) >= model.bufferViews.size())
            throw InputError(path + ": accessor " + std::to_string(i) + " has no buffer view");
        const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(acc.bufferView)];
        if (view.byteStride != 0 && view.byteStride != elem_size) throw InputError(path + ": interleaved attributes are not supported");
        const tinygltf::Buffer& b = model.buffers.at(static_cast<size_t>(view.buffer));
        const size_t start = view.byteOffset + acc.byteOffset;
        if (start + acc.count * elem_size > b.data.size() || acc.count * elem_size > view.byteLength)
            throw InputError(path + ": accessor " + std::to_string(i) + " runs past its buffer");
        return {b.data.data() + start, acc.count};
    };
    auto read_vec3 = [&](int i) {
        if (model.accessors.at(static_cast<size_t>(i)).componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
            throw InputError(path + ": attribute is not float");
        auto [p, n] = accessor_bytes(i, TINYGLTF_TYPE_VEC3, 12);
        std::vector<Point3> pts(n);
        for (size_t k = 0; k < n; ++k)
            for (int d = 0; d < 3; ++d) {
                float f;
                std::memcpy(&f, p + 12 * k + 4 * static_cast<size_t>(d), 4);
                pts[k][d] = f;
            }
        return pts;
    };

    GltfStrip s;
    s.mode = prim.mode;
    const auto pos_it = prim.attributes.find("POSITION");
    if (pos_it == prim.attributes.end()) throw InputError(path + ": primitive has no POSITION");
    s.positions = read_vec3(pos_it->second);
    const auto nrm_it = prim.attributes.find("NORMAL");
    if (nrm_it != prim.attributes.end()) s.normals = read_vec3(nrm_it->second);
    if (prim.indices < 0) throw InputError(path + ": primitive has no indices");
    const int ct = model.accessors.at(static_cast<size_t>(prim.indices)).componentType;
    s.index_component_type = ct;
    const size_t size = ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                        : ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                        : ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                       : 0;
    if (size == 0) throw InputError(path + ": indices have an unsupported component type");
    auto [p, n] = accessor_bytes(prim.indices, TINYGLTF_TYPE_SCALAR, size);
    s.indices.resize(n);
    for (size_t k = 0; k < n; ++k) {
        uint32_t v = 0;
        if (size == 1) {
            v = p[k];
        } else if (size == 2) {
            uint16_t h;
            std::memcpy(&h, p + 2 * k, 2);
            v = h;
        } else {
            std::memcpy(&v, p + 4 * k, 4);
        }
        s.indices[k] = v;
    }
    return s;
}

}  // namespace singlestrip
