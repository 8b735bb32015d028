// The pipeline every front end calls; see pipeline.hpp.
#include "singlestrip/pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <span>
#include <string>
#include <utility>

#include "algo/face_order.hpp"
#include "components.hpp"
#include "core/soup_edges.hpp"
#include "singlestrip/attributes.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/gltf.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/models.hpp"
#include "singlestrip/validate.hpp"

namespace singlestrip {
namespace {

class Stopwatch {
public:
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double s = std::chrono::duration<double>(now - start_).count();
        start_ = now;
        return s;
    }

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

void enter(PipelineStage* stage, PipelineStage s) {
    if (stage) *stage = s;
}

/// The one check that each constraint edge is an edge of the soup; the engines then only look
/// the half-edges up. \throw RequestError naming the edge by its file line, or by its index when
/// it was given as a pair.
/// `internal` (optional): the soup's number of each given vertex, when they differ.
void check_constraint_edges(const TriangleSoup& soup, const std::vector<ConstraintEdge>& constraints, const PipelineOptions& options,
                            const std::vector<uint32_t>* internal) {
    const SoupEdges edges(soup.triangles, soup.points.size());
    const auto number = [&](uint32_t v) { return internal && v < internal->size() ? (*internal)[v] : v; };
    for (std::size_t i = 0; i < constraints.size(); ++i) {
        const ConstraintEdge& e = constraints[i];
        if (edges.has_edge(number(e.a), number(e.b))) continue;
        const std::string pair = "(" + std::to_string(e.a) + ", " + std::to_string(e.b) + ") is not an edge of the mesh";
        if (e.line == 0 || !options.constraints_file) throw RequestError("constraint " + std::to_string(i) + ": " + pair);
        const std::string where = *options.constraints_file + ": line " + std::to_string(e.line) + ": ";
        if (options.index_base == 0) throw RequestError(where + pair);
        // The pair is shown 0-based; say so rather than show numbers the file lacks.
        throw RequestError(where + pair + " (vertex numbers counted from 0 here: add 1 for the file's numbering)");
    }
}

// prepare_soup() promises a soup Mesh::from_soup() accepts: a refusal here is a bug.
// `twin`: the checks' edge pairing of the soup (PreparedSoup::twin), or empty.
Mesh build_mesh(TriangleSoup& soup, std::vector<uint32_t>&& twin, bool self_check, bool take_soup) {
    Mesh mesh;
    try {
        if (twin.empty())
            mesh = take_soup ? Mesh::from_soup(std::move(soup)) : Mesh::from_soup(soup);
        else
            mesh = take_soup ? Mesh::from_soup(std::move(soup), std::move(twin)) : Mesh::from_soup(soup, std::move(twin));
    } catch (const InputError& e) {
        throw InternalError(std::string("prepare_soup accepted a soup that Mesh::from_soup rejects: ") + e.what());
    }
    if (self_check) {
        mesh.validate();
        if (const uint32_t n = mesh.num_components(); n != 1)
            throw InternalError("prepare_soup accepted a mesh with " + std::to_string(n) + " components");
    }
    return mesh;
}

double per_input_triangle(const StripStats& stats) noexcept {
    return stats.input_triangles ? static_cast<double>(stats.input_triangles) : 1.0;
}

}  // namespace

bool is_builtin_input(const std::string& input) noexcept {
    return input.rfind("builtin:", 0) == 0;
}

TriangleSoup read_input(const std::string& input, const ReadOptions& options) {
    if (!is_builtin_input(input))
        return is_gltf_path(input) && options.format.empty() ? read_gltf_soup(input) : read_mesh_file(input, options);
    if (input != kBuiltinGenus2) throw RequestError("unknown built-in model '" + input + "' (available: " + kBuiltinGenus2 + ")");
    return make_builtin_model();
}

const char* stage_name(PipelineStage stage) noexcept {
    switch (stage) {
        case PipelineStage::Checks:
            return "prepare_soup";
        case PipelineStage::Constraints:
            return "constraints";
        case PipelineStage::Mesh:
            return "Mesh::from_soup";
        case PipelineStage::Strip:
            return "build_strip";
        case PipelineStage::Encode:
            return "encode_triangle_strip";
        case PipelineStage::Cycles:
            return "compute_fundamental_cycles";
        case PipelineStage::Done:
            return "done";
    }
    return "unknown";
}

namespace {

/// Applies weld / repair (options) to `soup`, recording what changed in `r`.
TriangleSoup pre_repair(TriangleSoup soup, const PipelineOptions& options, PipelineResult& r) {
    if (options.repair) {
        RepairedSoup rs = repair_soup(soup, RepairOptions{options.repair_weld});
        r.face_origin = std::move(rs.face_origin);
        r.repair = std::move(rs.report);
        return std::move(rs.soup);
    }
    if (options.weld) r.welded = weld_soup(soup);
    return soup;
}

/// A warning when an unwelded soup falls apart into components that --weld would join.
void warn_unwelded(PipelineResult& r, uint32_t components) {
    if (components < 2 || r.options.weld || r.options.repair) return;
    const uint64_t u = unwelded_vertices(r.input);
    if (u == 0) return;
    r.warnings.push_back(std::to_string(u) +
                         " vertices have exactly the coordinates of another vertex (the file left its corners apart): the " +
                         std::to_string(components) + " components may be one surface; --weld (or --repair) merges them");
}

/// prepare_soup_components() may have reordered the faces for the cache: parents then go
/// through its face_origin, after repair's.
void keep_face_origin(PipelineResult& r, std::vector<uint32_t> order) {
    if (order.empty()) return;
    if (r.face_origin.empty()) {
        r.face_origin = std::move(order);
        return;
    }
    std::vector<uint32_t> composed(order.size());
    for (size_t i = 0; i < order.size(); ++i) composed[i] = r.face_origin[order[i]];
    r.face_origin = std::move(composed);
}

/// prepare_soup_components() numbered the vertices by first use (origin[i] = the given vertex
/// of vertex i): the engines ran in that numbering; what stripify() returns is in the given one.
void results_to_given(PipelineResult& r, const std::vector<uint32_t>& origin) {
    const size_t nv = origin.size();
    if (r.input.points.size() == nv) permute_vertices(r.input, origin, true);  // lean: the mesh took it
    if (r.arrays.points.size() >= nv) {
        const std::vector<Point3> first(r.arrays.points.begin(), r.arrays.points.begin() + static_cast<std::ptrdiff_t>(nv));
        for (size_t i = 0; i < nv; ++i) r.arrays.points[origin[i]] = first[i];
    }
    const auto given = [&](uint32_t& v) { v = v < nv ? origin[v] : v; };
    for (Triangle& t : r.arrays.faces) std::for_each(t.begin(), t.end(), given);
    const bool restarts = r.options.join == JoinMode::Restart;
    for (uint32_t& x : r.indices)
        if (!restarts || x != r.options.restart_index) given(x);
    if (r.strip.mesh.num_input_vertices() == nv && nv > 0) r.strip.mesh.renumber_input_vertices(origin);
}

/// Output vertices get the input's attributes (midpoints blended inside their parent face);
/// parents still number the faces of r.input here.
void carry_attributes(PipelineResult& r) {
    if (r.input.attributes.empty()) return;
    const auto src = attribute_sources(r.input.points, r.input.triangles, r.arrays.points, r.arrays.faces, r.arrays.parent);
    for (const VertexAttribute& a : r.input.attributes) r.arrays.attributes.push_back(blend_attribute(a, src));
}

void map_parents(PipelineResult& r) {
    if (r.face_origin.empty()) return;
    for (uint32_t& p : r.arrays.parent) p = r.face_origin[p];
}

void compute_cycles(PipelineResult& r, PipelineStage* stage) {
    if (!r.options.cycles) return;
    enter(stage, PipelineStage::Cycles);
    r.cycles = compute_fundamental_cycles(r.strip);
}

/// Today's path: one component, one strip.
void strip_one(PipelineResult& r, std::vector<uint32_t>&& twin, bool self_check, PipelineStage* stage) {
    // Attributes are blended from r.input after the strip: then it has to stay.
    const bool lean = r.options.release_intermediates && r.input.attributes.empty();
    enter(stage, PipelineStage::Mesh);
    Mesh mesh = build_mesh(r.input, std::move(twin), self_check, lean);
    enter(stage, PipelineStage::Strip);
    r.strip = build_strip_connected(std::move(mesh), r.options.strip);  // the checks counted one component
    if (self_check) r.strip.mesh.validate();
    if (lean) compute_cycles(r, stage);
    enter(stage, PipelineStage::Encode);
    r.arrays = lean ? strip_arrays(std::move(r.strip)) : strip_arrays(r.strip);
    r.indices = encode_triangle_strip(r.arrays.faces);
    const StripStats& st = r.strip.stats;
    r.components.push_back({st.input_triangles, st.output_triangles, st.splits, st.genus, st.boundary_loops, 0, r.indices.size()});
    if (!lean) compute_cycles(r, stage);
}

}  // namespace

std::vector<uint32_t> degenerate_joined_indices(const PipelineResult& r) {
    if (r.components.size() <= 1 || r.options.join == JoinMode::Degenerate) return r.indices;
    std::vector<std::vector<uint32_t>> strips;
    for (const ComponentStrip& c : r.components)
        strips.push_back(encode_triangle_strip(std::span<const Triangle>(r.arrays.faces).subspan(c.first_face, c.output_triangles)));
    return join_strips(strips, JoinMode::Degenerate);
}

PipelineResult stripify(TriangleSoup soup, const PipelineOptions& options, PipelineStage* stage) {
    Stopwatch clock;
    PipelineResult r;
    r.options = options;
    enter(stage, PipelineStage::Checks);
    if (const std::string bad = attribute_problem(soup.attributes, soup.points.size()); !bad.empty())
        throw InputError(options.name + ": " + bad);
    soup = pre_repair(std::move(soup), options, r);
    // A seed face names a face, source and target name vertices of the given numbering (and so do
    // the messages about them): the soup is then stripped as given.
    const StripOptions& so = options.strip;
    const PrepareOptions prep{options.orient || options.repair, !so.seed_face, !so.seed_face && !so.source && !so.target};
    PreparedSoup prepared = prepare_soup_components(std::move(soup), prep, options.name);
    r.input = std::move(prepared.soup);
    keep_face_origin(r, std::move(prepared.face_origin));
    const std::vector<uint32_t> origin = std::move(prepared.vertex_origin);
    std::vector<ConstraintEdge>& constraints = r.options.strip.constraint_edges;
    if (options.constraints_file) {
        enter(stage, PipelineStage::Constraints);
        const auto nv = static_cast<uint32_t>(r.input.points.size());
        const std::vector<ConstraintEdge> read = read_constraints_based(*options.constraints_file, nv, options.index_base);
        constraints.insert(constraints.end(), read.begin(), read.end());
    }
    std::vector<ConstraintEdge> given_constraints;
    if (!constraints.empty()) {
        enter(stage, PipelineStage::Constraints);
        const std::vector<uint32_t> internal = origin.empty() ? std::vector<uint32_t>() : inverse_permutation(origin);
        check_constraint_edges(r.input, constraints, options, origin.empty() ? nullptr : &internal);
        if (!origin.empty()) {
            given_constraints = constraints;
            for (ConstraintEdge& e : constraints) e = ConstraintEdge{internal[e.a], internal[e.b], e.line};
        }
    }
    const uint32_t count = prepared.num_components;
    std::vector<uint32_t> comp = std::move(prepared.component);
    warn_unwelded(r, count);
    r.seconds.build = clock.lap();
    if (count <= 1) {
        comp = std::vector<uint32_t>();  // not needed for one component: free it before the strip
        strip_one(r, std::move(prepared.twin), options.self_check, stage);
    } else {
        detail::strip_components(r, comp, count, std::move(prepared.twin), stage);
    }
    if (!origin.empty()) {
        results_to_given(r, origin);
        if (!constraints.empty()) constraints = std::move(given_constraints);
    }
    carry_attributes(r);
    map_parents(r);
    r.seconds.strip = clock.lap();
    enter(stage, PipelineStage::Done);
    return r;
}

double extra_percent(const StripStats& stats) noexcept {
    return 100.0 * (static_cast<double>(stats.output_triangles) - static_cast<double>(stats.input_triangles)) / per_input_triangle(stats);
}

double indices_per_triangle(const StripStats& stats, size_t strip_indices) noexcept {
    return static_cast<double>(strip_indices) / per_input_triangle(stats);
}

}  // namespace singlestrip
