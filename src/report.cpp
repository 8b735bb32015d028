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
              {"orient", o.orient},
              {"constraint_edges", o.strip.constraint_edges.size()}};
    if (o.strip.seed_face) j["seed_face"] = *o.strip.seed_face;
    if (o.strip.source) j["source"] = *o.strip.source;
    if (o.strip.target) j["target"] = *o.strip.target;
    return j;
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
    j["indices_per_triangle"] = indices_per_triangle(st, r.indices.size());
    j["extra_percent"] = extra_percent(st);
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

}  // namespace singlestrip
