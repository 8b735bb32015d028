// singlestrip — matching engine: loops and paths labelled, loops joined by flipping alternating
// cycles, then the joins (path ends for free, loops by one midpoint split each); where one loop
// is cut at a single pin.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "matching_builder.hpp"

namespace singlestrip::matching {

// Loops and paths: components of the crossed edges, the virtual face joining the pinned faces.
// Structures are numbered by their lowest face, as a search from each unlabelled face in index
// order would number them; the faces are read in index order (a union-find whose root is the
// lowest face), not along the loops, which on a large mesh jump across memory at every step
// (10M faces: 3.1x the time per face of 100K when walked).
void MatchingBuilder::label_structures() {
    const uint32_t nf = mesh_.num_faces();
    // First a parent per face (a face index, stored as a StructId), root = lowest face.
    sid_.assign(nf, kNone);
    for (FaceId f : mesh_.faces()) sid_[f] = StructId(f.idx());
    auto root = [&](uint32_t x) {  // path halving: a parent never exceeds its child
        for (;;) {
            const uint32_t p = sid_[FaceId(x)].idx();
            if (p == x) return x;
            const uint32_t g = sid_[FaceId(p)].idx();
            sid_[FaceId(x)] = StructId(g);
            x = g;
        }
    };
    auto unite = [&](FaceId a, FaceId b) {
        const uint32_t ra = root(a.idx()), rb = root(b.idx());
        if (ra != rb) sid_[FaceId(std::max(ra, rb))] = StructId(std::min(ra, rb));
    };
    for (FaceId f : mesh_.faces()) {
        for (HalfedgeId h : sides(f))
            if (used_[h] && across(h) > f) unite(f, across(h));
        if (vlink_[f])
            for (uint32_t i = 0; i < num_pins_; ++i) unite(f, pins_[i]);
    }
    // Then, in index order, a face's parent (lower, already labelled) gives its label.
    uf_.clear();
    cycle_.clear();
    pinned_.clear();
    for (FaceId f : mesh_.faces()) {
        const uint32_t p = sid_[f].idx();
        if (p == f.idx()) {
            sid_[f] = StructId(static_cast<uint32_t>(uf_.size()));
            uf_.push_back(sid_[f]);
            cycle_.push_back(1);
            pinned_.push_back(0);
        } else {
            sid_[f] = sid_[FaceId(p)];
        }
        const StructId id = sid_[f];
        if (hdeg(f) < 2) cycle_[id] = 0;
        if (vlink_[f]) pinned_[id] = 1;
    }
    for (StructId s : IdRange<StructId>(static_cast<uint32_t>(uf_.size())))
        if (pinned_[s] && num_pins_ == 1) cycle_[s] = 0;
    stats_.loops = static_cast<uint32_t>(uf_.size());
}

// Walking loop from face `from` away from face `back`: true if `good` comes before `bad`
// (within a bound; false past it).
bool MatchingBuilder::meets_first(FaceId from, FaceId back, FaceId good, FaceId bad) const {
    FaceId prev = back, cur = from;
    for (uint32_t step = 0; step < 256; ++step) {
        if (cur == good) return true;
        if (cur == bad) return false;
        FaceId next = kNone;
        for (HalfedgeId h : sides(cur))
            if (used_[h] && across(h) != prev) next = across(h);
        if (next == kNone) return false;
        prev = cur;
        cur = next;
    }
    return false;
}

// An alternating cycle: crossed and matched edges in turn, each face on it once. Swapping crossed
// and matched edges along it keeps one matched edge per face. Each loop it crosses opens at its
// crossed edge and the new edges link the openings in turn, so loops met once are all joined into
// one. A loop met twice, at crossed edges p then q (tail t, head h), stays joined only if its arc
// from h_p away from t_p reaches h_q before t_q (else it splits off again): checked by walking
// it. Depth-first from f1 through at most kMaxLoops crossed edges, at most one loop met twice.
// Every face of a cycle starts it (each way round), so a whole-mesh pass may start only at the
// lower face of each matched pair (`one_end`): half the searches, for the same cycles.
bool MatchingBuilder::flip_alternating(FaceId f1, bool one_end) {
    constexpr uint32_t kMaxLoops = 4;
    if (vlink_[f1]) return false;
    HalfedgeId m1 = kNone;  // f1's matched edge closes the cycle
    for (HalfedgeId h : sides(f1))
        if (matched_[h]) m1 = h;
    if (m1 == kNone) return false;
    const FaceId close_face = across(m1);
    if (one_end && close_face < f1) return false;
    const StructId close_root = find(sid_[close_face]);
    if (close_root == find(sid_[f1])) return false;  // cheap filter: rarely joins loops
    // The last face before close_face is one of its crossed neighbours: the last depth is only
    // entered there.
    FaceId last[2] = {kNone, kNone};
    for (uint32_t k = 0, n = 0; k < 3; ++k)
        if (const HalfedgeId h = Mesh::halfedge(close_face, k); used_[h]) last[n++ & 1] = across(h);
    // Faces from which the depth before the last can still close: a face of last[], or a crossed
    // neighbour of a face matched to one.
    FaceId before_last[6] = {last[0], last[1], kNone, kNone, kNone, kNone};
    for (uint32_t i = 0, n = 2; i < 2; ++i) {
        if (last[i] == kNone) continue;
        HalfedgeId m = kNone;
        for (HalfedgeId e : sides(last[i]))
            if (matched_[e]) m = e;
        if (m == kNone) continue;
        const FaceId g = across(m);
        for (HalfedgeId e : sides(g))
            if (used_[e] && n < 6) before_last[n++] = across(e);
    }
    auto may_close = [&](FaceId next, uint32_t next_depth) {
        if (next_depth + 1 == kMaxLoops) return next == last[0] || next == last[1];
        if (next_depth + 2 == kMaxLoops) return std::find(std::begin(before_last), std::end(before_last), next) != std::end(before_last);
        return true;
    };
    HalfedgeId path[2 * kMaxLoops];  // crossed edge, then matched edge, in turn
    StructId roots[kMaxLoops];
    bool repeated = false;  // a loop met twice, at the crossed edges of depths rep_p and rep_q
    uint32_t rep_p = 0, rep_q = 0;
    auto faces_distinct = [&](uint32_t depth) {
        FaceId faces[2 * kMaxLoops];
        for (uint32_t i = 0; i <= depth; ++i) faces[2 * i] = Mesh::face(path[2 * i]), faces[2 * i + 1] = across(path[2 * i]);
        for (uint32_t i = 0; i < 2 * depth + 2; ++i)
            for (uint32_t j = 0; j < i; ++j)
                if (faces[i] == faces[j]) return false;
        return true;
    };
    auto closes_one_loop = [&](uint32_t depth) {
        if (!repeated) return true;
        if (!faces_distinct(depth)) return false;
        const HalfedgeId up = path[2 * rep_p], uq = path[2 * rep_q];
        return meets_first(across(up), Mesh::face(up), across(uq), Mesh::face(uq));
    };
    // Returns true once a cycle is flipped. `f` is the face at which a crossed edge is taken.
    auto search = [&](auto&& self, FaceId f, uint32_t depth) -> bool {
        const StructId r = find(sid_[f]);
        if (!cycle_[r] || pinned_[r] || vlink_[f]) return false;
        // Crossed edges stay in their loop: at the last depth only close_face's loop can close.
        if (depth + 1 == kMaxLoops && r != close_root) return false;
        bool repeat = false;
        for (uint32_t i = 0; i < depth; ++i)
            if (roots[i] == r) {
                if (repeated) return false;
                rep_p = i, rep_q = depth, repeat = repeated = true;
            }
        roots[depth] = r;
        bool found = false;
        for (uint32_t k = 0; k < 3 && !found; ++k) {
            const HalfedgeId h = Mesh::halfedge(f, k);
            if (!used_[h]) continue;
            const FaceId g = across(h);
            HalfedgeId m = kNone;
            for (HalfedgeId e : sides(g))
                if (matched_[e]) m = e;
            if (m == kNone || vlink_[g]) continue;
            path[2 * depth] = h;
            path[2 * depth + 1] = m;
            if (g == close_face && mesh_.twin(m) == m1 && depth > 0 && closes_one_loop(depth)) {
                for (uint32_t i = 0; i <= 2 * depth + 1; ++i) {
                    set_pair(used_, path[i], !used_[path[i]]);
                    set_pair(matched_, path[i], !matched_[path[i]]);
                    flipped_faces_.push_back(Mesh::face(path[i]));
                }
                for (uint32_t i = 1; i <= depth; ++i) uf_[find(roots[i])] = find(roots[0]);
                found = true;
            } else if (depth + 1 < kMaxLoops && g != close_face) {
                const FaceId next = across(m);
                if (may_close(next, depth + 1)) found = self(self, next, depth + 1);
            }
        }
        if (repeat) repeated = false;
        return found;
    };
    return search(search, f1, 0);
}

// Fewer loops before any split: flip alternating cycles that join loops.
// A flip can enable another, near the faces it changed: later passes look only there (on the
// libcgal-demo meshes, whole-mesh passes after the first never found one).
void MatchingBuilder::reduce_loops() {
    IdVector<FaceId, uint32_t> stamp(mesh_.num_faces(), 0);
    std::vector<FaceId> todo;
    flipped_faces_.clear();
    for (FaceId f : mesh_.faces()) stats_.ring_flips += flip_alternating(f, true);
    for (uint32_t pass = 1; pass < 4 && !flipped_faces_.empty(); ++pass) {
        todo.clear();
        for (FaceId f : flipped_faces_)
            for (HalfedgeId h : sides(f))
                for (FaceId g : {f, mesh_.is_boundary(h) ? f : across(h)})
                    if (stamp[g] != pass) stamp[g] = pass, todo.push_back(g);
        flipped_faces_.clear();
        for (FaceId f : todo) stats_.ring_flips += flip_alternating(f, false);
    }
}

// Loop or path b joins a across h (now crossed): the union's root is a.
void MatchingBuilder::join(HalfedgeId h, StructId a, StructId b, bool cycle, bool pinned) {
    set_pair(used_, h, 1);
    uf_[b] = a;
    cycle_[a] = cycle;
    pinned_[a] = pinned;
}

// Path end across h joins loop a for free: the loop opens at h's face (one crossed edge dropped).
void MatchingBuilder::rotate_into(HalfedgeId h, StructId a, StructId b) {
    for (HalfedgeId e : sides(Mesh::face(h)))
        if (used_[e]) {
            set_pair(used_, e, 0);
            break;
        }
    join(h, a, b, false, pinned_[b]);
}

// Loop a (h's face f crosses its two other edges) joins b (g = the face across h) by one
// midpoint split of h: f_a-g_a and f_b-g_b become crossed, f's and g's outer edges stay as they
// were. A loop joined to a loop stays a loop; to a path (g inside, at an end, or alone), a path.
void MatchingBuilder::merge_by_split(HalfedgeId h, StructId a, StructId b) {
    const HalfedgeId t = mesh_.twin(h);
    split(h);
    set_pair(used_, h, 1);  // f_a - g_a
    set_pair(used_, t, 1);  // g_b - f_b
    uf_[b] = a;
    cycle_[a] = cycle_[b];
    pinned_[a] = pinned_[a] || pinned_[b];
}

bool MatchingBuilder::try_merge(HalfedgeId h, bool allow_split) {
    const FaceId f = Mesh::face(h), g = across(h);
    const StructId a = find(sid_[f]), b = find(sid_[g]);
    const bool fe = hdeg(f) < 2, ge = hdeg(g) < 2;
    if (a == b) {
        if (cycle_[a] || !fe || !ge || f == g) return false;
        set_pair(used_, h, 1);  // a path whose two ends touch closes into a loop
        cycle_[a] = 1;
        return true;
    }
    if (fe && ge) return join(h, a, b, false, pinned_[a] || pinned_[b]), true;
    if (cycle_[a] && !pinned_[a] && ge) return rotate_into(h, a, b), true;
    if (cycle_[b] && !pinned_[b] && fe) return rotate_into(mesh_.twin(h), b, a), true;
    if (!allow_split || vlink_[f] || vlink_[g]) return false;
    if (cycle_[a] && !(pinned_[a] && !cycle_[b])) return merge_by_split(h, a, b), true;
    if (cycle_[b] && !(pinned_[b] && !cycle_[a])) return merge_by_split(mesh_.twin(h), b, a), true;
    return false;
}

// Swaps a split join of h adds. Each child pivots on its endpoint of h, so both cross edges swap
// and each crossed outer edge of f and g changes state: 2 + 4 - 2 * (outer swaps), -2 to 6.
int MatchingBuilder::split_join_cost(HalfedgeId h) const {
    const HalfedgeId t = mesh_.twin(h);
    int cost = 2;
    for (HalfedgeId e : {Mesh::next(h), Mesh::prev(h), Mesh::next(t), Mesh::prev(t)})
        if (used_[e] && hdeg(Mesh::face(e)) == 2 && hdeg(across(e)) == 2) cost += 1 - 2 * swap_at(e);
    return cost;
}

// Split joins cheapest first (Kruskal over the loops, costs from split_join_cost, kept current
// lazily): on a regular grid every split in the pattern costs 6 swaps, one where the pattern
// already breaks costs less.
void MatchingBuilder::merge_by_cost() {
    constexpr int kLow = -2, kBuckets = 9;
    std::vector<HalfedgeId> bucket[kBuckets];
    auto candidate = [&](HalfedgeId h) {
        if (!passable(h) || used_[h]) return false;
        const FaceId f = Mesh::face(h), g = across(h);
        const StructId a = find(sid_[f]), b = find(sid_[g]);
        return a != b && (cycle_[a] || cycle_[b]) && !vlink_[f] && !vlink_[g];
    };
    for (HalfedgeId h : mesh_.halfedges())
        if (h < mesh_.twin(h) && candidate(h)) bucket[split_join_cost(h) - kLow].push_back(h);
    for (int i = 0; i < kBuckets; ++i)
        while (!bucket[i].empty()) {
            const HalfedgeId h = bucket[i].back();
            bucket[i].pop_back();
            if (!candidate(h)) continue;
            const int c = split_join_cost(h) - kLow;
            if (c > i) {
                bucket[c].push_back(h);
                continue;
            }
            try_merge(h, true);
        }
}

// Free joins first (path ends, path ends into loops), then splits (cheapest first), then any
// join left (the pass that guarantees one strip), then free joins again.
// With one structure left only a path's own ends pass the test below (closing it), so a pass
// looks at them alone, and no split join is left to rank: same joins, without three scans of
// every edge (the 1M sphere after the path growth took all its loops in).
void MatchingBuilder::merge_all() {
    for (bool allow_split : {false, true, false}) {
        const bool one = num_structures() == 1;
        if (allow_split && !one) merge_by_cost();
        for (uint32_t fi = 0; fi < mesh_.num_faces(); ++fi) {  // a join may split: faces are added
            const FaceId f(fi);
            if (one && hdeg(f) == 2) continue;
            for (uint32_t k = 0; k < 3;) {
                const HalfedgeId h = Mesh::halfedge(f, k);
                const bool skip =
                    !passable(h) || used_[h] || (find(sid_[f]) == find(sid_[across(h)]) && (cycle_[find(sid_[f])] || hdeg(f) == 2));
                k = !skip && try_merge(h, allow_split) ? 0 : k + 1;  // f's edges changed: look at all three again
            }
        }
    }
}

uint32_t MatchingBuilder::num_structures() {
    uint32_t roots = 0;
    for (StructId s : IdRange<StructId>(static_cast<uint32_t>(uf_.size()))) roots += find(s) == s;
    return roots;
}

bool MatchingBuilder::single_strip_ready() {
    if (num_structures() != 1) return false;
    return num_pins_ != 2 || cycle_[find(StructId(0))];  // one structure: every id leads to its root
}

// Loop mode: where the loop is cut, a face of the pin (the seed face, else a face at the source
// or target vertex; reversed_ turns a target's walk round).
FaceId MatchingBuilder::loop_start() const {
    const std::optional<VertexId> v = opt_.source ? opt_.source : opt_.target;
    if (loop_pin_ != kNone && (!v || face_has_vertex(mesh_, loop_pin_, *v))) return loop_pin_;
    return face_at_vertex(mesh_, blocked_, *v, kNone);  // the seed face was split away from it
}

}  // namespace singlestrip::matching
