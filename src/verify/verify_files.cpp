// verify_files(): reads the files and replays the input steps the strip run was asked for
// (weld, repair, orient) with the library's own functions before the independent checks of
// verify.cpp. Only this file ties the verifier to the library's repair (verify.hpp).
#include <string>
#include <utility>
#include <vector>

#include "singlestrip/errors.hpp"
#include "singlestrip/gltf.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/repair.hpp"
#include "singlestrip/validate.hpp"
#include "singlestrip/verify.hpp"
#include "verify_attributes.hpp"

namespace singlestrip {
namespace {

constexpr uint32_t kNo = 0xffffffffu;

}  // namespace

std::vector<std::string> replay_input_steps(VerifyInput& vi, const InputSteps& steps, std::vector<VertexAttribute> attributes) {
    std::vector<std::string> notes;
    TriangleSoup input;
    input.points = std::move(vi.in_points);
    input.triangles = std::move(vi.in_faces);
    input.attributes = std::move(attributes);
    std::vector<uint32_t> face_of_input;
    if (steps.repair) {
        RepairedSoup rs = repair_soup(input, RepairOptions{steps.repair_weld});
        face_of_input.assign(input.triangles.size(), kNo);
        for (uint32_t t = 0; t < rs.face_origin.size(); ++t) face_of_input[rs.face_origin[t]] = t;
        notes.push_back("checked against the input as repaired by the library's repair_soup (this part depends on the library): " +
                        rs.report.summary());
        input = std::move(rs.soup);
    } else if (steps.weld) {
        notes.push_back("checked against the input welded by the library's weld_soup: " + std::to_string(weld_soup(input)) +
                        " vertices merged");
    }
    if (steps.orient || steps.repair) {
        const long long flipped = orient_soup(input);
        if (flipped > 0 || steps.orient)
            notes.push_back("checked against the input re-oriented by the library's orient_soup: " +
                            (flipped < 0 ? std::string("not orientable") : std::to_string(flipped) + " faces flipped"));
    }
    vi.in_points = std::move(input.points);
    vi.in_faces = std::move(input.triangles);
    vi.in_attributes = std::move(input.attributes);  // with repair's copies appended
    // A parent naming a dropped or unknown input face maps past the end: verify() reports it.
    if (!face_of_input.empty())
        for (uint32_t& p : vi.out_parent) p = p < face_of_input.size() && face_of_input[p] != kNo ? face_of_input[p] : kNo - 1;
    return notes;
}

VerifyInput verify_input(const TriangleSoup& input, const StripArrays& output, const std::vector<uint32_t>& indices) {
    VerifyInput in;
    in.in_points = input.points;
    in.in_faces = input.triangles;
    in.out_points = output.points;
    in.out_faces = output.faces;
    in.out_parent = output.parent;
    in.indices = indices;
    return in;
}

VerifyReport verify_files(const std::string& in_path, const std::string& out_path, const VerifyFileOptions& options) {
    if (is_gltf_path(in_path) && is_gltf_path(out_path) && options.input_format.empty())
        return verify_gltf_scene(in_path, out_path, options.steps);
    ReadOptions read;
    read.format = options.input_format;
    return verify_files(is_gltf_path(in_path) && read.format.empty() ? read_gltf_soup(in_path) : read_mesh_file(in_path, read), out_path,
                        options);
}

VerifyReport verify_files(TriangleSoup input, const std::string& out_path, const VerifyFileOptions& options) {
    VerifyInput vi;
    vi.in_points = std::move(input.points);
    vi.in_faces = std::move(input.triangles);
    if (is_gltf_path(out_path)) {
        GltfStrip g = read_gltf_strip(out_path);
        if (g.mode != 5) throw InputError(out_path + ": the first primitive is not a TRIANGLE_STRIP (mode " + std::to_string(g.mode) + ")");
        vi.out_points = std::move(g.positions);
        vi.out_faces = verify_decode_strip(g.indices);
        vi.indices = std::move(g.indices);
        vi.float32 = true;
    } else {
        OutputMesh om = read_output_mesh(out_path);
        vi.out_points = std::move(om.points);
        vi.out_faces = std::move(om.faces);
        vi.out_parent = std::move(om.parent);
        vi.out_attributes = std::move(om.attributes);
    }
    std::vector<std::string> notes = replay_input_steps(vi, options.steps, std::move(input.attributes));
    if (is_gltf_path(out_path)) verify_detail::read_gltf_strip_attributes(out_path, vi, notes);
    if (options.indices_path) vi.indices = read_index_file(*options.indices_path);
    if (options.constraints_path)
        vi.constraints =
            vertex_pairs(read_constraints_based(*options.constraints_path, static_cast<uint32_t>(vi.in_points.size()), options.index_base));
    vi.source = options.source;
    vi.target = options.target;
    vi.restart_index = options.restart_index;
    if (options.cycles_path) vi.cycles = read_cycles_file(*options.cycles_path);
    VerifyReport report = verify(vi);
    report.notes.insert(report.notes.begin(), notes.begin(), notes.end());
    return report;
}

}  // namespace singlestrip
