// The report JSON of one run; see report.hpp.
#include "singlestrip/report.hpp"

#include <nlohmann/json.hpp>

#include "singlestrip/errors.hpp"

namespace singlestrip {
namespace {

using json = nlohmann::json;

json options_json(const PipelineOptions& o) {
    json j = {{"engine", engine_name(o.strip.engine)},
              {"greedy", o.strip.greedy},
              {"polish", o.strip.polish},
              {"orient", o.orient},
              {"constraint_edges", o.strip.constraint_edges.size()}};
    j["repair"] = o.repair;
    j["weld"] = o.weld;
    j["join"] = join_mode_name(o.join);
    if (o.join == JoinMode::Restart) j["restart_index"] = o.restart_index;
    if (o.strip.seed_face) j["seed_face"] = o.strip.seed_face->idx();
    if (o.strip.source) j["source"] = o.strip.source->idx();
    if (o.strip.target) j["target"] = o.strip.target->idx();
    return j;
}

json pairs(const std::vector<std::pair<uint32_t, uint32_t>>& v) {
    json a = json::array();
    for (const auto& [x, y] : v) a.push_back({x, y});
    return a;
}

json repair_json_value(const RepairReport& r) {
    return {{"summary", r.summary()},
            {"changed", r.changed()},
            {"welded_vertices", r.welded.size()},
            {"invalid_faces", r.invalid_faces.size()},
            {"degenerate_faces", r.degenerate_faces.size()},
            {"duplicate_faces", r.duplicate_faces.size()},
            {"non_manifold_edges", r.non_manifold_edges.size()},
            {"split_vertices", r.split_vertices.size()},
            {"vertex_copies", r.copied_from.size()},
            {"orientation_cuts", r.orientation_cuts.size()},
            {"non_orientable_components", r.non_orientable_components},
            {"flipped_faces", r.flipped_faces.size()},
            {"turned_outward", r.turned_outward},
            {"components", r.components},
            {"elements",
             {{"welded", pairs(r.welded)},
              {"invalid_faces", r.invalid_faces},
              {"degenerate_faces", r.degenerate_faces},
              {"duplicate_faces", r.duplicate_faces},
              {"non_manifold_edges", pairs(r.non_manifold_edges)},
              {"split_vertices", r.split_vertices},
              {"copied_from", r.copied_from},
              {"orientation_cuts", pairs(r.orientation_cuts)},
              {"flipped_faces", r.flipped_faces}}}};
}

void add_counts(json& j, const PipelineResult& r) {
    const StripStats& st = r.strip.stats;
    j["engine"] = engine_name(st.engine);
    j["input_triangles"] = st.input_triangles;
    j["output_triangles"] = st.output_triangles;
    j["splits"] = st.splits;
    j["swaps"] = st.swaps;
    j["strip_indices"] = r.indices.size();
    j["genus"] = st.genus;
    j["boundary_loops"] = st.boundary_loops;
    j["fundamental_triangles"] = st.fundamental_triangles;
    j["deferred_regions"] = st.deferred_regions;
    if (r.options.strip.polish) j["polished"] = st.polished;
    j["indices_per_triangle"] = indices_per_triangle(st, r.indices.size());
    j["extra_percent"] = extra_percent(st);
    j["strips"] = r.components.size();
    json comps = json::array();
    for (const ComponentStrip& c : r.components)
        comps.push_back({{"input_triangles", c.input_triangles},
                         {"output_triangles", c.output_triangles},
                         {"splits", c.splits},
                         {"genus", c.genus},
                         {"boundary_loops", c.boundary_loops},
                         {"first_face", c.first_face},
                         {"strip_indices", c.strip_indices}});
    j["components"] = comps;
    if (r.repair) j["repair"] = repair_json_value(*r.repair);
    if (r.options.weld && !r.options.repair) j["welded_vertices"] = r.welded;
    if (!r.warnings.empty()) j["warnings"] = r.warnings;
}

void add_cycles(json& j, const Cycles& c) {
    size_t faces = 0;
    for (const auto& cycle : c.cycles) faces += cycle.size();
    j["cycles"] = c.cycles.size();
    j["cycle_lengths"] = c.lengths;
    j["cycle_faces_total"] = faces;
}

void add_outcome(json& j, const RunOutcome& o) {
    j["ok"] = o.ok;
    j["exit_code"] = o.exit_code;
    if (!o.ok) j["error"] = o.error;
    j["seconds"] = o.seconds;
}

}  // namespace

std::string repair_json(const RepairReport& report) {
    return repair_json_value(report).dump(2) + "\n";
}

std::string report_json(const ReportInput& in) {
    const PipelineOptions* options = in.options ? in.options : in.result ? &in.result->options : nullptr;
    if (!options) throw InternalError("report_json: neither options nor a result");
    json j;
    if (!in.input.empty()) j["input"] = in.input;
    if (!in.output.empty()) j["output"] = in.output;
    j["options"] = options_json(*options);
    if (in.result) {
        add_counts(j, *in.result);
        if (in.result->cycles) add_cycles(j, *in.result->cycles);
        if (in.stage_seconds) {
            const StageSeconds& s = in.result->seconds;
            j["seconds"] = {{"read", s.read}, {"build", s.build}, {"strip", s.strip}, {"write", s.write}};
        }
    } else {
        j["engine"] = engine_name(options->strip.engine);
    }
    if (in.outcome) add_outcome(j, *in.outcome);
    return j.dump(2) + "\n";
}

std::string info_json(const std::string& input, const MeshInfo& m, long long flipped, const RepairReport* repair,
                      const std::vector<std::string>& attributes) {
    json j;
    j["file"] = input;
    j["vertices"] = m.vertices;
    j["referenced_vertices"] = m.referenced_vertices;
    j["faces"] = m.faces;
    j["polygons"] = m.polygons;
    j["edges"] = m.edges;
    j["boundary_edges"] = m.boundary_edges;
    j["non_manifold_edges"] = m.non_manifold_edges;
    j["components"] = m.components;
    j["component_sizes"] = m.component_sizes;
    j["boundary_loops"] = m.boundary_loops;
    j["euler_characteristic"] = m.euler_characteristic;
    j["genus"] = m.genus_valid ? json(m.genus) : json(nullptr);
    j["orientable"] = m.orientable;
    j["oriented"] = m.oriented;
    if (flipped >= 0) j["faces_flipped_by_orient"] = flipped;
    j["unwelded_vertices"] = m.unwelded_vertices;
    j["valid"] = m.valid();
    json ps = json::array();
    for (const auto& p : m.problems) ps.push_back({{"kind", p.kind}, {"message", p.message}});
    j["problems"] = ps;
    j["attributes"] = attributes;
    if (repair) j["repair"] = repair_json_value(*repair);
    return j.dump(2) + "\n";
}

std::string gltf_report_json(const std::string& input, const std::string& output, const std::vector<GltfPrimitiveResult>& primitives) {
    json j = {{"input", input}, {"output", output}, {"primitives", json::array()}};
    for (const auto& p : primitives)
        j["primitives"].push_back({{"mesh", p.mesh},
                                   {"primitive", p.primitive},
                                   {"stripped", p.stripped},
                                   {"note", p.note},
                                   {"input_triangles", p.input_triangles},
                                   {"output_triangles", p.output_triangles},
                                   {"splits", p.splits},
                                   {"strips", p.strips},
                                   {"strip_indices", p.strip_indices},
                                   {"welded_vertices", p.welded},
                                   {"attributes", p.attributes},
                                   {"repair", p.repair}});
    return j.dump(2) + "\n";
}

}  // namespace singlestrip
