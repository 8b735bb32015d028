// singlestrip — request checks and constraint edges shared by the strip engines.
#include "strip_controls.hpp"

#include <algorithm>
#include <string>

#include "singlestrip/errors.hpp"

namespace singlestrip {

namespace {

// Calls fn(h) for every half-edge h leaving v until fn returns true. Rotates both ways from v's
// half-edge (the fan may be open); no cap on the degree.
template <class Fn>
void for_each_outgoing(const Mesh& mesh, VertexId v, Fn&& fn) {
    const HalfedgeId h0 = mesh.vertex_halfedge(v);
    if (h0 == kNone) return;
    HalfedgeId h = h0;
    for (uint32_t guard = 0; guard <= mesh.num_halfedges(); ++guard) {
        if (fn(h)) return;
        const HalfedgeId t = mesh.twin(Mesh::prev(h));
        if (t == kNone) break;
        if (t == h0) return;  // closed fan: every half-edge seen
        h = t;
    }
    h = h0;
    for (uint32_t guard = 0; guard <= mesh.num_halfedges(); ++guard) {
        const HalfedgeId t = mesh.twin(h);
        if (t == kNone) return;
        h = Mesh::next(t);
        if (h == h0 || fn(h)) return;
    }
}

std::string piece_sizes(std::vector<uint32_t> sizes) {
    std::sort(sizes.rbegin(), sizes.rend());
    std::string list;
    for (size_t i = 0; i < sizes.size() && i < 10; ++i) list += (i ? ", " : "") + std::to_string(sizes[i]);
    if (sizes.size() > 10) list += ", ...";
    return list;
}

// Sizes of the face pieces connected through interior edges that are not blocked.
std::vector<uint32_t> pieces(const Mesh& mesh, const std::vector<uint8_t>& blocked) {
    const uint32_t nf = mesh.num_faces();
    std::vector<uint8_t> seen(nf, 0);
    std::vector<uint32_t> sizes, stack;
    for (uint32_t f0 = 0; f0 < nf; ++f0) {
        if (seen[f0]) continue;
        sizes.push_back(0);
        seen[f0] = 1;
        stack.assign(1, f0);
        while (!stack.empty()) {
            const FaceId f(stack.back());
            stack.pop_back();
            ++sizes.back();
            for (uint32_t k = 0; k < 3; ++k) {
                const HalfedgeId h = Mesh::halfedge(f, k);
                const FaceId g = mesh.neighbor(h);
                if (g == kNone || blocked[h.idx()] || seen[g.idx()]) continue;
                seen[g.idx()] = 1;
                stack.push_back(g.idx());
            }
        }
    }
    return sizes;
}

void check_vertex(const Mesh& mesh, const char* what, uint32_t v) {
    if (v >= mesh.num_input_vertices())
        throw RequestError(std::string(what) + " vertex " + std::to_string(v) + " is out of range (mesh has " +
                           std::to_string(mesh.num_input_vertices()) + " vertices)");
    if (mesh.vertex_halfedge(VertexId(v)) == kNone)
        throw RequestError(std::string(what) + " vertex " + std::to_string(v) + " is not used by any face");
}

}  // namespace

void check_strip_request(const Mesh& mesh, const StripOptions& opt) {
    const uint32_t nf = mesh.num_faces();
    if (nf == 0) throw InputError("mesh has no faces");
    if (opt.seed_face && opt.seed_face->idx() >= nf)
        throw RequestError("seed face " + std::to_string(opt.seed_face->idx()) + " is out of range (mesh has " + std::to_string(nf) +
                           " faces)");
    if (opt.source) check_vertex(mesh, "source", opt.source->idx());
    if (opt.target) check_vertex(mesh, "target", opt.target->idx());
    if (opt.seed_face && opt.source && !face_has_vertex(mesh, opt.seed_face->idx(), opt.source->idx()))
        throw RequestError("seed face " + std::to_string(opt.seed_face->idx()) + " is not incident to source vertex " +
                           std::to_string(opt.source->idx()));
}

uint32_t find_halfedge(const Mesh& mesh, uint32_t u, uint32_t v) {
    if (u >= mesh.num_vertices() || v >= mesh.num_vertices()) return kNone;
    HalfedgeId found = kNone;
    for_each_outgoing(mesh, VertexId(u), [&](HalfedgeId h) {
        if (mesh.to(h) == VertexId(v))
            found = h;
        else if (mesh.from(Mesh::prev(h)) == VertexId(v))
            found = Mesh::prev(h);
        return found != kNone;
    });
    return found.idx();
}

std::vector<uint8_t> constraint_halfedges(const Mesh& mesh, const StripOptions& opt) {
    std::vector<uint8_t> blocked(mesh.num_halfedges(), 0);
    size_t index = 0;
    for (const ConstraintEdge& e : opt.constraint_edges) {
        const uint32_t h = find_halfedge(mesh, e.a, e.b);
        if (h == kNone)
            throw RequestError("constraint " + std::to_string(index) + ": (" + std::to_string(e.a) + ", " + std::to_string(e.b) +
                               ") is not an edge of the mesh");
        blocked[h] = 1;
        if (!mesh.is_boundary(HalfedgeId(h))) blocked[mesh.twin(HalfedgeId(h)).idx()] = 1;
        ++index;
    }
    if (opt.constraint_edges.empty()) return blocked;
    const std::vector<uint32_t> sizes = pieces(mesh, blocked);
    if (sizes.size() > 1)
        throw RequestError("the constraint edges cut the surface into " + std::to_string(sizes.size()) + " pieces (faces per piece: " +
                           piece_sizes(sizes) + "); one strip cannot cover them without crossing a constraint");
    return blocked;
}

uint32_t face_at_vertex(const Mesh& mesh, const std::vector<uint8_t>& blocked, uint32_t v, uint32_t avoid) {
    uint32_t best = kNone;
    int best_score = -1;
    for_each_outgoing(mesh, VertexId(v), [&](HalfedgeId h) {
        const uint32_t f = Mesh::face(h).idx();
        int score = 0;
        for (uint32_t k = 3 * f; k < 3 * f + 3; ++k) score += mesh.is_boundary(HalfedgeId(k)) || blocked[k];
        if (f == avoid) score = -1;
        if (score > best_score || best == kNone) {
            best_score = score;
            best = f;
        }
        return false;
    });
    return best;
}

uint32_t count_swaps(const Mesh& mesh, const std::vector<uint32_t>& order) {
    uint32_t swaps = 0;
    int prev_turn = 0;
    for (size_t i = 1; i + 1 < order.size(); ++i) {
        const HalfedgeId hin = mesh.shared_halfedge(FaceId(order[i]), FaceId(order[i - 1]));
        const HalfedgeId hout = mesh.shared_halfedge(FaceId(order[i]), FaceId(order[i + 1]));
        if (hin == kNone || hout == kNone) throw InternalError("strip: consecutive faces do not share an edge");
        const int turn = hout == Mesh::next(hin) ? +1 : -1;
        if (turn == prev_turn) ++swaps;
        prev_turn = turn;
    }
    return swaps;
}

}  // namespace singlestrip
