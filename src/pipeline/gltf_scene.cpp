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
#include "singlestrip/errors.hpp"
#include "singlestrip/gltf.hpp"
#include "singlestrip/gltf_scene.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/pipeline.hpp"

namespace singlestrip {
namespace {

using gltf_detail::AccessorData;
constexpr uint32_t kNo = 0xffffffffu;

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

/// Where an output vertex takes its attributes from: up to three input vertices and weights.
struct Source {
    std::array<uint32_t, 3> v{kNo, kNo, kNo};
    std::array<double, 3> w{1, 0, 0};
    uint32_t nearest = kNo;
};

std::array<double, 3> barycentric(const Point3& p, const Point3& a, const Point3& b, const Point3& c) {
    const Point3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]},
        q{p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    auto dot = [](const Point3& x, const Point3& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
    const double uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), qu = dot(q, u), qv = dot(q, v), det = uu * vv - uv * uv;
    if (!(std::abs(det) > 0)) return {1, 0, 0};
    double s = (vv * qu - uv * qv) / det, t = (uu * qv - uv * qu) / det;
    s = std::clamp(s, 0.0, 1.0);
    t = std::clamp(t, 0.0, 1.0 - s);
    return {1 - s - t, s, t};
}

/// Sources of every output vertex of `r` (n input vertices of the primitive soup `tris`).
std::vector<Source> vertex_sources(const PipelineResult& r, const std::vector<Triangle>& tris, const std::vector<Point3>& pts) {
    const std::size_t n = pts.size(), N = r.arrays.points.size();
    const std::size_t copies = r.repair ? r.repair->copied_from.size() : 0;
    std::vector<Source> src(N);
    for (std::size_t v = 0; v < std::min(n, N); ++v) src[v].v[0] = src[v].nearest = static_cast<uint32_t>(v);
    for (std::size_t j = 0; j < copies && n + j < N; ++j) src[n + j].v[0] = src[n + j].nearest = r.repair->copied_from[j];
    for (std::size_t f = 0; f < r.arrays.faces.size(); ++f)
        for (uint32_t v : r.arrays.faces[f]) {
            if (v < n + copies || src[v].nearest != kNo) continue;
            const Triangle& t = tris[r.arrays.parent[f]];
            src[v].v = t;
            src[v].w = barycentric(r.arrays.points[v], pts[t[0]], pts[t[1]], pts[t[2]]);
            src[v].nearest = t[static_cast<std::size_t>(std::max_element(src[v].w.begin(), src[v].w.end()) - src[v].w.begin())];
        }
    for (Source& s : src)
        if (s.nearest == kNo) s.v[0] = s.nearest = 0;  // an unreferenced vertex: any value will do
    return src;
}

// Skin influences stay paired (nearest corner); custom integer attributes may be ids. Everything
// else is interpolated and written as float, which every core attribute (and
// KHR_mesh_quantization's) accepts with the same meaning.
bool interpolated(const std::string& name, const AccessorData& d) {
    if (name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0) return false;
    if (name.rfind('_', 0) == 0) return d.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT || d.normalized;
    return true;
}

/// A new accessor for attribute `name` over the output vertices.
int write_attribute(tinygltf::Model& model, const std::string& name, const AccessorData& d, const std::vector<Source>& src) {
    tinygltf::Accessor acc;
    acc.count = src.size();
    acc.type = d.type;
    std::vector<unsigned char> bytes;
    if (!interpolated(name, d)) {
        acc.componentType = d.component_type;
        acc.normalized = d.normalized;
        for (const Source& s : src)
            bytes.insert(bytes.end(), d.raw.begin() + static_cast<std::ptrdiff_t>(s.nearest * d.elem_size),
                         d.raw.begin() + static_cast<std::ptrdiff_t>((s.nearest + 1) * d.elem_size));
    } else {
        acc.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        const auto k = static_cast<std::size_t>(d.components);
        std::vector<float> val(k);
        for (const Source& s : src) {
            for (std::size_t c = 0; c < k; ++c) {
                double x = 0;
                for (int i = 0; i < 3; ++i)
                    if (s.v[i] != kNo && s.w[i] != 0) x += s.w[i] * d.values[s.v[i] * k + c];
                val[c] = static_cast<float>(x);
            }
            if (name == "NORMAL" || name == "TANGENT") {  // unit vectors stay unit
                const double len = std::sqrt(double(val[0]) * val[0] + double(val[1]) * val[1] + double(val[2]) * val[2]);
                for (std::size_t c = 0; c < 3; ++c) val[c] = len > 0 ? static_cast<float>(val[c] / len) : (c == 2 ? 1.0f : 0.0f);
                if (name == "TANGENT") val[3] = d.values[s.nearest * k + 3];
            }
            for (float f : val) {
                const auto* p = reinterpret_cast<const unsigned char*>(&f);
                bytes.insert(bytes.end(), p, p + 4);
            }
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
    const std::vector<Point3> pts = soup.points;
    const std::vector<Triangle> tris = soup.triangles;
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
    const std::vector<Source> src = vertex_sources(r, tris, pts);
    for (const auto& [attr, d] : attrs) {
        prim.attributes[attr] = attr == "POSITION" ? write_positions(model, r.arrays.points) : write_attribute(model, attr, d, src);
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
