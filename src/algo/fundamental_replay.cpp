// singlestrip — fundamental triangles of any strip order, found by replaying it (§3.1, §4).
//
// The growth builder knows its fundamental triangles because it tracks the Betti number of the
// unstriped region as it goes. Any other strip order (the matching engine's) gets them here:
// the unstriped region before position i is the suffix U_i = faces at positions >= i, and the
// face at position i is fundamental when beta1(U_{i+1}) < beta1(U_i). Adding the faces back in
// reverse strip order makes every step a local update (derivation in cycles.hpp).
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "core/face_sides.hpp"
#include "core/id_vector.hpp"
#include "singlestrip/cycles.hpp"
#include "singlestrip/errors.hpp"
#include "union_find.hpp"

namespace singlestrip {

namespace {

/// Per vertex: how many faces it has and whether it lies on the mesh boundary; with the count of
/// its faces already in the region this tells whether a face closes the vertex's fan.
struct VertexFans {
    IdVector<VertexId, uint32_t> valence, in_region;
    IdVector<VertexId, uint8_t> on_boundary;
    explicit VertexFans(const Mesh& mesh)
        : valence(mesh.num_vertices(), 0), in_region(mesh.num_vertices(), 0), on_boundary(mesh.num_vertices(), 0) {
        for (const HalfedgeId h : mesh.halfedges()) {
            ++valence[mesh.from(h)];
            if (mesh.is_boundary(h)) on_boundary[mesh.from(h)] = on_boundary[mesh.to(h)] = 1;
        }
    }
};

/// beta1 gained by adding face t to the region `in` (then the caller adds it). Vertices count
/// once per fan piece, so a vertex whose two edges in t are both shared loses a piece (two
/// pieces merge) unless t closes its fan (then it stays one piece, now interior).
long long beta1_gain(const Mesh& mesh, FaceId t, const IdVector<FaceId, uint8_t>& in, UnionFind& sets, const VertexFans& fans) {
    bool shared[3];
    uint32_t roots[3];
    int s = 0, components = 0;
    for (uint32_t k = 0; k < 3; ++k) {
        const FaceId g = mesh.neighbor(Mesh::halfedge(t, k));
        shared[k] = g.valid() && in[g];
        if (!shared[k]) continue;
        ++s;
        const uint32_t r = sets.find(g.idx());
        bool seen = false;
        for (int c = 0; c < components; ++c) seen = seen || roots[c] == r;
        if (!seen) roots[components++] = r;
    }
    long long dchi = 1 - (3 - s);  // the face and its new edges
    for (uint32_t k = 0; k < 3; ++k) {
        const VertexId v = mesh.from(Mesh::halfedge(t, k));
        const int at_v = shared[k] + shared[(k + 2) % 3];  // half-edges k and prev(k) touch v
        const bool closes_fan = !fans.on_boundary[v] && fans.in_region[v] + 1 == fans.valence[v];
        if (at_v == 0) dchi += 1;                 // a new piece
        if (at_v == 2 && !closes_fan) dchi -= 1;  // two pieces merge
    }
    const long long db0 = 1 - components;
    return db0 - dchi;
}

}  // namespace

std::vector<uint32_t> replay_fundamental_positions(const Mesh& mesh, const std::vector<uint32_t>& order) {
    const uint32_t nf = mesh.num_faces();
    if (order.size() != nf) throw InternalError("fundamental replay: strip order does not cover the mesh");
    IdVector<FaceId, uint8_t> in(nf, 0);
    UnionFind sets(nf);
    VertexFans fans(mesh);
    const bool closed = mesh.num_boundary_edges() == 0;
    std::vector<uint32_t> found;  // positions, largest first
    for (uint32_t i = nf; i-- > 0;) {
        const FaceId t(order[i]);
        if (t.idx() >= nf || in[t]) throw InternalError("fundamental replay: strip order is not a permutation");
        long long gain = beta1_gain(mesh, t, in, sets, fans);
        if (i == 0 && closed) gain += 1;  // the last face closes the surface: beta2 becomes 1
        for (long long c = 0; c < gain; ++c) found.push_back(i);
        in[t] = 1;
        for (const HalfedgeId h : sides(t)) {
            ++fans.in_region[mesh.from(h)];
            const FaceId g = mesh.neighbor(h);
            if (g.valid() && in[g]) sets.unite(t.idx(), g.idx());
        }
    }
    return {found.rbegin(), found.rend()};
}

}  // namespace singlestrip
