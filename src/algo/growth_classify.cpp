// singlestrip — the growth builder's classification of the next face as safe, bridge or
// fundamental: the O(1) cavity test first, a bidirectional search only when it cannot tell.
#include <cstdint>
#include <string>

#include "growth_builder.hpp"
#include "singlestrip/errors.hpp"

namespace singlestrip::growth {

// Local cavity test (paper Fig. 6): a and b (N's open neighbours across ha and hb) stay connected
// without N if the faces around the vertex V shared by ha and hb lead from a to b, away from N,
// through open faces of r and passable edges. That path is every face and edge around V but N
// and its two edges, so it exists exactly when V is not on the rim (no boundary or constraint
// edge at V) and no face around V is striped: the unstriped faces around V are then connected
// to N, hence in N's region (a region is a connected piece of the unstriped faces). O(1), any
// valence. (A walk around V cost O(valence) per test: quadratic on a cone's apex; a walk capped at
// 4096 steps answered "not connected" wrongly and a closed cone failed with "fundamental
// triangle in a region without cycles".)
bool Builder::fan_connects(FaceId n, HalfedgeId ha, HalfedgeId hb, RegionId r) const {
    const VertexId v = mesh_.from(ha) == mesh_.to(hb) ? mesh_.from(ha) : mesh_.to(ha);
    // a shares both its edges at V with N: N closes the fan, the path would go through N.
    const bool connects = mesh_.neighbor(ha) != mesh_.neighbor(hb) && !rim_[v] && striped_at_[v] == 0;
    if (opt_.validate_each_split && connects != fan_connects_walk(n, ha, hb, r))
        throw InternalError("strip builder: cavity test disagrees with the walk around vertex " + std::to_string(v.idx()));
    return connects;
}

// The same test by walking around V (O(valence)); a cross-check in tests (validate_each_split).
bool Builder::fan_connects_walk(FaceId n, HalfedgeId ha, HalfedgeId hb, RegionId r) const {
    const VertexId v = mesh_.from(ha) == mesh_.to(hb) ? mesh_.from(ha) : mesh_.to(ha);
    const FaceId b = mesh_.neighbor(hb);
    HalfedgeId g = mesh_.twin(ha);  // in face a, incident to v
    for (uint32_t guard = 0; guard <= mesh_.num_halfedges(); ++guard) {
        const HalfedgeId other = mesh_.from(g) == v ? Mesh::prev(g) : Mesh::next(g);
        if (!passable(other)) return false;
        g = mesh_.twin(other);
        const FaceId f = Mesh::face(g);
        if (f == b) return true;
        if (f == n || !in_region(f, r)) return false;
    }
    return false;
}

// Alternating search from a and from b through open faces of r, never entering n.
// Met if they meet (connected), else the side that ran out first (IslandOfA or IslandOfB); that
// side's faces are then in side_[0] or side_[1]. Cost O(size of the smaller island) when they are
// separated. When they are not, the sides may meet only after going around the whole region (a
// disk with a hole every ten faces: O(F) per fundamental triangle, quadratic in all), so two walks
// along the rim run beside them: removing n cuts the region along an arc from its third edge to
// its vertex between a and b, and an arc between two different rim loops never separates a
// surface. A loop that closes without meeting the other end proves Met in its own length. Not in
// the first, short searches of choose_safe(): there a candidate they cannot settle gives way to
// the next one, as before the walks (the libcgal-demo strips stay as they were; preferring the
// far-connected candidate cost the growth builder up to +3 points of extra triangles).
Builder::SearchOutcome Builder::bidirectional_search(FaceId n, HalfedgeId ha, HalfedgeId hb, RegionId r, size_t budget, bool rims) {
    const FaceId a = mesh_.neighbor(ha), b = mesh_.neighbor(hb);
    stamp_base_ += 2;
    if (stamp_base_ >= 0xfffffff0u) {
        stamp_.assign(stamp_.size(), 0);
        stamp_base_ = 2;
    }
    const uint32_t mark[2] = {stamp_base_, stamp_base_ + 1};
    size_t popped = 0;
    for (int s = 0; s < 2; ++s) {
        side_[s].clear();
        stack_[s].clear();
    }
    side_[0].push_back(a);
    side_[1].push_back(b);
    stack_[0].push_back(a);
    stack_[1].push_back(b);
    stamp_[a] = mark[0];
    stamp_[b] = mark[1];
    stamp_[n] = mark[0];  // never enter n (both sides treat it as foreign but not as a meeting)
    // The rim walks: from n's third edge hc, and from vertex v's fan around n (see rims_differ()).
    const VertexId v = mesh_.from(ha) == mesh_.to(hb) ? mesh_.from(ha) : mesh_.to(ha);
    HalfedgeId hc = kNone;
    for (const HalfedgeId h : sides(n))
        if (h != ha && h != hb) hc = h;
    RimWalk walk[2];
    if (rims && budget > kFirstBudget && a != b && open_neighbor(hc, r) == kNone) {
        walk[0] = RimWalk{hc, hc, kNone, true};
        walk[1] = RimWalk{kNone, kNone, mesh_.from(ha) == v ? ha : hb, true};
    }
    for (;;) {
        if (popped > budget) {
            stamp_[n] = 0;
            return SearchOutcome::OverBudget;
        }
        if (rims_differ(walk, n, v, hc, r)) {
            stamp_[n] = 0;
            if (opt_.validate_each_split && bidirectional_search(n, ha, hb, r, SIZE_MAX, false) != SearchOutcome::Met)
                throw InternalError("strip builder: the rim walks found two loops at face " + std::to_string(n.idx()) +
                                    " but removing it separates its region");
            return SearchOutcome::Met;
        }
        for (int s = 0; s < 2; ++s) {
            if (stack_[s].empty()) {
                stamp_[n] = 0;
                return s == 0 ? SearchOutcome::IslandOfA : SearchOutcome::IslandOfB;
            }
            const FaceId f = stack_[s].back();
            stack_[s].pop_back();
            ++popped;
            for (const HalfedgeId h : sides(f)) {
                const FaceId g = open_neighbor(h, r);
                if (g == kNone || g == n) continue;
                if (stamp_[g] == mark[s]) continue;
                if (stamp_[g] == mark[1 - s]) {
                    stamp_[n] = 0;
                    return SearchOutcome::Met;
                }
                stamp_[g] = mark[s];
                side_[s].push_back(g);
                stack_[s].push_back(g);
            }
        }
    }
}

bool Builder::rim_step(RimWalk& w, RegionId r) const {
    w.rot = w.rot == kNone ? Mesh::next(w.at) : Mesh::next(mesh_.twin(w.rot));
    if (open_neighbor(w.rot, r) != kNone) return false;
    w.at = w.rot;
    w.rot = kNone;
    return true;
}

// One step of each walk still on. walk[0] follows the loop through hc from hc: it meets v's end
// of the arc when its rotation around v passes through n. walk[1] first rotates around v from n
// to a rim half-edge (back at n: v's fan is closed, a and b meet around it), then follows that
// loop: it meets the other end when it reaches hc. A walk that meets the other end stops (one
// loop: the search decides); one that closes first proves two loops.
bool Builder::rims_differ(RimWalk (&w)[2], FaceId n, VertexId v, HalfedgeId hc, RegionId r) const {
    if (w[0].on) {
        const bool reached = rim_step(w[0], r);
        if (!reached && Mesh::face(w[0].rot) == n && mesh_.from(w[0].rot) == v) w[0].on = false;
        if (reached && w[0].at == w[0].start) return true;
    }
    if (w[1].on) {
        if (w[1].start == kNone) {  // rotating around v to its fan's rim
            w[1].rot = Mesh::next(mesh_.twin(w[1].rot));
            if (Mesh::face(w[1].rot) == n) return true;
            if (open_neighbor(w[1].rot, r) == kNone) w[1].start = w[1].at = w[1].rot, w[1].rot = kNone;
        } else if (rim_step(w[1], r)) {
            if (w[1].at == hc) w[1].on = false;
            if (w[1].at == w[1].start) return true;
        }
    }
    return false;
}

// Cheap part of the classification: open neighbours, then the local cavity test. In a region
// without cycles (beta 0, a disk) a failed cavity test proves a bridge without any search.
Builder::Classification Builder::classify_local(FaceId n, FaceId from, RegionId r) const {
    Classification c;
    for (const HalfedgeId h : sides(n)) {
        const FaceId g = open_neighbor(h, r);
        if (g == kNone || g == from) continue;
        if (c.a == kNone) {
            c.a = g;
            c.ha = h;
        } else {
            c.b = g;
            c.hb = h;
        }
    }
    if (c.b == kNone) return c;  // at most one open neighbour: removing n keeps R connected
    if (fan_connects(n, c.ha, c.hb, r)) return c;
    c.kind = region_beta_[r] <= 0 ? Kind::Bridge : Kind::Unknown;
    return c;
}

// Expensive part: the bidirectional search decides Unknown, and finds the smaller island of a
// bridge (left in side_[c.small_side]); call it right before taking a bridge. With a budget
// (faces visited) it may return false: still Unknown.
bool Builder::resolve(Classification& c, FaceId n, RegionId r, size_t budget) {
    if (c.kind == Kind::Safe || (c.kind == Kind::Bridge && c.small_side != kNone && searched_ == n)) return true;
    const SearchOutcome s = bidirectional_search(n, c.ha, c.hb, r, budget);
    searched_ = n;
    if (s == SearchOutcome::OverBudget) return false;
    if (s == SearchOutcome::Met) {
        // A split candidate that is not a bridge (§3.1). Impossible in a disk.
        if (region_beta_[r] <= 0)
            throw InternalError("strip builder: fundamental triangle in a region without cycles (topology tracking broken)");
        c.kind = Kind::Safe;
        c.fundamental = true;
        return true;
    }
    c.kind = Kind::Bridge;
    c.small_side = s == SearchOutcome::IslandOfA ? 0 : 1;
    return true;
}

}  // namespace singlestrip::growth
