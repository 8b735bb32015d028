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
std::vector<uint32_t> pieces(const Mesh& mesh, const EdgeFlags& blocked) {
    IdVector<FaceId, uint8_t> seen(mesh.num_faces(), 0);
    std::vector<uint32_t> sizes;
    std::vector<FaceId> stack;
    for (const FaceId f0 : mesh.faces()) {
        if (seen[f0]) continue;
        sizes.push_back(0);
        seen[f0] = 1;
        stack.assign(1, f0);
        while (!stack.empty()) {
            const FaceId f = stack.back();
            stack.pop_back();
            ++sizes.back();
            for (const HalfedgeId h : sides(f)) {
                const FaceId g = mesh.neighbor(h);
                if (g == kNone || blocked[h] || seen[g]) continue;
                seen[g] = 1;
                stack.push_back(g);
            }
        }
    }
    return sizes;
}

void check_vertex(const Mesh& mesh, const char* what, VertexId v) {
    if (v.idx() >= mesh.num_input_vertices())
        throw RequestError(std::string(what) + " vertex " + std::to_string(v.idx()) + " is out of range (mesh has " +
                           std::to_string(mesh.num_input_vertices()) + " vertices)");
    if (mesh.vertex_halfedge(v) == kNone)
        throw RequestError(std::string(what) + " vertex " + std::to_string(v.idx()) + " is not used by any face");
}

}  // namespace

void check_strip_request(const Mesh& mesh, const StripOptions& opt) {
    const uint32_t nf = mesh.num_faces();
    if (nf == 0) throw InputError("mesh has no faces");
    if (opt.seed_face && opt.seed_face->idx() >= nf)
        throw RequestError("seed face " + std::to_string(opt.seed_face->idx()) + " is out of range (mesh has " + std::to_string(nf) +
                           " faces)");
    if (opt.source) check_vertex(mesh, "source", *opt.source);
    if (opt.target) check_vertex(mesh, "target", *opt.target);
    if (opt.seed_face && opt.source && !face_has_vertex(mesh, *opt.seed_face, *opt.source))
        throw RequestError("seed face " + std::to_string(opt.seed_face->idx()) + " is not incident to source vertex " +
                           std::to_string(opt.source->idx()));
}

HalfedgeId find_halfedge(const Mesh& mesh, VertexId u, VertexId v) {
    if (u.idx() >= mesh.num_vertices() || v.idx() >= mesh.num_vertices()) return kNone;
    HalfedgeId found = kNone;
    for_each_outgoing(mesh, u, [&](HalfedgeId h) {
        if (mesh.to(h) == v)
            found = h;
        else if (mesh.from(Mesh::prev(h)) == v)
            found = Mesh::prev(h);
        return found != kNone;
    });
    return found;
}

EdgeFlags constraint_halfedges(const Mesh& mesh, const StripOptions& opt) {
    EdgeFlags blocked(mesh.num_halfedges(), 0);
    size_t index = 0;
    for (const ConstraintEdge& e : opt.constraint_edges) {
        const HalfedgeId h = find_halfedge(mesh, VertexId(e.a), VertexId(e.b));
        if (h == kNone)
            throw RequestError("constraint " + std::to_string(index) + ": (" + std::to_string(e.a) + ", " + std::to_string(e.b) +
                               ") is not an edge of the mesh");
        blocked[h] = 1;
        if (!mesh.is_boundary(h)) blocked[mesh.twin(h)] = 1;
        ++index;
    }
    if (opt.constraint_edges.empty()) return blocked;
    const std::vector<uint32_t> sizes = pieces(mesh, blocked);
    if (sizes.size() > 1)
        throw RequestError("the constraint edges cut the surface into " + std::to_string(sizes.size()) + " pieces (faces per piece: " +
                           piece_sizes(sizes) + "); one strip cannot cover them without crossing a constraint");
    return blocked;
}

FaceId face_at_vertex(const Mesh& mesh, const EdgeFlags& blocked, VertexId v, FaceId avoid) {
    FaceId best = kNone;
    int best_score = -1;
    for_each_outgoing(mesh, v, [&](HalfedgeId h) {
        const FaceId f = Mesh::face(h);
        int score = 0;
        for (const HalfedgeId e : sides(f)) score += mesh.is_boundary(e) || blocked[e];
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
