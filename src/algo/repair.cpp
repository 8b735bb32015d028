// Repair of a triangle soup: weld, drop, cut apart, orient (see repair.hpp and docs/repair.md).
// Faces never move: half-edge 3f+k keeps its identity while vertices are re-pointed, so cut
// marks survive the vertex splits.
#include "singlestrip/repair.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "core/soup_edges.hpp"
#include "singlestrip/attributes.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/validate.hpp"
#include "union_find.hpp"

namespace singlestrip {
namespace {

uint32_t from(const std::vector<Triangle>& t, uint32_t h) {
    return t[h / 3][h % 3];
}
uint32_t to(const std::vector<Triangle>& t, uint32_t h) {
    return t[h / 3][(h % 3 + 1) % 3];
}

/// The corner of face h/3 at vertex v (v is an end of half-edge h).
uint32_t corner_at(const std::vector<Triangle>& t, uint32_t h, uint32_t v) {
    return from(t, h) == v ? h : 3 * (h / 3) + (h % 3 + 1) % 3;
}

/// The input vertex a (possibly copied) vertex stands for.
uint32_t input_vertex(uint32_t v, std::size_t n, const std::vector<uint32_t>& copied_from) {
    return v < n ? v : copied_from[v - n];
}

/// Working state shared by the steps.
struct Work {
    std::size_t n = 0;  // input points
    std::vector<Point3> points;
    std::vector<Triangle> tris;
    std::vector<uint32_t> origin;  // input face per face
    std::vector<char> cut;         // per half-edge: never glue across it
    RepairReport& rep;
    std::vector<char> split_mark;  // per input vertex: reported in split_vertices

    // Every vertex gets one copy per fan of faces glued across uncut edges with exactly two faces;
    // corners are visited in index order, so the fan with the lowest corner keeps the vertex.
    void split_fans() {
        UnionFind corners(3 * tris.size());
        edges().for_each_edge([&](const SoupEdges::Edge& e) {
            if (e.num_halfedges() != 2) return;
            const uint32_t h0 = e.first[0], h1 = e.first[1];
            if (cut[h0] || cut[h1]) return;
            for (uint32_t v : {from(tris, h0), to(tris, h0)}) corners.unite(corner_at(tris, h0, v), corner_at(tris, h1, v));
        });
        std::vector<uint32_t> assigned(3 * tris.size(), kNone);
        std::vector<char> taken(points.size(), 0);
        for (uint32_t c = 0; c < 3 * tris.size(); ++c) {
            const uint32_t r = corners.find(c);
            uint32_t& v = tris[c / 3][c % 3];
            if (assigned[r] == kNone) {
                if (!taken[v]) {
                    taken[v] = 1;
                    assigned[r] = v;
                } else {
                    const uint32_t iv = input_vertex(v, n, rep.copied_from);
                    assigned[r] = static_cast<uint32_t>(points.size());
                    points.push_back(points[v]);
                    taken.push_back(1);
                    rep.copied_from.push_back(iv);
                    if (!split_mark[iv]) {
                        split_mark[iv] = 1;
                        rep.split_vertices.push_back(iv);
                    }
                }
            }
            v = assigned[r];
        }
    }

    /// The faces' half-edges grouped and classified (soup_edges.hpp); valid until tris changes.
    SoupEdges edges() const { return SoupEdges(tris, points.size()); }

    void record_non_manifold_edges() {
        edges().for_each_edge([&](const SoupEdges::Edge& e) {
            if (e.kind == EdgeKind::non_manifold) rep.non_manifold_edges.emplace_back(e.lo, e.hi);
        });
    }

    /// Twin of each half-edge across an uncut edge with exactly two faces, else kNone.
    std::vector<uint32_t> twins() const {
        std::vector<uint32_t> twin(3 * tris.size(), kNone);
        edges().for_each_edge([&](const SoupEdges::Edge& e) {
            if (e.kind == EdgeKind::non_manifold)
                throw InternalError("repair: edge still has " + std::to_string(e.num_halfedges()) + " faces after the cut");
            if (e.kind != EdgeKind::boundary && !cut[e.first[0]] && !cut[e.first[1]]) SoupEdges::pair(e, twin);
        });
        return twin;
    }

    struct Orientation {
        std::vector<uint32_t> twin, comp, order;  // order: faces by component, BFS order
        std::vector<uint32_t> comp_start;
        std::vector<int8_t> flip;
        std::vector<uint32_t> conflicts;  // half-edges where the search disagrees with itself
    };

    // Breadth-first from the lowest face of each component: flip[g] = flip[f] xor (same direction).
    Orientation orient_search() const {
        Orientation o;
        o.twin = twins();
        const std::size_t nf = tris.size();
        o.flip.assign(nf, -1);
        o.comp.assign(nf, kNone);
        for (uint32_t s = 0; s < nf; ++s) {
            if (o.flip[s] >= 0) continue;
            o.comp_start.push_back(static_cast<uint32_t>(o.order.size()));
            o.flip[s] = 0;
            o.order.push_back(s);
            for (std::size_t qi = o.comp_start.back(); qi < o.order.size(); ++qi) {
                const uint32_t f = o.order[qi];
                o.comp[f] = static_cast<uint32_t>(o.comp_start.size() - 1);
                for (uint32_t k = 0; k < 3; ++k) {
                    const uint32_t h = 3 * f + k, t = o.twin[h];
                    if (t == kNone) continue;
                    const auto want = static_cast<int8_t>(o.flip[f] ^ (from(tris, h) == from(tris, t) ? 1 : 0));
                    if (o.flip[t / 3] < 0) {
                        o.flip[t / 3] = want;
                        o.order.push_back(t / 3);
                    } else if (o.flip[t / 3] != want && h < t) {
                        o.conflicts.push_back(h);
                    }
                }
            }
        }
        o.comp_start.push_back(static_cast<uint32_t>(o.order.size()));
        return o;
    }

    // The disagreeing edges of a non-orientable component form curves (an even number at every
    // interior vertex); cutting them and splitting fans again leaves the search tree intact.
    Orientation orient_with_cuts() {
        for (int round = 0; round < 4; ++round) {
            Orientation o = orient_search();
            if (o.conflicts.empty()) return o;
            std::vector<char> bad_comp(o.comp_start.size(), 0);
            for (uint32_t h : o.conflicts) {
                const uint32_t t = o.twin[h];
                cut[h] = cut[t] = 1;
                bad_comp[o.comp[h / 3]] = 1;
                const uint32_t a = input_vertex(from(tris, h), n, rep.copied_from), b = input_vertex(to(tris, h), n, rep.copied_from);
                rep.orientation_cuts.emplace_back(std::min(a, b), std::max(a, b));
            }
            rep.non_orientable_components += static_cast<uint32_t>(std::count(bad_comp.begin(), bad_comp.end(), 1));
            split_fans();
        }
        throw InternalError("repair: a non-orientable component is still not orientable after cutting");
    }

    // Each component keeps its majority orientation; a closed one is turned outward.
    void choose_orientation(Orientation& o) {
        rep.components = static_cast<uint32_t>(o.comp_start.size() - 1);
        for (std::size_t c = 0; c + 1 < o.comp_start.size(); ++c) {
            const auto first = o.order.begin() + o.comp_start[c], last = o.order.begin() + o.comp_start[c + 1];
            const auto size = static_cast<std::size_t>(last - first);
            std::size_t flips = 0;
            bool closed = true;
            for (auto it = first; it != last; ++it) {
                flips += o.flip[*it] == 1 ? 1 : 0;
                for (uint32_t k = 0; k < 3; ++k) closed = closed && o.twin[3 * *it + k] != kNone;
            }
            const bool majority_invert = 2 * flips > size;
            bool invert = majority_invert;
            if (closed) {
                std::vector<Triangle> faces;
                for (auto it = first; it != last; ++it) {
                    Triangle t = tris[*it];
                    if (o.flip[*it] == 1) std::swap(t[1], t[2]);
                    faces.push_back(t);
                }
                const double vol = signed_volume(points, faces);
                if (vol != 0) invert = vol < 0;
                if (invert != majority_invert) ++rep.turned_outward;
            }
            if (invert)
                for (auto it = first; it != last; ++it) o.flip[*it] = static_cast<int8_t>(1 - o.flip[*it]);
        }
        for (uint32_t f = 0; f < tris.size(); ++f)
            if (o.flip[f] == 1) {
                std::swap(tris[f][1], tris[f][2]);
                rep.flipped_faces.push_back(origin[f]);
            }
    }
};

/// Step 2: drops out-of-range and repeated-vertex faces (after welding) and later copies of a
/// vertex set; fills w.tris and w.origin in input order.
void keep_faces(const TriangleSoup& in, const std::vector<uint32_t>& weld, Work& w) {
    const std::size_t n = in.points.size();
    std::vector<char> referenced(n, 0);
    for (uint32_t f = 0; f < in.triangles.size(); ++f) {
        Triangle t = in.triangles[f];
        if (t[0] >= n || t[1] >= n || t[2] >= n) {
            w.rep.invalid_faces.push_back(f);
            continue;
        }
        for (uint32_t& v : t) {
            referenced[v] = 1;
            v = weld[v];
        }
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
            w.rep.degenerate_faces.push_back(f);
            continue;
        }
        w.tris.push_back(t);
        w.origin.push_back(f);
    }
    for (uint32_t v = 0; v < n; ++v)
        if (referenced[v] && weld[v] != v) w.rep.welded.emplace_back(v, weld[v]);
    std::vector<std::pair<Triangle, uint32_t>> sorted;
    sorted.reserve(w.tris.size());
    for (uint32_t i = 0; i < w.tris.size(); ++i) {
        Triangle t = w.tris[i];
        std::sort(t.begin(), t.end());
        sorted.emplace_back(t, i);
    }
    std::sort(sorted.begin(), sorted.end());
    std::vector<char> drop(w.tris.size(), 0);
    for (std::size_t i = 1; i < sorted.size(); ++i)
        if (sorted[i].first == sorted[i - 1].first) drop[sorted[i].second] = 1;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < w.tris.size(); ++i) {
        if (drop[i]) {
            w.rep.duplicate_faces.push_back(w.origin[i]);
            continue;
        }
        w.tris[kept] = w.tris[i];
        w.origin[kept++] = w.origin[i];
    }
    w.tris.resize(kept);
    w.origin.resize(kept);
    std::sort(w.rep.duplicate_faces.begin(), w.rep.duplicate_faces.end());
}

void add_count(std::string& s, std::size_t count, const char* what) {
    if (count == 0) return;
    s += (s.empty() ? "" : ", ") + std::to_string(count) + " " + what;
}

}  // namespace

bool RepairReport::changed() const noexcept {
    return !welded.empty() || !invalid_faces.empty() || !degenerate_faces.empty() || !duplicate_faces.empty() ||
           !non_manifold_edges.empty() || !copied_from.empty() || !orientation_cuts.empty() || !flipped_faces.empty();
}

std::string RepairReport::summary() const {
    std::string s;
    add_count(s, welded.size(), "vertices welded");
    add_count(s, invalid_faces.size(), "faces with an index out of range dropped");
    add_count(s, degenerate_faces.size(), "degenerate faces (repeated vertex) dropped");
    add_count(s, duplicate_faces.size(), "duplicate faces dropped");
    add_count(s, non_manifold_edges.size(), "non-manifold edges cut");
    add_count(s, orientation_cuts.size(), "edges cut to make non-orientable parts orientable");
    add_count(s, split_vertices.size(), "vertices split");
    add_count(s, copied_from.size(), "vertex copies added");
    add_count(s, flipped_faces.size(), "faces flipped");
    add_count(s, turned_outward, "closed components turned outward against their majority");
    return s.empty() ? "nothing to repair" : s;
}

std::vector<uint32_t> weld_map(const TriangleSoup& soup) {
    std::vector<uint32_t> rep = weld_map(soup.points);
    if (soup.attributes.empty()) return rep;
    // Vertices at one position but with different attributes (a texture seam) stay apart: each
    // joins the lowest-numbered vertex equal to it in everything.
    auto same = [&](uint32_t a, uint32_t b) {
        for (const VertexAttribute& at : soup.attributes)
            for (std::size_t c = 0; c < at.components; ++c)
                if (at.values[a * at.components + c] != at.values[b * at.components + c]) return false;
        return true;
    };
    std::vector<std::vector<uint32_t>> members(soup.points.size());
    for (uint32_t v = 0; v < rep.size(); ++v) {
        auto& group = members[rep[v]];
        const auto it = std::find_if(group.begin(), group.end(), [&](uint32_t u) { return same(u, v); });
        const uint32_t to = it == group.end() ? v : *it;
        if (it == group.end()) group.push_back(v);
        rep[v] = to;
    }
    return rep;
}

std::vector<uint32_t> weld_map(const std::vector<Point3>& points) {
    std::vector<uint32_t> rep(points.size());
    std::iota(rep.begin(), rep.end(), 0u);
    std::vector<uint32_t> idx;
    idx.reserve(points.size());
    // Non-finite points never weld (and would break the strict ordering of the sort).
    for (uint32_t v = 0; v < points.size(); ++v)
        if (std::isfinite(points[v][0]) && std::isfinite(points[v][1]) && std::isfinite(points[v][2])) idx.push_back(v);
    // Ties by index (not std::stable_sort: its temporary buffer trips ASan's alloc-dealloc check
    // in GCC 12's libstdc++).
    std::sort(idx.begin(), idx.end(), [&](uint32_t a, uint32_t b) { return points[a] < points[b] || (points[a] == points[b] && a < b); });
    for (std::size_t i = 1; i < idx.size(); ++i)
        if (points[idx[i]] == points[idx[i - 1]]) rep[idx[i]] = rep[idx[i - 1]];
    return rep;
}

uint64_t weld_soup(TriangleSoup& soup) {
    const std::vector<uint32_t> rep = weld_map(soup);
    std::vector<char> merged(soup.points.size(), 0);
    uint64_t count = 0;
    for (Triangle& t : soup.triangles)
        for (uint32_t& v : t)
            if (v < rep.size() && rep[v] != v) {
                if (!merged[v]) ++count;
                merged[v] = 1;
                v = rep[v];
            }
    return count;
}

double signed_volume(const std::vector<Point3>& points, const std::vector<Triangle>& faces) {
    if (faces.empty()) return 0;
    const Point3 o = points[faces[0][0]];  // a nearby origin keeps the products well scaled
    double vol = 0;
    for (const Triangle& t : faces) {
        std::array<std::array<double, 3>, 3> p{};
        for (int i = 0; i < 3; ++i)
            for (int d = 0; d < 3; ++d) p[i][d] = points[t[i]][d] - o[d];
        vol += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
               p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
    }
    return vol / 6.0;
}

RepairedSoup repair_soup(const TriangleSoup& in, const RepairOptions& options) {
    RepairedSoup out;
    Work w{in.points.size(), in.points, {}, {}, {}, out.report, std::vector<char>(in.points.size(), 0)};
    std::vector<uint32_t> weld(in.points.size());
    std::iota(weld.begin(), weld.end(), 0u);
    if (options.weld) weld = weld_map(in);
    keep_faces(in, weld, w);
    w.cut.assign(3 * w.tris.size(), 0);
    w.record_non_manifold_edges();
    w.split_fans();
    Work::Orientation o = w.orient_with_cuts();
    w.choose_orientation(o);
    std::sort(out.report.split_vertices.begin(), out.report.split_vertices.end());

    out.soup.points = std::move(w.points);
    out.soup.triangles = std::move(w.tris);
    out.face_origin = std::move(w.origin);
    out.soup.attributes = in.attributes;
    append_copies(out.soup.attributes, out.report.copied_from);
    if (!in.source_polygon.empty() && in.source_polygon.size() == in.triangles.size())
        for (uint32_t f : out.face_origin) out.soup.source_polygon.push_back(in.source_polygon[f]);
    // The post-condition is cheap to check next to the repair itself, and a miss is a bug.
    for (const SoupProblem& p : diagnose_soup(out.soup))
        if (p.kind != "no_faces") throw InternalError("repair left a problem: " + p.message);
    return out;
}

}  // namespace singlestrip
