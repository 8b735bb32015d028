// singlestrip — matching engine: ears and bridges of the dual graph, split before the matching.
//
// A strip crosses a bridge of the dual graph (an edge whose removal cuts the faces in two) once
// unless it is split, so any single strip splits every bridge off the path between its ends;
// an ear's one passable edge is such a bridge. docs/algorithm.md, "The matching engine", steps 3-4.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "matching_builder.hpp"

namespace singlestrip::matching {

// A face with one passable edge (an ear) can only end a strip. Unless it is a pinned face, it is
// split with its neighbour g (+2 faces, even for the two ears a strip could end in: an end that
// is not where the loops close blocks joins). The ear's children
// and g's form a ring of four faces entered and left through g's other two edges, so g's
// children are matched to each other (when g had three passable edges).
void MatchingBuilder::split_ears() {
    std::vector<FaceId> ears;
    for (FaceId f : mesh_.faces())
        if (degree(f) == 1) ears.push_back(f);
    if (mesh_.num_faces() <= 2) return;
    mesh_.reserve_splits(static_cast<uint32_t>(ears.size()));  // one allocation, not a doubling per 1.5x
    for (FaceId f : ears) {
        if (f == pins_[0] || f == pins_[1] || degree(f) != 1) continue;
        HalfedgeId h = Mesh::halfedge(f, 0);
        while (!passable(h)) h = Mesh::next(h);
        const FaceId g = across(h);
        if (degree(g) == 1) continue;  // two faces only: an ear pair is a strip already
        const HalfedgeId tn = Mesh::next(mesh_.twin(h));
        const SplitResult sr = split(h);
        ++ear_splits_;
        const HalfedgeId inner = tn;  // after the split: g_b's half-edge towards g_a
        if (degree(sr.g_a) == 3 && degree(sr.g_b) == 3 && num_matched(sr.g_a) == 0 && num_matched(sr.g_b) == 0)
            set_pair(matched_, inner, 1);
    }
}

// Passable edges whose removal disconnects the faces (bridges of the dual graph), by an
// iterative lowpoint search that keeps no stack (parent edges lead back up, next_side says where
// a face's scan resumes: 21 bytes a face; a stack of frames was the engine's memory peak on long
// dual paths). Also counts every bridge and the most of them one path of faces crosses: the
// diameter of the tree of 2-edge-connected pieces, a longest path of the search tree counting
// its bridges (the tree less its bridges spans each piece), from the deepest bridge count below
// each face (`down`). A strip crosses such an edge exactly once, so the two sides must each
// be covered by a path ending at it; split, the edge becomes two crossings (the four children
// form a ring across it), which removes that parity constraint: a serpentine corridor of odd
// length between walls has no 2-factor until its one-edge gaps are split.
MatchingBuilder::DualBridges MatchingBuilder::dual_bridges() const {
    if (!may_have_bridges()) return {};
    const uint32_t nf = mesh_.num_faces();
    constexpr uint32_t kUnseen = 0;  // order is 1-based
    IdVector<FaceId, uint32_t> order(nf, kUnseen), low(nf, 0), size(nf, 1), down(nf, 0);
    IdVector<FaceId, HalfedgeId> parent_edge(nf, kNone);
    IdVector<FaceId, uint8_t> next_side(nf, 0);
    DualBridges b;
    uint32_t time = 1;
    for (FaceId r : mesh_.faces()) {
        if (order[r] != kUnseen) continue;
        order[r] = low[r] = time++;
        for (FaceId f = r;;) {
            if (next_side[f] < 3) {
                const HalfedgeId h = Mesh::halfedge(f, next_side[f]++);
                if (!passable(h) || mesh_.twin(h) == parent_edge[f]) continue;
                const FaceId g = across(h);
                if (order[g] == kUnseen) {
                    order[g] = low[g] = time++;
                    parent_edge[g] = h;
                    f = g;
                } else {
                    low[f] = std::min(low[f], order[g]);
                }
                continue;
            }
            if (parent_edge[f] == kNone) break;
            const FaceId p = Mesh::face(parent_edge[f]);
            low[p] = std::min(low[p], low[f]);
            size[p] += size[f];
            const bool bridge = low[f] > order[p];
            b.all += bridge;
            const uint32_t reach = down[f] + bridge;
            b.on_one_path = std::max(b.on_one_path, down[p] + reach);
            down[p] = std::max(down[p], reach);
            // A small side (a spike, a pendant ring) is better joined as a loop later.
            if (bridge && std::min(size[f], nf - size[f]) >= kMinBridgeSide) b.to_split.push_back(parent_edge[f]);
            f = p;
        }
    }
    return b;
}

// Closed and unconstrained, every vertex has a whole ring of faces, a dual cycle through each
// edge at it: no bridge, and no ear.
bool MatchingBuilder::may_have_bridges() const {
    return stats_.boundary_loops != 0 || !opt_.constraint_edges.empty();
}

// Walks from face f away from face `from` through faces with two passable edges; true if it
// reaches a face with three (a branch) within a bound.
bool MatchingBuilder::chain_reaches_branch(FaceId f, FaceId from) const {
    for (uint32_t step = 0; step < 64; ++step) {
        if (degree(f) == 3) return true;
        if (degree(f) != 2) return false;
        FaceId next = kNone;
        for (HalfedgeId h : sides(f))
            if (passable(h) && across(h) != from) next = across(h);
        if (next == kNone) return false;
        from = f;
        f = next;
    }
    return false;
}

// Bridges on a chain that joins two branching faces are split; a chain ending in an ear or a
// boundary (a fan, a strip of faces) is a strip already and is left alone. The splits any single
// strip of the input needs: the ears split (each a bridge off any path but at its two ends) and
// the bridges left off the longest path through them.
void MatchingBuilder::split_bridges() {
    const DualBridges b = dual_bridges();
    const uint64_t bridges = uint64_t{ear_splits_} + b.all;
    forced_splits_ = static_cast<uint32_t>(bridges - std::min<uint64_t>(bridges, uint64_t{b.on_one_path} + 2));
    for (HalfedgeId h : b.to_split) {
        const FaceId f = Mesh::face(h), g = across(h);
        if (f == pins_[0] || f == pins_[1] || g == pins_[0] || g == pins_[1]) continue;
        if (chain_reaches_branch(f, g) && chain_reaches_branch(g, f)) split(h);
    }
}

}  // namespace singlestrip::matching
