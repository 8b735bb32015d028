// verify_gltf_scene(): a glTF scene stripped primitive by primitive, checked primitive by
// primitive with the independent verify() (verify.hpp). Reading the two files and rebuilding the
// input primitive as the strip saw it use the library's glTF reader.
#include <cctype>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "io/gltf_access.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/verify.hpp"
#include "verify_attributes.hpp"

namespace singlestrip {
namespace {

/// How the scene rewriter carries glTF attribute `name` (docs: skin influences and integer
/// custom attributes are copied from one corner; normals and tangents renormalised).
AttributeBlend gltf_blend(const std::string& name, const gltf_detail::AccessorData& d) {
    if (name == "NORMAL" || name == "TANGENT") return AttributeBlend::Unit;
    if (name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0) return AttributeBlend::Nearest;
    if (name.rfind('_', 0) == 0 && d.component_type != TINYGLTF_COMPONENT_TYPE_FLOAT && !d.normalized) return AttributeBlend::Nearest;
    return AttributeBlend::Linear;
}

/// The attributes both primitives have, as verify() compares them: float32 values (glTF).
std::vector<VertexAttribute> shared_attributes(const tinygltf::Model& in, const tinygltf::Primitive& ip, const tinygltf::Model& out,
                                               const tinygltf::Primitive& op, VerifyInput& vi, const std::string& name) {
    std::vector<VertexAttribute> in_attrs;
    for (const auto& [attr, index] : ip.attributes) {
        if (attr == "POSITION" || !op.attributes.count(attr)) continue;
        const gltf_detail::AccessorData a = gltf_detail::read_accessor(in, index, name);
        const gltf_detail::AccessorData b = gltf_detail::read_accessor(out, op.attributes.at(attr), name);
        const auto k = static_cast<uint32_t>(a.components);
        in_attrs.push_back({attr, k, gltf_blend(attr, a), std::vector<double>(a.values.begin(), a.values.end())});
        vi.out_attributes.push_back({attr, static_cast<uint32_t>(b.components), std::vector<double>(b.values.begin(), b.values.end()), 1e-6,
                                     1e-6, "glTF, float32 tolerance"});
    }
    return in_attrs;
}

/// verify() of one stripped primitive; fills `vi` from the two models.
VerifyReport verify_primitive(const tinygltf::Model& in, const tinygltf::Primitive& ip, const tinygltf::Model& out,
                              const tinygltf::Primitive& op, const InputSteps& steps, const std::string& name) {
    VerifyInput vi;
    const TriangleSoup soup = gltf_detail::primitive_soup(in, ip, name);
    vi.in_points = soup.points;
    vi.in_faces = soup.triangles;
    const gltf_detail::AccessorData pos = gltf_detail::read_accessor(out, op.attributes.at("POSITION"), name);
    vi.out_points.resize(pos.count);
    for (std::size_t v = 0; v < pos.count; ++v)
        for (std::size_t k = 0; k < 3; ++k) vi.out_points[v][k] = pos.values[3 * v + k];
    std::vector<uint32_t> idx;
    for (float x : gltf_detail::read_accessor(out, op.indices, name).values) idx.push_back(static_cast<uint32_t>(x));
    vi.out_faces = verify_decode_strip(idx);
    vi.indices = std::move(idx);
    vi.float32 = true;
    InputSteps s = steps;
    s.repair_weld = false;  // glTF primitives are never welded across attribute seams
    s.weld = false;
    std::vector<VertexAttribute> in_attrs = shared_attributes(in, ip, out, op, vi, name);
    const std::vector<std::string> notes = replay_input_steps(vi, s, std::move(in_attrs));
    VerifyReport r = verify(vi);
    r.notes.insert(r.notes.begin(), notes.begin(), notes.end());
    return r;
}

void add(VerifyReport& total, const VerifyReport& r, const std::string& who) {
    for (const auto& f : r.failures) total.failures.push_back(who + ": " + f);
    for (const auto& n : r.notes) total.notes.push_back(who + ": " + n);
    total.faces_checked += r.faces_checked;
    total.input_faces += r.input_faces;
    total.output_faces += r.output_faces;
    total.output_vertices += r.output_vertices;
    total.euler_characteristic += r.euler_characteristic;
    total.boundary_loops += r.boundary_loops;
    total.genus += r.genus;
    total.strips += r.strips;
}

}  // namespace

namespace verify_detail {

void read_gltf_strip_attributes(const std::string& path, VerifyInput& vi, std::vector<std::string>& notes) {
    const tinygltf::Model m = gltf_detail::load_model(path);
    if (m.meshes.empty() || m.meshes[0].primitives.empty()) return;
    auto custom = [](const std::string& name) {  // the writer's "_NAME" for a name glTF does not know
        std::string c = "_" + name;
        for (char& ch : c) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        return c;
    };
    for (const auto& [attr, index] : m.meshes[0].primitives[0].attributes) {
        if (attr == "POSITION") continue;
        std::string name = attr;
        for (const VertexAttribute& a : vi.in_attributes)
            if (a.name != attr && custom(a.name) == attr) name = a.name;
        const gltf_detail::AccessorData d = gltf_detail::read_accessor(m, index, path);
        vi.out_attributes.push_back({name, static_cast<uint32_t>(d.components), std::vector<double>(d.values.begin(), d.values.end()), 1e-6,
                                     1e-6, "glTF, float32 tolerance"});
    }
    for (VertexAttribute& a : vi.in_attributes) {
        if (a.name != "NORMAL" || a.components != 3) continue;
        for (std::size_t v = 0; 3 * v + 2 < a.values.size(); ++v) {
            double* n = &a.values[3 * v];
            const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (int c = 0; c < 3; ++c) n[c] = len > 0 ? n[c] / len : (c == 2 ? 1.0 : 0.0);
        }
        notes.push_back("attributes: the input's NORMAL compared normalised (glTF holds unit normals)");
    }
}

}  // namespace verify_detail

VerifyReport verify_gltf_scene(const std::string& in_path, const std::string& out_path, const InputSteps& steps) {
    const tinygltf::Model in = gltf_detail::load_model(in_path), out = gltf_detail::load_model(out_path);
    if (in.meshes.size() != out.meshes.size())
        throw InputError(out_path + ": has " + std::to_string(out.meshes.size()) + " meshes, " + in_path + " has " +
                         std::to_string(in.meshes.size()));
    VerifyReport total;
    for (std::size_t m = 0; m < in.meshes.size(); ++m) {
        if (in.meshes[m].primitives.size() != out.meshes[m].primitives.size())
            throw InputError(out_path + ": mesh " + std::to_string(m) + " has a different number of primitives than in " + in_path);
        for (std::size_t p = 0; p < in.meshes[m].primitives.size(); ++p) {
            const std::string who = "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
            const tinygltf::Primitive& ip = in.meshes[m].primitives[p];
            const tinygltf::Primitive& op = out.meshes[m].primitives[p];
            if (op.mode != TINYGLTF_MODE_TRIANGLE_STRIP || !gltf_detail::why_not_stripped(in, ip).empty()) {
                total.notes.push_back(who + ": not stripped, not checked");
                continue;
            }
            if (op.indices < 0 || !op.attributes.count("POSITION")) {
                total.failures.push_back(who + ": strip primitive without indices or POSITION");
                continue;
            }
            add(total, verify_primitive(in, ip, out, op, steps, out_path + ": " + who), who);
        }
    }
    return total;
}

}  // namespace singlestrip
