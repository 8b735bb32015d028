// One strip per edge-connected component (components.hpp). Each component is stripped as its
// own soup with local vertex numbers, so a component costs O(its size), not O(V); requests are
// checked here with global numbers first, so messages name the user's vertices and faces.
#include "components.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/mesh.hpp"

namespace singlestrip::detail {
namespace {

/// One component as its own soup.
struct Part {
    TriangleSoup soup;             // local vertex ids
    std::vector<uint32_t> vertex;  // local -> global vertex
    std::vector<uint32_t> face;    // local -> global face
};

struct Split {
    std::vector<Part> parts;
    std::vector<uint32_t> vertex_part, local_vertex;  // per global vertex (kNone when unused)
    std::vector<uint32_t> local_face;                 // per global face
};

Split split_parts(const TriangleSoup& s, const std::vector<uint32_t>& comp, uint32_t count) {
    Split sp;
    sp.parts.resize(count);
    sp.vertex_part.assign(s.points.size(), kNone);
    sp.local_vertex.assign(s.points.size(), kNone);
    sp.local_face.assign(s.triangles.size(), kNone);
    for (uint32_t f = 0; f < s.triangles.size(); ++f) {
        Part& p = sp.parts[comp[f]];
        Triangle t{};
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = s.triangles[f][k];
            if (sp.vertex_part[v] == kNone) {
                sp.vertex_part[v] = comp[f];
                sp.local_vertex[v] = static_cast<uint32_t>(p.vertex.size());
                p.vertex.push_back(v);
                p.soup.points.push_back(s.points[v]);
            } else if (sp.vertex_part[v] != comp[f]) {
                // prepare_soup() refuses non-manifold vertices, so no vertex is in two components.
                throw InternalError("vertex " + std::to_string(v) + " is in two edge-connected components");
            }
            t[k] = sp.local_vertex[v];
        }
        sp.local_face[f] = static_cast<uint32_t>(p.face.size());
        p.face.push_back(f);
        p.soup.triangles.push_back(t);
    }
    return sp;
}

uint32_t part_of_vertex(const Split& sp, const char* what, uint32_t v) {
    if (v >= sp.vertex_part.size())
        throw RequestError(std::string(what) + " vertex " + std::to_string(v) + " is out of range (mesh has " +
                           std::to_string(sp.vertex_part.size()) + " vertices)");
    if (sp.vertex_part[v] == kNone) throw RequestError(std::string(what) + " vertex " + std::to_string(v) + " is not used by any face");
    return sp.vertex_part[v];
}

/// Output order of the parts: the one holding source / target first, the rest by lowest face.
std::vector<uint32_t> part_order(const Split& sp, const StripOptions& o) {
    std::vector<uint32_t> order;
    std::optional<uint32_t> first;
    if (o.source) first = part_of_vertex(sp, "source", o.source->idx());
    if (o.target) {
        const uint32_t t = part_of_vertex(sp, "target", o.target->idx());
        if (first && *first != t)
            throw RequestError("source vertex " + std::to_string(o.source->idx()) + " is in component " + std::to_string(*first) +
                               " and target vertex " + std::to_string(o.target->idx()) + " in component " + std::to_string(t) + " (of " +
                               std::to_string(sp.parts.size()) +
                               " edge-connected components): source and target start and end one strip, so they must be in "
                               "the same component");
        first = t;
    }
    if (first) order.push_back(*first);
    for (uint32_t c = 0; c < sp.parts.size(); ++c)
        if (!first || c != *first) order.push_back(c);
    return order;
}

/// The request of part c in local numbers (check_requests() has named what is wrong globally).
StripOptions part_options(const Split& sp, const std::vector<uint32_t>& comp, const StripOptions& o, uint32_t c) {
    StripOptions local = o;
    local.seed_face.reset();
    local.source.reset();
    local.target.reset();
    local.constraint_edges.clear();
    if (o.seed_face && comp[o.seed_face->idx()] == c) local.seed_face = FaceId(sp.local_face[o.seed_face->idx()]);
    if (o.source && sp.vertex_part[o.source->idx()] == c) local.source = VertexId(sp.local_vertex[o.source->idx()]);
    if (o.target && sp.vertex_part[o.target->idx()] == c) local.target = VertexId(sp.local_vertex[o.target->idx()]);
    for (const ConstraintEdge& e : o.constraint_edges)
        if (sp.vertex_part[e.a] == c) local.constraint_edges.push_back({sp.local_vertex[e.a], sp.local_vertex[e.b], e.line});
    return local;
}

/// The seed face is checked on the whole input, so that its message gives input numbers (stripify()
/// checked the constraint edges).
void check_requests(const TriangleSoup& s, const StripOptions& o) {
    const auto nf = s.triangles.size();
    if (o.seed_face && o.seed_face->idx() >= nf)
        throw RequestError("seed face " + std::to_string(o.seed_face->idx()) + " is out of range (mesh has " + std::to_string(nf) +
                           " faces)");
    if (o.seed_face && o.source) {
        const Triangle& t = s.triangles[o.seed_face->idx()];
        if (t[0] != o.source->idx() && t[1] != o.source->idx() && t[2] != o.source->idx())
            throw RequestError("seed face " + std::to_string(o.seed_face->idx()) + " is not incident to source vertex " +
                               std::to_string(o.source->idx()));
    }
}

StripResult strip_part(const Part& p, const StripOptions& local, uint32_t c, uint32_t count, bool self_check) {
    Mesh mesh;
    try {
        mesh = Mesh::from_soup(p.soup);
    } catch (const InputError& e) {
        throw InternalError(std::string("prepare_soup accepted a component that Mesh::from_soup rejects: ") + e.what());
    }
    if (self_check) {
        mesh.validate();
        if (mesh.num_components() != 1) throw InternalError("a component split into several");
    }
    try {
        StripResult res = build_strip_connected(std::move(mesh), local);  // one component by construction
        if (self_check) res.mesh.validate();
        return res;
    } catch (const RequestError& e) {
        throw RequestError("component " + std::to_string(c) + " of " + std::to_string(count) + " (" + std::to_string(p.face.size()) +
                           " faces from face " + std::to_string(p.face.front()) + "): " + e.what());
    }
}

void add_stats(StripStats& total, const StripStats& s) {
    total.input_triangles += s.input_triangles;
    total.output_triangles += s.output_triangles;
    total.splits += s.splits;
    total.swaps += s.swaps;
    total.fundamental_triangles += s.fundamental_triangles;
    total.deferred_regions += s.deferred_regions;
    total.detours += s.detours;
    total.genus += s.genus;
    total.boundary_loops += s.boundary_loops;
    total.loops += s.loops;
    total.ring_flips += s.ring_flips;
    total.parity_splits += s.parity_splits;
    total.unmatched += s.unmatched;
    total.absorbed += s.absorbed;
    total.polished += s.polished;
    total.growth_fallback = total.growth_fallback || s.growth_fallback;
}

/// Appends part p's strip to r.arrays in global numbers (midpoints appended to the points).
void append_arrays(PipelineResult& r, const Part& p, const StripResult& res) {
    const StripArrays a = strip_arrays(res);
    const auto nloc = static_cast<uint32_t>(p.vertex.size());
    const auto base = static_cast<uint32_t>(r.arrays.points.size());
    r.arrays.points.insert(r.arrays.points.end(), a.points.begin() + nloc, a.points.end());
    for (std::size_t i = 0; i < a.faces.size(); ++i) {
        Triangle t{};
        for (int k = 0; k < 3; ++k) t[k] = a.faces[i][k] < nloc ? p.vertex[a.faces[i][k]] : base + (a.faces[i][k] - nloc);
        r.arrays.faces.push_back(t);
        r.arrays.parent.push_back(p.face[a.parent[i]]);
    }
}

}  // namespace

void strip_components(PipelineResult& r, const std::vector<uint32_t>& comp, uint32_t count, PipelineStage* stage) {
    if (stage) *stage = PipelineStage::Strip;  // request checks belong to the strip stage, as in build_strip()
    const StripOptions& o = r.options.strip;
    check_requests(r.input, o);
    if (stage) *stage = PipelineStage::Mesh;
    const Split sp = split_parts(r.input, comp, count);
    if (stage) *stage = PipelineStage::Strip;  // source and target in two parts is a request error
    const std::vector<uint32_t> order = part_order(sp, o);
    r.arrays.points = r.input.points;
    r.strip.stats.engine = o.engine;
    std::vector<std::vector<uint32_t>> strips;
    Cycles cycles;
    for (uint32_t c : order) {
        const Part& p = sp.parts[c];
        if (stage) *stage = PipelineStage::Strip;
        const StripResult res = strip_part(p, part_options(sp, comp, o, c), c, count, r.options.self_check);
        if (stage) *stage = PipelineStage::Encode;
        const std::size_t first = r.arrays.faces.size();
        append_arrays(r, p, res);
        std::vector<Triangle> faces(r.arrays.faces.begin() + static_cast<std::ptrdiff_t>(first), r.arrays.faces.end());
        strips.push_back(encode_triangle_strip(faces));
        const StripStats& st = res.stats;
        add_stats(r.strip.stats, st);
        r.components.push_back(
            {st.input_triangles, st.output_triangles, st.splits, st.genus, st.boundary_loops, first, strips.back().size()});
        if (r.options.cycles) {
            if (stage) *stage = PipelineStage::Cycles;
            Cycles part = compute_fundamental_cycles(res);
            for (auto& cyc : part.cycles) {
                for (uint32_t& f : cyc) f += static_cast<uint32_t>(first);
                cycles.cycles.push_back(std::move(cyc));
            }
            cycles.lengths.insert(cycles.lengths.end(), part.lengths.begin(), part.lengths.end());
            cycles.sources.insert(cycles.sources.end(), part.sources.begin(), part.sources.end());
        }
    }
    r.indices = join_strips(strips, r.options.join, r.options.restart_index);
    if (r.options.cycles) r.cycles = std::move(cycles);
}

}  // namespace singlestrip::detail
