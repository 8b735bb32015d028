// singlestrip — mesh core: corner table construction, midpoint split, topology queries.
#include "singlestrip/mesh.hpp"
#include "singlestrip/vec3.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "gentle_growth.hpp"
#include "singlestrip/errors.hpp"
#include "soup_edges.hpp"
#include "topology.hpp"
#include "two_halves.hpp"

namespace singlestrip {

Mesh Mesh::from_soup(const TriangleSoup& soup) {
    return build(soup.triangles, soup.points);
}

Mesh Mesh::from_soup(TriangleSoup&& soup) {
    // The caller gave the soup up: free it as soon as it is copied (assigning {} would keep
    // the capacity); build() frees the triangles once the corners hold them.
    soup.source_polygon = std::vector<uint32_t>();
    Mesh m = build(soup.triangles, std::move(soup.points), &soup.triangles);
    soup.points = std::vector<Point3>();
    return m;
}

Mesh Mesh::from_soup(const TriangleSoup& soup, std::vector<uint32_t>&& twin) {
    return build(soup.triangles, soup.points, nullptr, &twin);
}

Mesh Mesh::from_soup(TriangleSoup&& soup, std::vector<uint32_t>&& twin) {
    soup.source_polygon = std::vector<uint32_t>();
    Mesh m = build(soup.triangles, std::move(soup.points), &soup.triangles, &twin);
    soup.points = std::vector<Point3>();
    return m;
}

// The pairing's scratch (SoupEdges, 28 bytes a face while sorting) comes before the corner
// table's arrays, and `release` (the soup's triangles) goes once the corners are filled: that
// keeps the peak of a large mesh at about its corner table plus the soup.
Mesh Mesh::build(const std::vector<Triangle>& triangles, std::vector<Point3> points, std::vector<Triangle>* release,
                 std::vector<uint32_t>* paired) {
    Mesh m;
    const size_t nf = triangles.size();
    if (nf >= kNone / 3) throw InputError("mesh has too many faces (" + std::to_string(nf) + ")");
    m.points_ = std::move(points);
    m.num_input_vertices_ = static_cast<uint32_t>(m.points_.size());
    m.num_input_faces_ = static_cast<uint32_t>(nf);
    for (size_t f = 0; f < nf; ++f) {
        const Triangle& t = triangles[f];
        for (int k = 0; k < 3; ++k)
            if (t[k] >= m.points_.size())
                throw InputError("face " + std::to_string(f) + " references vertex " + std::to_string(t[k]) + " but there are only " +
                                 std::to_string(m.points_.size()) + " vertices");
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) throw InputError("face " + std::to_string(f) + " repeats a vertex");
    }
    // Capacity for the splits the engines add (reserve_splits(): F/16 at most up front), taken
    // before the arrays are filled: reserving later copies them all (2M faces: 50 ms), and pages
    // no split touches cost address space, not memory.
    const size_t spare = reserved_spare(nf);
    if (paired) {
        m.adopt_twins(std::move(*paired), triangles);
    } else {
        m.twin_.reserve(reserved_halfedges(nf));
        m.twin_.assign(3 * nf, kNone);
        m.pair_halfedges(SoupEdges(triangles, m.points_.size()));
    }
    m.corner_vertex_.reserve(3 * nf + 6 * spare);
    m.corner_vertex_.resize(3 * nf);
    for (size_t f = 0; f < nf; ++f)
        for (int k = 0; k < 3; ++k) m.corner_vertex_[3 * f + k] = triangles[f][k];
    if (release) *release = std::vector<Triangle>();
    m.face_parent_.reserve(nf + 2 * spare);
    m.face_parent_.resize(nf);
    std::iota(m.face_parent_.begin(), m.face_parent_.end(), 0u);
    m.vertex_halfedge_.reserve(m.points_.size() + spare);
    m.assign_vertex_halfedges();
    m.check_vertex_fans();
    return m;
}

// A pairing found by the caller's analysis, checked to be one: each pair is mutual and runs
// opposite ways along one edge (sequential reads but for the partner's two ends).
void Mesh::adopt_twins(std::vector<uint32_t>&& twin, const std::vector<Triangle>& triangles) {
    const size_t nh = 3 * triangles.size();
    if (twin.size() != nh) throw InputError("edge pairing of " + std::to_string(twin.size()) + " half-edges for " + std::to_string(nh));
    auto end = [&](uint32_t h, uint32_t k) { return triangles[h / 3][(h % 3 + k) % 3]; };
    for (uint32_t h = 0; h < nh; ++h) {
        const uint32_t t = twin[h];
        if (t == kNone) continue;
        if (t >= nh || t == h || twin[t] != h || end(h, 0) != end(t, 1) || end(h, 1) != end(t, 0))
            throw InputError("edge pairing: half-edge " + std::to_string(h) + " is not paired with an opposite half-edge");
    }
    twin_ = std::move(twin);
    twin_.reserve(reserved_halfedges(triangles.size()));
}

void Mesh::pair_halfedges(const SoupEdges& edges) {
    // Each half-edge is on one edge, each edge at one smaller end: the halves write apart
    // (with the fan checks' and the sorts' halves, 1.3M-face sphere: from_soup 64 -> 50 ns a face).
    const auto nv = static_cast<uint32_t>(edges.num_vertices());
    run_in_two_halves(edges.middle_vertex(), nv, twin_.size() / 3 >= kTwoThreadFaces,
                      [&](uint32_t begin, uint32_t end) { pair_halfedge_range(edges, begin, end); });
}

void Mesh::pair_halfedge_range(const SoupEdges& edges, uint32_t v_begin, uint32_t v_end) {
    edges.for_each_edge(v_begin, v_end, [&](const SoupEdges::Edge& e) {
        const uint32_t h0 = *e.first;
        switch (e.kind) {
            case EdgeKind::boundary:
                return;
            case EdgeKind::non_manifold:
                throw InputError("edge (" + std::to_string(edges.from(h0)) + ", " + std::to_string(edges.to(h0)) + ") has " +
                                 std::to_string(e.num_halfedges()) + " faces (non-manifold edge)");
            case EdgeKind::inconsistent:
                throw InputError("faces " + std::to_string(h0 / 3) + " and " + std::to_string(e.first[1] / 3) + " traverse edge (" +
                                 std::to_string(edges.from(h0)) + ", " + std::to_string(edges.to(h0)) +
                                 ") in the same direction (inconsistent orientation)");
            case EdgeKind::manifold:
                SoupEdges::pair(e, twin_);
                return;
        }
    });
}

// One outgoing half-edge per vertex; a boundary vertex gets its boundary half-edge, so the
// rotation h -> twin(prev(h)) from it sees the whole fan.
void Mesh::assign_vertex_halfedges() {
    vertex_halfedge_.assign(points_.size(), kNone);
    for (uint32_t h = 0; h < twin_.size(); ++h) {
        uint32_t& vh = vertex_halfedge_[corner_vertex_[h]];
        if (vh == kNone || twin_[h] == kNone) vh = h;
    }
}

// Vertex manifoldness: each vertex's fan must contain all its corners.
void Mesh::check_vertex_fans() const {
    std::vector<uint32_t> corners_at(points_.size(), 0);
    for (const uint32_t v : corner_vertex_) ++corners_at[v];
    const auto nv = static_cast<uint32_t>(points_.size());
    run_in_two_halves(nv / 2, nv, face_parent_.size() >= kTwoThreadFaces,
                      [&](uint32_t begin, uint32_t end) { check_fan_range(corners_at, begin, end); });
}

void Mesh::check_fan_range(const std::vector<uint32_t>& corners_at, uint32_t v_begin, uint32_t v_end) const {
    for (uint32_t i = v_begin; i < v_end; ++i) {
        const VertexId v(i);
        const HalfedgeId h0 = vertex_halfedge(v);
        if (!h0.valid()) continue;
        uint32_t count = 0;
        HalfedgeId h = h0;
        do {
            ++count;
            const HalfedgeId t = twin(prev(h));
            if (!t.valid()) break;
            h = t;
        } while (h != h0 && count <= corners_at[v.idx()]);
        if (count != corners_at[v.idx()])
            throw InputError("vertex " + std::to_string(v.idx()) + " is non-manifold (" + std::to_string(corners_at[v.idx()]) +
                             " faces in more than one fan)");
    }
}

HalfedgeId Mesh::shared_halfedge(FaceId f, FaceId g) const noexcept {
    for (uint32_t k = 0; k < 3; ++k) {
        const HalfedgeId h = halfedge(f, k);
        if (neighbor(h) == g && g.valid()) return h;
    }
    return kNone;
}

SplitResult Mesh::split_edge(HalfedgeId he) {
    if (he.idx() >= twin_.size() || is_boundary(he))
        throw InternalError("split_edge: half-edge " + std::to_string(he.idx()) + " is not an interior edge");
    reserve_for_split();  // first: references into points_ below must stay valid
    // The corner table's own arrays, indexed directly.
    const uint32_t h = he.idx(), t = twin_[h];
    const uint32_t f = h / 3, g = t / 3;
    const uint32_t a = corner_vertex_[h], b = to(he).idx(), c = opposite(he).idx(), d = opposite(HalfedgeId(t)).idx();
    const uint32_t hn = next(he).idx();             // b->c in f (prev(h), c->a, stays)
    const uint32_t tn = next(HalfedgeId(t)).idx();  // a->d in g (prev(t), d->b, stays)
    const uint32_t twin_bc = twin_[hn], twin_ad = twin_[tn];

    const auto& pa = points_[a];
    const auto& pb = points_[b];
    const uint32_t mid = static_cast<uint32_t>(points_.size());
    points_.push_back(vec3::midpoint(pa, pb));
    vertex_halfedge_.push_back(kNone);

    const uint32_t fb = num_faces(), ga = fb + 1;
    const uint32_t fb0 = 3 * fb, ga0 = 3 * ga;
    corner_vertex_.insert(corner_vertex_.end(), {mid, b, c, mid, a, d});
    twin_.insert(twin_.end(), 6, kNone);
    face_parent_.push_back(face_parent_[f]);
    face_parent_.push_back(face_parent_[g]);

    // f = (a, mid, c): h: a->mid, hn: mid->c, hp: c->a (unchanged)
    corner_vertex_[hn] = mid;
    // g = (b, mid, d): t: b->mid, tn: mid->d, tp: d->b (unchanged)
    corner_vertex_[tn] = mid;

    auto link = [&](uint32_t x, uint32_t y) {
        twin_[x] = y;
        if (y != kNone) twin_[y] = x;
    };
    link(h, ga0 + 0);        // a->mid  |  mid->a
    link(hn, fb0 + 2);       // mid->c  |  c->mid
    link(t, fb0 + 0);        // b->mid  |  mid->b
    link(tn, ga0 + 2);       // mid->d  |  d->mid
    link(fb0 + 1, twin_bc);  // b->c moved into f_b
    link(ga0 + 1, twin_ad);  // a->d moved into g_a

    // Half-edges that moved out of f/g: b->c (was hn) and a->d (was tn).
    if (vertex_halfedge_[b] == hn) vertex_halfedge_[b] = fb0 + 1;
    if (vertex_halfedge_[a] == tn) vertex_halfedge_[a] = ga0 + 1;
    vertex_halfedge_[mid] = fb0 + 0;
    return SplitResult{VertexId(mid), FaceId(f), FaceId(fb), FaceId(ga), FaceId(g)};
}

void Mesh::reserve_splits(uint32_t splits) {
    points_.reserve(points_.size() + splits);
    vertex_halfedge_.reserve(vertex_halfedge_.size() + splits);
    corner_vertex_.reserve(corner_vertex_.size() + size_t{6} * splits);
    twin_.reserve(twin_.size() + size_t{6} * splits);
    face_parent_.reserve(face_parent_.size() + size_t{2} * splits);
}

void Mesh::reserve_for_split() {
    reserve_gently(points_, points_.size() + 1);
    reserve_gently(vertex_halfedge_, vertex_halfedge_.size() + 1);
    reserve_gently(corner_vertex_, corner_vertex_.size() + 6);
    reserve_gently(twin_, twin_.size() + 6);
    reserve_gently(face_parent_, face_parent_.size() + 2);
}

void Mesh::renumber_input_vertices(const std::vector<uint32_t>& to) {
    const size_t n = num_input_vertices_;
    const auto refuse = [n] {
        throw InternalError("renumber_input_vertices: not a permutation of the " + std::to_string(n) + " input vertices");
    };
    if (to.size() != n) refuse();
    std::vector<char> hit(n, 0);
    for (const uint32_t w : to) {
        if (w >= n || hit[w]) refuse();
        hit[w] = 1;
    }
    for (uint32_t& v : corner_vertex_)
        if (v < n) v = to[v];
    std::vector<Point3> points(points_.begin(), points_.begin() + static_cast<std::ptrdiff_t>(n));
    std::vector<uint32_t> out(vertex_halfedge_.begin(), vertex_halfedge_.begin() + static_cast<std::ptrdiff_t>(n));
    for (size_t v = 0; v < n; ++v) {
        points_[to[v]] = points[v];
        vertex_halfedge_[to[v]] = out[v];
    }
}

std::vector<Point3> Mesh::release_points() && {
    std::vector<Point3> p = std::move(points_);
    *this = Mesh();
    return p;
}

uint32_t Mesh::num_referenced_vertices() const {
    uint32_t n = 0;
    for (uint32_t vh : vertex_halfedge_) n += vh != kNone;
    return n;
}

uint32_t Mesh::num_edges() const {
    uint32_t n = 0;
    for (uint32_t h = 0; h < twin_.size(); ++h) n += twin_[h] == kNone || h < twin_[h];
    return n;
}

uint32_t Mesh::num_boundary_edges() const {
    return static_cast<uint32_t>(std::count(twin_.begin(), twin_.end(), kNone));
}

uint32_t Mesh::num_boundary_loops() const {
    // Follow boundary half-edges: the next boundary half-edge after h starts at to(h); rotate
    // clockwise around to(h) from next(h) until a boundary half-edge is found.
    std::vector<char> seen;  // allocated at the first boundary half-edge: a closed mesh needs none
    uint32_t loops = 0;
    for (uint32_t h0 = 0; h0 < twin_.size(); ++h0) {
        if (twin_[h0] != kNone) continue;
        if (seen.empty()) seen.assign(twin_.size(), 0);
        if (seen[h0]) continue;
        ++loops;
        uint32_t h = h0;
        while (!seen[h]) {
            seen[h] = 1;
            HalfedgeId n = next(HalfedgeId(h));
            while (!is_boundary(n)) n = next(twin(n));
            h = n.idx();
        }
    }
    return loops;
}

// A union-find over the twin pairs in half-edge order (sequential reads; a search from face to
// face reads the corner table at random, about 4x slower on a 1M-face sphere). Each root is the
// smallest face of its set (links point to smaller faces), so one pass in face order labels the
// components in order of their first face, as a search from face 0 upward would.
std::vector<uint32_t> Mesh::component_of_faces() const {
    const auto nf = static_cast<uint32_t>(face_parent_.size());
    std::vector<uint32_t> comp(nf);  // a link to a smaller face (or itself), then the label
    std::iota(comp.begin(), comp.end(), 0u);
    auto find = [&comp](uint32_t x) {
        while (comp[x] != x) x = comp[x] = comp[comp[x]];
        return x;
    };
    for (uint32_t h = 0; h < twin_.size(); ++h) {
        if (twin_[h] == kNone || twin_[h] < h) continue;
        const uint32_t a = find(h / 3), b = find(twin_[h] / 3);
        comp[std::max(a, b)] = std::min(a, b);
    }
    uint32_t id = 0;
    for (uint32_t f = 0; f < nf; ++f) comp[f] = comp[f] == f ? id++ : comp[comp[f]];  // the link is labelled already
    return comp;
}

uint32_t Mesh::num_components() const {
    const auto comp = component_of_faces();
    uint32_t n = 0;
    for (uint32_t c : comp) n = std::max(n, c + 1);
    return n;
}

long long Mesh::euler_characteristic() const {
    return singlestrip::euler_characteristic(num_referenced_vertices(), num_edges(), num_faces());
}

long long Mesh::genus() const {
    return genus_from_euler(euler_characteristic(), num_boundary_loops(), 1);
}

void Mesh::validate() const {
    auto fail = [](const std::string& what) { throw InternalError("mesh invariant violated: " + what); };
    const size_t nf = face_parent_.size();
    if (corner_vertex_.size() != 3 * nf || twin_.size() != 3 * nf) fail("I1 array sizes");
    if (vertex_halfedge_.size() != points_.size()) fail("I4 vertex_halfedge size");
    for (uint32_t f = 0; f < nf; ++f) {
        const uint32_t a = corner_vertex_[3 * f], b = corner_vertex_[3 * f + 1], c = corner_vertex_[3 * f + 2];
        if (a >= points_.size() || b >= points_.size() || c >= points_.size())
            fail("I2 face " + std::to_string(f) + " vertex out of range");
        if (a == b || b == c || a == c) fail("I2 face " + std::to_string(f) + " repeats a vertex");
        if (face_parent_[f] >= num_input_faces_) fail("I6 face " + std::to_string(f) + " parent out of range");
    }
    std::vector<uint32_t> corners_at(points_.size(), 0);
    for (uint32_t h = 0; h < twin_.size(); ++h) {
        ++corners_at[corner_vertex_[h]];
        const uint32_t t = twin_[h];
        if (t == kNone) continue;
        const HalfedgeId ht(h), tt(t);
        if (t >= twin_.size() || twin_[t] != h || face(tt) == face(ht) || from(tt) != to(ht) || to(tt) != from(ht))
            fail("I3 half-edge " + std::to_string(h) + " twin");
    }
    for (uint32_t v = 0; v < points_.size(); ++v) {
        const uint32_t h0 = vertex_halfedge_[v];
        if (h0 == kNone) {
            if (corners_at[v] != 0) fail("I4 vertex " + std::to_string(v) + " has faces but no half-edge");
            continue;
        }
        if (h0 >= twin_.size() || corner_vertex_[h0] != v) fail("I4 vertex " + std::to_string(v) + " half-edge");
        // Walk both ways around v; together the walks must see every corner exactly once.
        uint32_t count = 1;
        uint32_t h = h0;
        bool closed = false;
        while (count <= corners_at[v]) {
            const uint32_t t = twin_[prev(HalfedgeId(h)).idx()];
            if (t == kNone) break;
            if (t == h0) {
                closed = true;
                break;
            }
            h = t;
            ++count;
        }
        if (!closed) {
            h = h0;
            while (count <= corners_at[v] && twin_[h] != kNone) {
                h = next(HalfedgeId(twin_[h])).idx();
                ++count;
            }
        }
        if (count != corners_at[v]) fail("I5 vertex " + std::to_string(v) + " is not a single fan");
    }
}

}  // namespace singlestrip
