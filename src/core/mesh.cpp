// singlestrip — mesh core: corner table construction, midpoint split, topology queries.
#include "singlestrip/mesh.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "singlestrip/errors.hpp"

namespace singlestrip {

Mesh Mesh::from_soup(const TriangleSoup& soup) {
    Mesh m;
    const size_t nf = soup.triangles.size();
    if (nf >= kNone / 3) throw InputError("mesh has too many faces (" + std::to_string(nf) + ")");
    m.points_ = soup.points;
    m.num_input_vertices_ = static_cast<uint32_t>(soup.points.size());
    m.num_input_faces_ = static_cast<uint32_t>(nf);
    m.corner_vertex_.resize(3 * nf);
    m.twin_.assign(3 * nf, kNone);
    m.face_parent_.resize(nf);
    std::iota(m.face_parent_.begin(), m.face_parent_.end(), 0u);
    for (size_t f = 0; f < nf; ++f) {
        const Triangle& t = soup.triangles[f];
        for (int k = 0; k < 3; ++k) {
            if (t[k] >= soup.points.size())
                throw InputError("face " + std::to_string(f) + " references vertex " + std::to_string(t[k]) +
                                 " but there are only " + std::to_string(soup.points.size()) + " vertices");
            m.corner_vertex_[3 * f + k] = t[k];
        }
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
            throw InputError("face " + std::to_string(f) + " repeats a vertex");
    }
    // Pair half-edges: bucket them by their smaller endpoint (counting sort, O(V + F)), then
    // sort each bucket by the larger endpoint (buckets hold a vertex's few edges).
    const uint32_t nh = static_cast<uint32_t>(3 * nf);
    const size_t nv = m.points_.size();
    std::vector<uint32_t> start(nv + 1, 0);
    for (uint32_t h = 0; h < nh; ++h) ++start[std::min(m.from(h), m.to(h)) + 1];
    for (size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
    std::vector<uint32_t> order(nh);
    {
        std::vector<uint32_t> fill(start.begin(), start.end() - 1);
        for (uint32_t h = 0; h < nh; ++h) order[fill[std::min(m.from(h), m.to(h))]++] = h;
    }
    auto other = [&](uint32_t h) { return std::max(m.from(h), m.to(h)); };
    for (size_t v = 0; v < nv; ++v) {
        const auto first = order.begin() + start[v], last = order.begin() + start[v + 1];
        std::sort(first, last, [&](uint32_t x, uint32_t y) {
            const uint32_t ox = other(x), oy = other(y);
            return ox != oy ? ox < oy : x < y;
        });
    }
    for (uint32_t i = 0; i < nh;) {
        const uint32_t h0 = order[i];
        const uint32_t lo = std::min(m.from(h0), m.to(h0)), hi = other(h0);
        uint32_t j = i + 1;
        while (j < nh && other(order[j]) == hi && std::min(m.from(order[j]), m.to(order[j])) == lo) ++j;
        if (j - i > 2)
            throw InputError("edge (" + std::to_string(m.from(h0)) + ", " + std::to_string(m.to(h0)) + ") has " +
                             std::to_string(j - i) + " faces (non-manifold edge)");
        if (j - i == 2) {
            const uint32_t h1 = order[i + 1];
            if (m.from(h0) == m.from(h1))
                throw InputError("faces " + std::to_string(face(h0)) + " and " + std::to_string(face(h1)) +
                                 " traverse edge (" + std::to_string(m.from(h0)) + ", " + std::to_string(m.to(h0)) +
                                 ") in the same direction (inconsistent orientation)");
            m.twin_[h0] = h1;
            m.twin_[h1] = h0;
        }
        i = j;
    }
    // One outgoing half-edge per vertex; a boundary vertex gets its boundary half-edge, so the
    // rotation h -> twin(prev(h)) from it sees the whole fan.
    m.vertex_halfedge_.assign(m.points_.size(), kNone);
    for (uint32_t h = 0; h < nh; ++h) {
        uint32_t& vh = m.vertex_halfedge_[m.from(h)];
        if (vh == kNone || m.twin_[h] == kNone) vh = h;
    }
    // Vertex manifoldness: each vertex's fan must contain all its corners.
    std::vector<uint32_t> corners_at(m.points_.size(), 0);
    for (uint32_t h = 0; h < nh; ++h) ++corners_at[m.from(h)];
    for (uint32_t v = 0; v < m.points_.size(); ++v) {
        const uint32_t h0 = m.vertex_halfedge_[v];
        if (h0 == kNone) continue;
        uint32_t count = 0;
        uint32_t h = h0;
        do {
            ++count;
            const uint32_t t = m.twin_[prev(h)];
            if (t == kNone) break;
            h = t;
        } while (h != h0 && count <= corners_at[v]);
        if (count != corners_at[v])
            throw InputError("vertex " + std::to_string(v) + " is non-manifold (" + std::to_string(corners_at[v]) +
                             " faces in more than one fan)");
    }
    return m;
}

uint32_t Mesh::shared_halfedge(uint32_t f, uint32_t g) const noexcept {
    for (uint32_t k = 0; k < 3; ++k) {
        const uint32_t h = 3 * f + k;
        if (twin_[h] != kNone && twin_[h] / 3 == g) return h;
    }
    return kNone;
}

SplitResult Mesh::split_edge(uint32_t h) {
    if (h >= twin_.size() || twin_[h] == kNone)
        throw InternalError("split_edge: half-edge " + std::to_string(h) + " is not an interior edge");
    const uint32_t t = twin_[h];
    const uint32_t f = face(h), g = face(t);
    const uint32_t a = from(h), b = to(h), c = opposite(h), d = opposite(t);
    const uint32_t hn = next(h);  // b->c in f (prev(h), c->a, stays)
    const uint32_t tn = next(t);  // a->d in g (prev(t), d->b, stays)
    const uint32_t twin_bc = twin_[hn], twin_ad = twin_[tn];

    const auto& pa = points_[a];
    const auto& pb = points_[b];
    const uint32_t mid = static_cast<uint32_t>(points_.size());
    points_.push_back({(pa[0] + pb[0]) * 0.5, (pa[1] + pb[1]) * 0.5, (pa[2] + pb[2]) * 0.5});
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
    return SplitResult{mid, f, fb, ga, g};
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
    std::vector<char> seen(twin_.size(), 0);
    uint32_t loops = 0;
    for (uint32_t h0 = 0; h0 < twin_.size(); ++h0) {
        if (twin_[h0] != kNone || seen[h0]) continue;
        ++loops;
        uint32_t h = h0;
        while (!seen[h]) {
            seen[h] = 1;
            uint32_t n = next(h);
            while (twin_[n] != kNone) n = next(twin_[n]);
            h = n;
        }
    }
    return loops;
}

std::vector<uint32_t> Mesh::component_of_faces() const {
    std::vector<uint32_t> comp(num_faces(), kNone);
    std::vector<uint32_t> stack;
    uint32_t id = 0;
    for (uint32_t f0 = 0; f0 < num_faces(); ++f0) {
        if (comp[f0] != kNone) continue;
        comp[f0] = id;
        stack.push_back(f0);
        while (!stack.empty()) {
            const uint32_t f = stack.back();
            stack.pop_back();
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t g = neighbor(3 * f + k);
                if (g != kNone && comp[g] == kNone) {
                    comp[g] = id;
                    stack.push_back(g);
                }
            }
        }
        ++id;
    }
    return comp;
}

uint32_t Mesh::num_components() const {
    const auto comp = component_of_faces();
    uint32_t n = 0;
    for (uint32_t c : comp) n = std::max(n, c + 1);
    return n;
}

long long Mesh::euler_characteristic() const {
    return static_cast<long long>(num_referenced_vertices()) - num_edges() + num_faces();
}

long long Mesh::genus() const {
    return (2 - euler_characteristic() - static_cast<long long>(num_boundary_loops())) / 2;
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
        if (t >= twin_.size() || twin_[t] != h || face(t) == face(h) || from(t) != to(h) || to(t) != from(h))
            fail("I3 half-edge " + std::to_string(h) + " twin");
    }
    for (uint32_t v = 0; v < points_.size(); ++v) {
        const uint32_t h0 = vertex_halfedge_[v];
        if (h0 == kNone) {
            if (corners_at[v] != 0) fail("I4 vertex " + std::to_string(v) + " has faces but no half-edge");
            continue;
        }
        if (h0 >= twin_.size() || from(h0) != v) fail("I4 vertex " + std::to_string(v) + " half-edge");
        // Walk both ways around v; together the walks must see every corner exactly once.
        uint32_t count = 1;
        uint32_t h = h0;
        bool closed = false;
        while (count <= corners_at[v]) {
            const uint32_t t = twin_[prev(h)];
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
                h = next(twin_[h]);
                ++count;
            }
        }
        if (count != corners_at[v]) fail("I5 vertex " + std::to_string(v) + " is not a single fan");
    }
}

}  // namespace singlestrip
