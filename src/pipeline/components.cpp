// One strip per edge-connected component (components.hpp). Each component is stripped as its
// own soup with local vertex numbers, so a component costs O(its size), not O(V); requests are
// checked here with global numbers first, so messages name the user's vertices and faces.
#include "components.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/mesh.hpp"

namespace singlestrip::detail {
namespace {

/// The components grouped: part c's faces are faces[first[c] .. first[c + 1]), ascending, so a
/// part is built when it is stripped and freed after (all parts built up front doubled the peak:
/// two tori of 1M faces each, 282 MB against 154 MB for one torus of 2M).
struct Split {
    std::vector<uint32_t> first;                      // count + 1 offsets into faces
    std::vector<uint32_t> faces;                      // global faces, part by part
    std::vector<uint32_t> vertex_part, local_vertex;  // per global vertex (kNone when unused)
    std::vector<uint32_t> local_face;                 // per global face: its number in its part
    [[nodiscard]] uint32_t size() const { return static_cast<uint32_t>(first.size() - 1); }
};

/// One component as its own soup, numbered as the faces and vertices first appear in it.
struct Part {
    TriangleSoup soup;             // local vertex ids
    std::vector<uint32_t> vertex;  // local -> global vertex
    std::vector<uint32_t> face;    // local -> global face
    std::vector<uint32_t> twin;    // local pairing, from the analysis' (empty if it gave none)
};

Split split_parts(const TriangleSoup& s, const std::vector<uint32_t>& comp, uint32_t count) {
    Split sp;
    sp.first.assign(count + 1, 0);
    for (const uint32_t c : comp) ++sp.first[c + 1];
    for (uint32_t c = 0; c < count; ++c) sp.first[c + 1] += sp.first[c];
    sp.faces.resize(s.triangles.size());
    sp.local_face.resize(s.triangles.size());
    std::vector<uint32_t> fill(sp.first.begin(), sp.first.end() - 1);
    for (uint32_t f = 0; f < s.triangles.size(); ++f) {
        sp.local_face[f] = fill[comp[f]] - sp.first[comp[f]];
        sp.faces[fill[comp[f]]++] = f;
    }
    sp.vertex_part.assign(s.points.size(), kNone);
    sp.local_vertex.assign(s.points.size(), kNone);
    for (uint32_t c = 0; c < count; ++c) {
        uint32_t next = 0;
        for (uint32_t i = sp.first[c]; i < sp.first[c + 1]; ++i)
            for (const uint32_t v : s.triangles[sp.faces[i]]) {
                if (sp.vertex_part[v] == kNone) {
                    sp.vertex_part[v] = c;
                    sp.local_vertex[v] = next++;
                } else if (sp.vertex_part[v] != c) {
                    // prepare_soup() refuses non-manifold vertices, so no vertex is in two components.
                    throw InternalError("vertex " + std::to_string(v) + " is in two edge-connected components");
                }
            }
    }
    return sp;
}

Part make_part(const std::vector<Triangle>& triangles, const std::vector<Point3>& points, const Split& sp,
               const std::vector<uint32_t>& twin, uint32_t c) {
    Part p;
    p.face.assign(sp.faces.begin() + sp.first[c], sp.faces.begin() + sp.first[c + 1]);
    p.soup.triangles.reserve(p.face.size());
    for (const uint32_t f : p.face) {
        Triangle t{};
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = triangles[f][k];
            t[k] = sp.local_vertex[v];
            if (t[k] == p.vertex.size()) p.vertex.push_back(v);  // its first use
        }
        p.soup.triangles.push_back(t);
    }
    p.soup.points.reserve(p.vertex.size());
    for (const uint32_t v : p.vertex) p.soup.points.push_back(points[v]);
    if (twin.empty()) return p;
    p.twin.reserve(Mesh::reserved_halfedges(p.face.size()));
    for (const uint32_t f : p.face)
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t t = twin[3 * f + k];
            p.twin.push_back(t == kNone ? kNone : 3 * sp.local_face[t / 3] + t % 3);
        }
    return p;
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
                               std::to_string(sp.size()) +
                               " edge-connected components): source and target start and end one strip, so they must be in "
                               "the same component");
        first = t;
    }
    if (first) order.push_back(*first);
    for (uint32_t c = 0; c < sp.size(); ++c)
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

StripResult strip_part(Part& p, const StripOptions& local, uint32_t c, uint32_t count, bool self_check) {
    Mesh mesh;
    try {
        mesh = p.twin.empty() ? Mesh::from_soup(std::move(p.soup)) : Mesh::from_soup(std::move(p.soup), std::move(p.twin));
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

/// One part's strip in its own numbers, ready to be appended.
struct PartOut {
    std::vector<uint32_t> vertex, face;  // local -> global (Part's)
    StripArrays arrays;
    std::vector<uint32_t> strip;
    Cycles cycles;
    StripStats stats;
};

/// The shared, read-only inputs of the parts' work.
struct PartJob {
    const PipelineResult& r;
    const std::vector<Point3>& points;  // the input's (r.input.points, or moved out of it when lean)
    const Split& sp;
    const std::vector<uint32_t>& comp;
    const std::vector<uint32_t>& twin;
    uint32_t count;
};

PartOut strip_one_part(const PartJob& job, uint32_t c, PipelineStage& at) {
    at = PipelineStage::Mesh;
    Part p = make_part(job.r.input.triangles, job.points, job.sp, job.twin, c);
    at = PipelineStage::Strip;
    StripResult res = strip_part(p, part_options(job.sp, job.comp, job.r.options.strip, c), c, job.count, job.r.options.self_check);
    PartOut out{std::move(p.vertex), std::move(p.face), {}, {}, {}, res.stats};
    if (job.r.options.cycles) {
        at = PipelineStage::Cycles;
        out.cycles = compute_fundamental_cycles(res);
    }
    at = PipelineStage::Encode;
    out.arrays = strip_arrays(std::move(res));
    out.strip = encode_triangle_strip(out.arrays.faces);
    return out;
}

/// The strips in output order, in global numbers: input vertices keep theirs, each part's
/// midpoints follow the input's points in part order.
struct Joined {
    std::vector<Point3> midpoints;
    std::vector<std::vector<uint32_t>> strips;
    Cycles cycles;
};

void append_part(PipelineResult& r, uint32_t num_points, Joined& j, PartOut&& p) {
    const auto nloc = static_cast<uint32_t>(p.vertex.size());
    const auto base = num_points + static_cast<uint32_t>(j.midpoints.size());
    auto global = [&](uint32_t v) { return v < nloc ? p.vertex[v] : base + (v - nloc); };
    j.midpoints.insert(j.midpoints.end(), p.arrays.points.begin() + nloc, p.arrays.points.end());
    const std::size_t first = r.arrays.faces.size();
    for (std::size_t i = 0; i < p.arrays.faces.size(); ++i) {
        const Triangle& t = p.arrays.faces[i];
        r.arrays.faces.push_back({global(t[0]), global(t[1]), global(t[2])});
        r.arrays.parent.push_back(p.face[p.arrays.parent[i]]);
    }
    for (uint32_t& x : p.strip) x = global(x);
    const StripStats& st = p.stats;
    add_stats(r.strip.stats, st);
    r.components.push_back({st.input_triangles, st.output_triangles, st.splits, st.genus, st.boundary_loops, first, p.strip.size()});
    j.strips.push_back(std::move(p.strip));
    for (auto& cyc : p.cycles.cycles) {
        for (uint32_t& f : cyc) f += static_cast<uint32_t>(first);
        j.cycles.cycles.push_back(std::move(cyc));
    }
    j.cycles.lengths.insert(j.cycles.lengths.end(), p.cycles.lengths.begin(), p.cycles.lengths.end());
    j.cycles.sources.insert(j.cycles.sources.end(), p.cycles.sources.begin(), p.cycles.sources.end());
}

/// From this many faces in all, two threads strip parts (each part on one; a thread costs tens
/// of microseconds).
constexpr std::size_t kTwoThreadParts = std::size_t{1} << 14;

/// Strips the parts in `order` on this thread and, when `parallel`, one more, appending each
/// to r as soon as every part before it is in. The first failure in part order is rethrown,
/// as a sequential loop would give it.
void strip_parts(PipelineResult& r, const PartJob& job, const std::vector<uint32_t>& order, Joined& j, bool parallel,
                 PipelineStage* stage) {
    const std::size_t n = order.size();
    std::vector<std::unique_ptr<PartOut>> done(n);  // finished, waiting for the parts before
    std::vector<std::exception_ptr> failed(n);
    std::vector<PipelineStage> at(n, PipelineStage::Mesh);
    std::mutex m;
    std::size_t appended = 0;
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    const auto num_points = static_cast<uint32_t>(job.points.size());
    auto work = [&] {
        for (std::size_t i; !stop && (i = next++) < n;) {
            std::unique_ptr<PartOut> out;
            std::exception_ptr err;
            try {
                out = std::make_unique<PartOut>(strip_one_part(job, order[i], at[i]));
            } catch (...) {
                err = std::current_exception();
                stop = true;
            }
            const std::lock_guard<std::mutex> lock(m);
            failed[i] = err;
            done[i] = std::move(out);
            for (; appended < n && done[appended]; ++appended) {
                append_part(r, num_points, j, std::move(*done[appended]));
                done[appended].reset();
            }
        }
    };
    std::thread other;
    if (parallel) try {
            other = std::thread(work);
        } catch (const std::system_error&) {  // no thread to be had: all on this one
        }
    work();
    if (other.joinable()) other.join();
    for (std::size_t i = 0; i < n; ++i)
        if (failed[i]) {
            if (stage) *stage = at[i];
            std::rethrow_exception(failed[i]);
        }
}

}  // namespace

void strip_components(PipelineResult& r, const std::vector<uint32_t>& comp, uint32_t count, std::vector<uint32_t> twin,
                      PipelineStage* stage) {
    if (stage) *stage = PipelineStage::Strip;  // request checks belong to the strip stage, as in build_strip()
    const StripOptions& o = r.options.strip;
    check_requests(r.input, o);
    if (stage) *stage = PipelineStage::Mesh;
    const Split sp = split_parts(r.input, comp, count);
    if (stage) *stage = PipelineStage::Strip;  // source and target in two parts is a request error
    const std::vector<uint32_t> order = part_order(sp, o);
    r.strip.stats.engine = o.engine;
    // Lean (release_intermediates(), no attributes): the points move to the output, not copied.
    const bool lean = r.options.release_intermediates && r.input.attributes.empty();
    std::vector<Point3> points = lean ? std::move(r.input.points) : std::vector<Point3>();
    const PartJob job{r, lean ? points : r.input.points, sp, comp, twin, count};
    r.arrays.faces.reserve(r.input.triangles.size());
    r.arrays.parent.reserve(r.input.triangles.size());
    Joined j;
    strip_parts(r, job, order, j, r.input.triangles.size() >= kTwoThreadParts, stage);
    if (stage) *stage = PipelineStage::Encode;
    r.arrays.points = lean ? std::move(points) : r.input.points;
    r.arrays.points.insert(r.arrays.points.end(), j.midpoints.begin(), j.midpoints.end());
    if (lean) r.input = TriangleSoup{};
    r.indices = join_strips(j.strips, r.options.join, r.options.restart_index);
    if (r.options.cycles) r.cycles = std::move(j.cycles);
}

}  // namespace singlestrip::detail
