// singlestrip — matching engine: loops taken into one growing path for free, before any split
// (rotation-extension, Pósa 1976). A path end next to a loop opens the loop there and continues
// round it; a path end next to a face x inside the path links to x and drops x's link towards the
// end, so the part between turns round and x's old neighbour becomes the end. Rotations are
// searched at random from the ends and kept only when they lead to a loop taken in for fewer GL
// indices than its split would cost. Only loops are handled (no pins, no other paths); what is
// left is joined by merge_all().
#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <vector>

#include "matching_builder.hpp"
#include "path_order.hpp"

namespace singlestrip::matching {

// Swaps at the crossed edges of the given faces (each edge counted once).
int MatchingBuilder::swaps_around(std::initializer_list<FaceId> faces) const {
    HalfedgeId seen[9];
    uint32_t n = 0;
    int sum = 0;
    for (FaceId f : faces)
        for (HalfedgeId h : sides(f)) {
            if (!used_[h]) continue;
            const HalfedgeId key = std::min(h, mesh_.twin(h));
            if (std::find(seen, seen + n, key) != seen + n) continue;
            seen[n++] = key;
            sum += swap_at(h);
        }
    return sum;
}

class PathGrower {
public:
    PathGrower(MatchingBuilder& b, uint32_t loops) : b_(b), loops_(loops), walk_budget_(b.mesh_.num_faces()) {}
    void run(StructId path_root);

private:
    struct Take {
        HalfedgeId link = kNone, cut = kNone;  ///< link: a free edge of the end; cut: a link of the loop
        int cost = 0;                          ///< swaps added
    };
    struct Rotation {
        uint32_t side;
        HalfedgeId link, dropped;
        uint32_t from;
    };
    // A split join adds two triangles (two GL indices) and often swaps around its four faces: a
    // loop is taken in while the turns changed cost fewer than 5 swaps (the best of 2, 3, 4, 5 and
    // unbounded on the libcgal-demo meshes; docs/algorithm.md).
    static constexpr int kSplitCost = 5;
    static constexpr uint64_t kWindow = 4096;  ///< rotations without a loop taken in, then stop
    static constexpr uint32_t kNoOrder = ~0u;  ///< Rotation::from of a rotation made before the order

    MatchingBuilder& b_;
    // Built at the first rotation: until then the path only grows at its ends, and the ends are
    // all a take needs (on closed meshes most loops go in that way, with no order kept at all).
    std::optional<PathOrder> path_;
    uint32_t loops_;               ///< loops not yet in the path
    StructId root_;                ///< the path's structure
    FaceId ends_[2];               ///< front, back
    std::vector<Rotation> trial_;  ///< rotations since the last loop taken in
    int trial_cost_ = 0;           ///< swaps they added
    uint64_t walk_budget_;         ///< steps towards_end() may still take: about one build of the order

    void start(StructId path_root);
    [[nodiscard]] Take best_take(uint32_t side);
    void take(uint32_t side, const Take& t);
    bool rotate(uint32_t side, HalfedgeId h);  ///< false if h led to the end's own neighbour
    void reverse(uint32_t side, uint32_t from) { side ? path_->reverse_back(from) : path_->reverse_front(from); }
    PathOrder& order();
    struct PathWalk {
        const MatchingBuilder& b;
        FaceId f;
        HalfedgeId in;
        FaceId operator()();
    };
    [[nodiscard]] PathWalk path_from(FaceId end) const;
    void undo_trial();
    bool take_all();
    [[nodiscard]] FaceId towards_end(uint32_t side, FaceId x);
};

// The path starts as the one path there is, else as the first loop cut open at its first
// crossed edge.
void PathGrower::start(StructId path_root) {
    const Mesh& mesh = b_.mesh_;
    if (path_root != kNone) {
        FaceId end = kNone;
        for (FaceId f : mesh.faces())
            if (b_.find(b_.sid_[f]) == path_root && b_.hdeg(f) < 2) {
                end = f;
                break;
            }
        root_ = path_root;
        ends_[0] = end;
        ends_[1] = end;
        auto walk = path_from(end);
        for (FaceId f = walk(); f != kNone; f = walk()) ends_[1] = f;
        return;
    }
    HalfedgeId cut = kNone;
    for (HalfedgeId h : mesh.halfedges())
        if (b_.used_[h]) {
            cut = h;
            break;
        }
    root_ = b_.find(b_.sid_[Mesh::face(cut)]);
    b_.set_pair(b_.used_, cut, 0);
    b_.cycle_[root_] = 0;
    ends_[0] = Mesh::face(cut);
    ends_[1] = b_.across(cut);
    --loops_;
}

// The faces of the path from `end` (a face with at most one crossed edge) along crossed edges,
// one per call, then kNone.
auto PathGrower::path_from(FaceId end) const -> PathWalk {
    return PathWalk{b_, end, kNone};
}

FaceId PathGrower::PathWalk::operator()() {
    const FaceId at = f;
    if (at == kNone) return at;
    const HalfedgeId out = b.next_crossed(at, in);
    if (out == kNone) {
        f = FaceId(kNone);
    } else {
        in = b.mesh_.twin(out), f = Mesh::face(in);
    }
    return at;
}

// The path's order, walked from ends_[0] along the crossed edges the first time it is needed.
PathOrder& PathGrower::order() {
    if (!path_) {
        path_.emplace(b_.mesh_.num_faces());
        // Walked straight into the order: the path as a vector first was 4 bytes a face at the
        // engine's memory peak (a 4M-face disk with holes: 16 MB of 331).
        (void)path_->append_from(path_from(ends_[0]));
    }
    return *path_;
}

// The cheapest way to take a loop in at ends_[side]: link into its face g, cut one of g's links.
PathGrower::Take PathGrower::best_take(uint32_t side) {
    Take best;
    const FaceId e = ends_[side];
    for (HalfedgeId h : sides(e)) {
        if (!b_.passable(h) || b_.used_[h]) continue;
        const FaceId g = b_.across(h);
        const StructId r = b_.find(b_.sid_[g]);
        if (r == root_ || !b_.cycle_[r] || b_.pinned_[r]) continue;
        for (HalfedgeId gc : sides(g)) {
            if (!b_.used_[gc]) continue;
            const FaceId c = b_.across(gc);
            const int before = b_.swaps_around({e, g, c});
            b_.set_pair(b_.used_, gc, 0), b_.set_pair(b_.used_, h, 1);
            const int cost = b_.swaps_around({e, g, c}) - before;
            b_.set_pair(b_.used_, gc, 1), b_.set_pair(b_.used_, h, 0);
            if (best.link == kNone || cost < best.cost) best = {h, gc, cost};
        }
    }
    return best;
}

void PathGrower::take(uint32_t side, const Take& t) {
    // The loop goes in as it is walked, before its crossed edges change.
    if (path_)
        ends_[side] = side ? path_->append_from(b_.loop_from(t.cut)) : path_->prepend_from(b_.loop_from(t.cut));
    else
        ends_[side] = b_.across(t.cut);  // the loop is walked from cut's face round to this one
    b_.uf_[b_.find(b_.sid_[Mesh::face(t.cut)])] = root_;
    b_.set_pair(b_.used_, t.cut, 0);
    b_.set_pair(b_.used_, t.link, 1);
    --loops_;
    ++b_.stats_.absorbed;
    trial_.clear();
    trial_cost_ = 0;
}

// Which of x's path neighbours lies towards ends_[side] (the new end after a rotation there):
// walks from x both ways at once, so it costs the distance to the nearer end. kNone once the
// walks have cost as much as building the order would (then the order answers).
FaceId PathGrower::towards_end(uint32_t side, FaceId x) {
    HalfedgeId in[2] = {kNone, kNone};
    FaceId first[2] = {kNone, kNone};
    uint32_t k = 0;
    for (HalfedgeId h : sides(x))
        if (b_.used_[h]) in[k] = b_.mesh_.twin(h), first[k++] = b_.across(h);
    if (k < 2) return first[0];  // x is the other end
    for (;;)
        for (uint32_t d = 0; d < 2; ++d) {
            const FaceId f = Mesh::face(in[d]);
            if (f == ends_[side]) return first[d];
            if (--walk_budget_ == 0) return kNone;
            const HalfedgeId out = b_.next_crossed(f, in[d]);
            if (out == kNone) return first[1 - d];  // this way ends at the other end
            in[d] = b_.mesh_.twin(out);
        }
}

// h: a free edge of ends_[side] into face x of the path. Before the order is built, the face
// that becomes the end is found by walking (rotations near the ends are the common ones).
bool PathGrower::rotate(uint32_t side, HalfedgeId h) {
    const FaceId e = ends_[side], x = b_.across(h);
    for (HalfedgeId k : sides(e))
        if (b_.used_[k] && b_.across(k) == x) return false;  // x is the end's own neighbour
    FaceId y = walk_budget_ == 0 ? kNone : towards_end(side, x);
    uint32_t from = kNoOrder;
    if (y == kNone) {
        PathOrder& path = order();
        const uint32_t px = path.position(x);
        from = side ? px + 1 : px;
        y = path.at(side ? px + 1 : px - 1);
    }
    HalfedgeId xy = kNone;
    for (HalfedgeId k : sides(x))
        if (b_.used_[k] && b_.across(k) == y) xy = k;
    const int before = b_.swaps_around({e, x, y});
    b_.set_pair(b_.used_, xy, 0);
    b_.set_pair(b_.used_, h, 1);
    trial_cost_ += b_.swaps_around({e, x, y}) - before;
    if (from != kNoOrder) reverse(side, from);
    trial_.push_back({side, h, xy, from});
    ends_[side] = y;
    return true;
}

// A rotation keeps its pivot x where it was and reverses the part beyond it, so undoing one
// made before the order was built reverses that part again, found from x's position (the
// order, built after it, holds the rotated path; the later rotations are undone first).
void PathGrower::undo_trial() {
    for (size_t i = trial_.size(); i-- > 0;) {
        const Rotation& r = trial_[i];
        if (r.from != kNoOrder) {
            reverse(r.side, r.from);
        } else if (path_) {
            const uint32_t px = path_->position(b_.across(r.link));
            reverse(r.side, r.side ? px + 1 : px);
        }
        b_.set_pair(b_.used_, r.link, 0);
        b_.set_pair(b_.used_, r.dropped, 1);
        ends_[r.side] = Mesh::face(r.link);
    }
    trial_.clear();
    trial_cost_ = 0;
}

// Every loop worth taking in at either end; true if one was.
bool PathGrower::take_all() {
    bool took = false;
    for (uint32_t side = 0; side < 2; ++side)
        for (Take t; (t = best_take(side)).link != kNone && trial_cost_ + t.cost < kSplitCost;) take(side, t), took = true;
    return took;
}

void PathGrower::run(StructId path_root) {
    start(path_root);
    const uint32_t nf = b_.mesh_.num_faces();
    uint64_t rng = 0x9e3779b97f4a7c15ULL, budget = 16ULL * nf, idle = 0;  // xorshift: reproducible
    bool moved = true;                                                    // the ends changed since take_all() last found nothing
    while (loops_ > 0 && budget > 0 && idle < kWindow) {
        if (moved && take_all()) {
            idle = 0;
            continue;
        }
        moved = false;
        rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
        const uint32_t side = rng & 1, k = static_cast<uint32_t>((rng >> 1) % 3);
        const HalfedgeId h = Mesh::halfedge(ends_[side], k);
        --budget, ++idle;
        if (b_.passable(h) && !b_.used_[h] && b_.find(b_.sid_[b_.across(h)]) == root_) moved |= rotate(side, h);
        if (trial_cost_ >= kSplitCost + 6) undo_trial(), moved = true;  // too far from the pattern: back to the last take
    }
    undo_trial();
}

void MatchingBuilder::absorb_loops() {
    if (!ends_free() || mesh_.num_faces() < 2) return;  // a loop is to be cut at a pin
    uint32_t loops = 0;
    StructId path = kNone;
    for (StructId s : IdRange<StructId>(static_cast<uint32_t>(uf_.size()))) {
        if (find(s) != s) continue;
        if (cycle_[s]) {
            ++loops;
        } else {
            if (path != kNone) return;  // two paths could only be joined end to end
            path = s;
        }
    }
    if (loops >= (path == kNone ? 2 : 1)) PathGrower(*this, loops).run(path);
}

}  // namespace singlestrip::matching
