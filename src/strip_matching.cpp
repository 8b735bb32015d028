// singlestrip — matching engine: one strip from a 2-factor of the dual graph.
//
// Gopi & Eppstein, "Single-Strip Triangulation of Manifolds with Arbitrary Topology" (2004), and
// Diaz-Gutierrez, Eppstein & Gopi, "Single Triangle Strip and Loop on Manifolds with Boundaries"
// (2006). Every face keeps one passable edge the strip does not cross (its *matched* edge, paired
// with the neighbour's), so the crossed (*used*) edges form loops and paths; loops are joined by one
// midpoint split each, path ends for free where they touch. Design, the argument that it ends in
// one strip, and what it costs: docs/algorithm.md, "The matching engine".
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/max_cardinality_matching.hpp>

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "path_order.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/strip.hpp"
#include "strip_controls.hpp"

namespace singlestrip {

namespace {

class MatchingBuilder {
public:
    MatchingBuilder(Mesh mesh, const StripOptions& options) : mesh_(std::move(mesh)), opt_(options) {}
    StripResult run();

private:
    Mesh mesh_;
    const StripOptions& opt_;
    // Per half-edge, symmetric across twins (a half-edge and its twin always agree).
    std::vector<uint8_t> blocked_;  ///< constraint edge: never crossed
    std::vector<uint8_t> matched_;  ///< passable edge not crossed, paired by the matching
    std::vector<uint8_t> used_;     ///< crossed by the strip (an edge of the loops and paths)
    // Per face.
    std::vector<uint8_t> vlink_;  ///< linked to the virtual face (a pinned end)
    std::vector<uint8_t> quota_;  ///< matched edges still wanted
    std::vector<uint32_t> sid_;   ///< structure (loop or path) id, through uf_
    // Per structure id.
    std::vector<uint32_t> uf_;           ///< union-find parent
    std::vector<uint8_t> cycle_;         ///< at a root: the structure is a loop (no free end)
    std::vector<uint8_t> pinned_;        ///< at a root: holds the virtual face
    uint32_t pins_[2] = {kNone, kNone};  ///< source face (or seed) and target face
    uint32_t num_pins_ = 0;
    bool reversed_ = false;  ///< only a target: the walk starts there and is reversed
    StripStats stats_;
    std::vector<Triangle> input_faces_;  ///< the input, to rebuild it if the split budget runs out
    std::optional<Mesh> pre_merge_;      ///< the mesh before the joins, kept when paths remain
    uint32_t pre_merge_splits_ = 0;
    // Augmenting search, per face: the outer face it was reached from and the two edges used.
    std::vector<uint32_t> aug_prev_, aug_matched_, aug_unmatched_, aug_queue_;

    [[nodiscard]] bool passable(uint32_t h) const { return !mesh_.is_boundary(h) && !blocked_[h]; }
    [[nodiscard]] uint32_t degree(uint32_t f) const { return passable(3 * f) + passable(3 * f + 1) + passable(3 * f + 2); }
    /// Links of f in the loops-and-paths graph, the virtual face included.
    [[nodiscard]] uint32_t hdeg(uint32_t f) const { return used_[3 * f] + used_[3 * f + 1] + used_[3 * f + 2] + vlink_[f]; }
    void set_pair(std::vector<uint8_t>& a, uint32_t h, uint8_t value) {
        a[h] = value;
        a[mesh_.twin(h)] = value;
    }
    uint32_t find(uint32_t s) {
        while (uf_[s] != s) s = uf_[s] = uf_[uf_[s]];
        return s;
    }

    void choose_pins();
    SplitResult split(uint32_t h);
    void split_ears();
    void set_quotas();
    std::vector<uint32_t> dual_bridges() const;
    static constexpr uint32_t kMinBridgeSide = 16;
    void split_bridges();
    bool chain_reaches_branch(uint32_t f, uint32_t from) const;
    void match_patterned();
    bool augment_from(uint32_t u, std::vector<uint32_t>& stamp, uint32_t mark, size_t budget);
    void settle_leftovers();
    void repair_short(std::vector<uint32_t>& short_faces);
    bool split_beside(uint32_t u);
    bool repair_in_balls(std::vector<uint32_t>& short_faces, size_t ball);
    bool repair_ball(const std::vector<uint32_t>& short_faces, size_t ball);
    static constexpr size_t kBallOneByOne = 8192;
    std::vector<uint32_t> ball_local_;
    void label_structures();
    void merge_all();
    void reduce_loops();
    void absorb_loops();
    std::vector<uint32_t> loop_from(uint32_t cut) const;
    int swap_at(uint32_t h) const;
    int swaps_around(std::initializer_list<uint32_t> faces) const;
    bool flip_alternating(uint32_t f1);
    bool meets_first(uint32_t from, uint32_t back, uint32_t good, uint32_t bad) const;
    bool try_merge(uint32_t h, bool allow_split);
    void join(uint32_t h, uint32_t a, uint32_t b, bool cycle, bool pinned);
    void rotate_into(uint32_t h, uint32_t a, uint32_t b);
    void merge_by_split(uint32_t h, uint32_t a, uint32_t b);
    bool single_strip_ready();
    std::vector<uint32_t> walk() const;
    StripResult finish(std::vector<uint32_t> order);
    StripResult fallback();
    Mesh input_mesh() const;
};

// Pinned faces: the strip starts at pins_[0] and ends at pins_[1] (either may be absent).
void MatchingBuilder::choose_pins() {
    const uint32_t nf = mesh_.num_faces();
    uint32_t first = kNone, last = kNone;
    if (opt_.seed_face)
        first = *opt_.seed_face;
    else if (opt_.source)
        first = face_at_vertex(mesh_, blocked_, *opt_.source, kNone);
    if (opt_.target && nf > 1) {
        last = face_at_vertex(mesh_, blocked_, *opt_.target, first);
        if (last == first) {
            // The target's only face is the first face: split it across the edge opposite the
            // target so that both children touch it; start in one, end in the other.
            uint32_t h = 3 * first;
            while (mesh_.from(h) == *opt_.target || mesh_.to(h) == *opt_.target) ++h;
            if (!passable(h))
                throw RequestError("cannot end at target vertex " + std::to_string(*opt_.target) +
                                   ": its only face is the first face of the strip and cannot be split");
            const SplitResult sr = split(h);
            const bool a_first = !opt_.source || face_has_vertex(mesh_, sr.f_a, *opt_.source);
            first = a_first ? sr.f_a : sr.f_b;
            last = a_first ? sr.f_b : sr.f_a;
        }
    }
    if (first != kNone) pins_[num_pins_++] = first;
    if (last != kNone) pins_[num_pins_++] = last;
    reversed_ = first == kNone && last != kNone;  // target only: walk from it, then reverse
}

// Splits the interior edge of h; per-half-edge flags follow the two half-edges that move, the
// four new inner edges start clear. Pins keep their vertex.
SplitResult MatchingBuilder::split(uint32_t h) {
    const uint32_t t = mesh_.twin(h), hn = Mesh::next(h), tn = Mesh::next(t);
    const uint32_t pin_vertex[2] = {opt_.source ? *opt_.source : kNone, opt_.target ? *opt_.target : kNone};
    const SplitResult sr = mesh_.split_edge(h);
    ++stats_.splits;
    const uint32_t fb0 = 3 * sr.f_b, ga0 = 3 * sr.g_a;
    for (auto* a : {&blocked_, &matched_, &used_}) {
        a->resize(mesh_.num_halfedges(), 0);
        (*a)[fb0 + 1] = (*a)[hn];
        (*a)[ga0 + 1] = (*a)[tn];
        for (uint32_t x : {h, hn, t, tn, fb0, fb0 + 2, ga0, ga0 + 2}) (*a)[x] = 0;
    }
    vlink_.resize(mesh_.num_faces(), 0);
    quota_.resize(mesh_.num_faces(), 0);
    if (!sid_.empty()) sid_.resize(mesh_.num_faces(), sid_[sr.f_a]), sid_[sr.g_a] = sid_[sr.g_b];
    for (uint32_t i = 0; i < num_pins_; ++i) {
        const uint32_t v = (i == 0 && !reversed_) ? pin_vertex[0] : pin_vertex[1];
        if (v == kNone) continue;
        const uint32_t old = pins_[i];
        if (old == sr.f_a && !face_has_vertex(mesh_, sr.f_a, v))
            pins_[i] = sr.f_b;
        else if (old == sr.g_b && !face_has_vertex(mesh_, sr.g_b, v))
            pins_[i] = sr.g_a;
        if (pins_[i] != old) std::swap(vlink_[old], vlink_[pins_[i]]);  // the virtual link moves along
    }
    return sr;
}

// A face with one passable edge (an ear) can only end a strip. Unless it is a pinned face, it is
// split with its neighbour g (+2 faces, even for the two ears a strip could end in: an end that
// is not where the loops close blocks joins). The ear's children
// and g's form a ring of four faces entered and left through g's other two edges, so g's
// children are matched to each other (when g had three passable edges).
void MatchingBuilder::split_ears() {
    std::vector<uint32_t> ears;
    for (uint32_t f = 0; f < mesh_.num_faces(); ++f)
        if (degree(f) == 1) ears.push_back(f);
    if (mesh_.num_faces() <= 2) return;
    for (uint32_t f : ears) {
        if (f == pins_[0] || f == pins_[1] || degree(f) != 1) continue;
        uint32_t h = 3 * f;
        while (!passable(h)) ++h;
        const uint32_t g = mesh_.neighbor(h);
        if (degree(g) == 1) continue;  // two faces only: an ear pair is a strip already
        const uint32_t tn = Mesh::next(mesh_.twin(h));
        const SplitResult sr = split(h);
        const uint32_t inner = tn;  // after the split: g_b's half-edge towards g_a
        const auto has_match = [&](uint32_t x) { return matched_[3 * x] | matched_[3 * x + 1] | matched_[3 * x + 2]; };
        if (degree(sr.g_a) == 3 && degree(sr.g_b) == 3 && !has_match(sr.g_a) && !has_match(sr.g_b)) set_pair(matched_, inner, 1);
    }
}

// Passable edges whose removal disconnects the faces (bridges of the dual graph), by an
// iterative lowpoint search. A strip crosses such an edge exactly once, so the two sides must each
// be covered by a path ending at it; split, the edge becomes two crossings (the four children
// form a ring across it), which removes that parity constraint: a serpentine corridor of odd
// length between walls has no 2-factor until its one-edge gaps are split.
std::vector<uint32_t> MatchingBuilder::dual_bridges() const {
    const uint32_t nf = mesh_.num_faces();
    std::vector<uint32_t> order(nf, kNone), low(nf, 0), parent_edge(nf, kNone), size(nf, 1), bridges;
    struct Frame {
        uint32_t f, k;
    };
    std::vector<Frame> stack;
    uint32_t time = 0;
    for (uint32_t r = 0; r < nf; ++r) {
        if (order[r] != kNone) continue;
        order[r] = low[r] = time++;
        stack.push_back({r, 0});
        while (!stack.empty()) {
            Frame& fr = stack.back();
            if (fr.k < 3) {
                const uint32_t h = 3 * fr.f + fr.k++;
                if (!passable(h) || mesh_.twin(h) == parent_edge[fr.f]) continue;
                const uint32_t g = mesh_.neighbor(h);
                if (order[g] == kNone) {
                    order[g] = low[g] = time++;
                    parent_edge[g] = h;
                    stack.push_back({g, 0});
                } else {
                    low[fr.f] = std::min(low[fr.f], order[g]);
                }
                continue;
            }
            const uint32_t f = fr.f;
            stack.pop_back();
            if (parent_edge[f] == kNone) continue;
            const uint32_t p = Mesh::face(parent_edge[f]);
            low[p] = std::min(low[p], low[f]);
            size[p] += size[f];
            // A small side (a spike, a pendant ring) is better joined as a loop later.
            if (low[f] > order[p] && std::min(size[f], nf - size[f]) >= kMinBridgeSide) bridges.push_back(parent_edge[f]);
        }
    }
    return bridges;
}

// Walks from face f away from face `from` through faces with two passable edges; true if it
// reaches a face with three (a branch) within a bound.
bool MatchingBuilder::chain_reaches_branch(uint32_t f, uint32_t from) const {
    for (uint32_t step = 0; step < 64; ++step) {
        if (degree(f) == 3) return true;
        if (degree(f) != 2) return false;
        uint32_t next = kNone;
        for (uint32_t h = 3 * f; h < 3 * f + 3; ++h)
            if (passable(h) && mesh_.neighbor(h) != from) next = mesh_.neighbor(h);
        if (next == kNone) return false;
        from = f;
        f = next;
    }
    return false;
}

// Bridges on a chain that joins two branching faces are split; a chain ending in an ear or a
// boundary (a fan, a strip of faces) is a strip already and is left alone.
void MatchingBuilder::split_bridges() {
    for (uint32_t h : dual_bridges()) {
        const uint32_t f = Mesh::face(h), g = mesh_.neighbor(h);
        if (f == pins_[0] || f == pins_[1] || g == pins_[0] || g == pins_[1]) continue;
        if (chain_reaches_branch(f, g) && chain_reaches_branch(g, f)) split(h);
    }
}

// Matched edges wanted per face: passable edges beyond the two the strip crosses (one crossed
// edge for a pinned face, whose other link is the virtual face).
void MatchingBuilder::set_quotas() {
    const uint32_t nf = mesh_.num_faces();
    vlink_.assign(nf, 0);
    for (uint32_t i = 0; i < num_pins_; ++i) vlink_[pins_[i]] = 1;
    if (num_pins_ == 2 && pins_[0] == pins_[1]) throw InternalError("matching engine: source and target faces coincide");
    quota_.assign(nf, 0);
    for (uint32_t f = 0; f < nf; ++f) {
        const int cap = 2 - vlink_[f];
        const int have = matched_[3 * f] + matched_[3 * f + 1] + matched_[3 * f + 2];
        quota_[f] = static_cast<uint8_t>(std::max(0, static_cast<int>(degree(f)) - cap - have));
    }
}

// Greedy matching carried face to face in breadth-first order: across a crossed edge (u, v),
// if this face's matched edge touches u, the neighbour's should touch v — then the two turns
// alternate and the GL strip needs no swap there.
void MatchingBuilder::match_patterned() {
    const uint32_t nf = mesh_.num_faces();
    std::vector<uint32_t> pref(nf, kNone), queue, critical;
    std::vector<uint8_t> seen(nf, 0);
    // Karp-Sipser: a face left with one free neighbour takes it at once, before the pattern
    // asks, so few faces are left short (each costs an augmenting path, which breaks the pattern).
    std::vector<uint8_t> free_n(nf, 0);
    auto wants = [&](uint32_t h) { return passable(h) && !matched_[h] && quota_[mesh_.neighbor(h)] > 0; };
    for (uint32_t f = 0; f < nf; ++f)
        if (quota_[f] > 0)
            for (uint32_t h = 3 * f; h < 3 * f + 3; ++h) free_n[f] += wants(h);
    for (uint32_t f = 0; f < nf; ++f)
        if (quota_[f] > 0 && free_n[f] == 1) critical.push_back(f);
    auto match = [&](uint32_t h) {
        set_pair(matched_, h, 1);
        for (uint32_t x : {Mesh::face(h), mesh_.neighbor(h)}) {
            if (--quota_[x] > 0) continue;
            for (uint32_t e = 3 * x; e < 3 * x + 3; ++e) {
                if (!passable(e)) continue;
                const uint32_t y = mesh_.neighbor(e);
                if (quota_[y] > 0 && free_n[y] > 0 && --free_n[y] == 1) critical.push_back(y);
            }
        }
    };
    auto drain = [&] {
        while (!critical.empty()) {
            const uint32_t x = critical.back();
            critical.pop_back();
            for (uint32_t e = 3 * x; e < 3 * x + 3 && quota_[x] > 0; ++e)
                if (wants(e)) match(e);
        }
    };
    drain();
    queue.reserve(nf);
    for (uint32_t s = 0; s < nf; ++s) {
        if (seen[s]) continue;
        seen[s] = 1;
        queue.assign(1, s);
        for (size_t head = 0; head < queue.size(); ++head) {
            const uint32_t f = queue[head];
            for (uint32_t i = 0; i < 3 && quota_[f] > 0; ++i) {
                const uint32_t h = i == 0 && pref[f] != kNone ? pref[f] : 3 * f + (i + (pref[f] == kNone ? 0 : pref[f] % 3)) % 3;
                if (wants(h)) match(h), drain();
            }
            uint32_t m = kNone;  // the edge this face does not cross
            for (uint32_t k = 0; k < 3; ++k)
                if (matched_[3 * f + k] || !passable(3 * f + k)) m = 3 * f + k;
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t h = 3 * f + k;
                if (!passable(h) || matched_[h]) continue;
                const uint32_t g = mesh_.neighbor(h);
                if (seen[g]) continue;
                seen[g] = 1;
                queue.push_back(g);
                const uint32_t t = mesh_.twin(h);
                if (m == Mesh::prev(h))
                    pref[g] = Mesh::prev(t);  // m touches from(h): g's should touch to(h)
                else if (m == Mesh::next(h))
                    pref[g] = Mesh::next(t);  // and the other way round
            }
        }
    }
}

// Augmenting path from a face still wanting a matched edge to another one: alternately an
// unmatched and a matched passable edge. Faces are visited once (simple paths; blossoms are not
// searched), at most `budget` of them. True if the matching grew.
bool MatchingBuilder::augment_from(uint32_t u, std::vector<uint32_t>& stamp, uint32_t mark, size_t budget) {
    std::vector<uint32_t>& queue = aug_queue_;
    queue.assign(1, u);
    stamp[u] = mark;
    for (size_t head = 0; head < queue.size() && queue.size() < budget; ++head) {
        const uint32_t x = queue[head];
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t h = 3 * x + k;
            if (!passable(h) || matched_[h]) continue;
            const uint32_t y = mesh_.neighbor(h);
            if (stamp[y] == mark) continue;
            stamp[y] = mark;
            if (quota_[y] > 0) {  // flip the path back to u
                set_pair(matched_, h, 1);
                for (uint32_t z = x; z != u; z = aug_prev_[z]) {
                    set_pair(matched_, aug_matched_[z], 0);
                    set_pair(matched_, aug_unmatched_[z], 1);
                }
                --quota_[u];
                --quota_[y];
                return true;
            }
            for (uint32_t j = 0; j < 3; ++j) {
                const uint32_t e = 3 * y + j;
                if (!matched_[e]) continue;
                const uint32_t z = mesh_.neighbor(e);
                if (stamp[z] == mark) continue;
                stamp[z] = mark;
                aug_prev_[z] = x;
                aug_unmatched_[z] = h;
                aug_matched_[z] = e;
                queue.push_back(z);
            }
        }
    }
    return false;
}

/// Initial matching for boost::matching(): the one already in the mate map.
template <typename Graph, typename MateMap>
struct keep_matching {
    static void find_matching(const Graph&, MateMap) {}
};

// Maximum matching (Edmonds' blossoms, Boost.Graph) on the faces within `ball` faces of each
// short face, starting from the current matching; faces matched across the ball's rim stay as
// they are. Where a perfect matching exists (closed surfaces) this finds the alternating paths
// through odd cycles that the plain search misses. True if a ball was cut off by its size (a
// larger one might still help); otherwise the matching is maximum where faces are still short.
bool MatchingBuilder::repair_in_balls(std::vector<uint32_t>& short_faces, size_t ball) {
    bool truncated = false;
    ball_local_.assign(mesh_.num_faces(), kNone);
    if (ball > kBallOneByOne) {  // large balls overlap: one search over their union
        truncated = repair_ball(short_faces, ball);
    } else {
        for (uint32_t s : std::vector<uint32_t>(short_faces))
            if (quota_[s] > 0) truncated |= repair_ball({s}, ball);
    }
    std::erase_if(short_faces, [&](uint32_t f) { return quota_[f] == 0; });
    return truncated;
}

// Edmonds on the union of the balls around `short_faces` (repair_in_balls()); true if a ball was
// cut off by its size.
bool MatchingBuilder::repair_ball(const std::vector<uint32_t>& short_faces, size_t ball) {
    std::vector<uint32_t>& local = ball_local_;  // kNone outside the ball, on entry and exit
    std::vector<uint32_t> faces, queue;
    bool truncated = false;
    for (uint32_t s : short_faces) {
        if (local[s] != kNone) continue;
        queue.assign(1, s);
        local[s] = 0;
        for (size_t head = 0; head < queue.size() && queue.size() < ball; ++head)
            for (uint32_t h = 3 * queue[head]; h < 3 * queue[head] + 3; ++h) {
                if (!passable(h)) continue;
                const uint32_t g = mesh_.neighbor(h);
                if (local[g] == kNone) local[g] = 0, queue.push_back(g);
            }
        faces.insert(faces.end(), queue.begin(), queue.end());
        truncated |= queue.size() >= ball;
    }
    // Keep faces that take matched edges and whose partners are all inside too. A pinned face
    // takes two: it gets two copies, each linked to all its neighbours (b-matching to matching).
    auto want = [&](uint32_t f) { return std::max(0, static_cast<int>(degree(f)) - (2 - vlink_[f])); };
    std::vector<uint32_t> kept, owner;
    for (uint32_t f : faces) local[f] = want(f) > 0 ? 0 : kNone;
    for (uint32_t f : faces) {
        if (local[f] == kNone) continue;
        bool inside = true;
        for (uint32_t h = 3 * f; h < 3 * f + 3; ++h)
            if (matched_[h] && local[mesh_.neighbor(h)] == kNone) inside = false;
        if (inside) kept.push_back(f);
    }
    for (uint32_t f : faces) local[f] = kNone;
    for (uint32_t f : kept) {
        local[f] = static_cast<uint32_t>(owner.size());
        for (int c = 0; c < want(f); ++c) owner.push_back(f);
    }
    // Edges kept in vectors and the graph built in one go: Boost's default edge list allocates
    // per edge.
    using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property, boost::no_property,
                                        boost::no_property, boost::vecS>;
    using Vertex = boost::graph_traits<Graph>::vertex_descriptor;
    const Vertex null = boost::graph_traits<Graph>::null_vertex();
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    std::vector<Vertex> mate(owner.size(), null);
    auto free_copy = [&](uint32_t f) {
        for (uint32_t v = local[f]; v < local[f] + static_cast<uint32_t>(want(f)); ++v)
            if (mate[v] == null) return v;
        return kNone;
    };
    for (uint32_t f : kept)
        for (uint32_t h = 3 * f; h < 3 * f + 3; ++h) {
            if (!passable(h)) continue;
            const uint32_t g = mesh_.neighbor(h);
            if (local[g] == kNone || local[g] <= local[f]) continue;
            for (int c = 0; c < want(f); ++c)
                for (int d = 0; d < want(g); ++d) edges.emplace_back(local[f] + c, local[g] + d);
            const uint32_t vf = free_copy(f), vg = free_copy(g);
            if (matched_[h] && vf != kNone && vg != kNone) mate[vf] = vg, mate[vg] = vf;
        }
    const Graph graph(edges.begin(), edges.end(), owner.size());
    boost::matching<Graph, Vertex*, boost::property_map<Graph, boost::vertex_index_t>::type, boost::edmonds_augmenting_path_finder,
                    keep_matching, boost::no_matching_verifier>(graph, mate.data(), boost::get(boost::vertex_index, graph));
    for (uint32_t f : kept)
        for (uint32_t h = 3 * f; h < 3 * f + 3; ++h) matched_[h] = 0;
    for (uint32_t v = 0; v < owner.size(); ++v) {
        if (mate[v] == null || mate[v] < v) continue;
        const uint32_t f = owner[v], g = owner[mate[v]];
        for (uint32_t h = 3 * f; h < 3 * f + 3; ++h)
            if (passable(h) && !matched_[h] && mesh_.neighbor(h) == g) {
                set_pair(matched_, h, 1);
                break;
            }
    }
    for (uint32_t f : kept) {
        const int have = matched_[3 * f] + matched_[3 * f + 1] + matched_[3 * f + 2];
        quota_[f] = static_cast<uint8_t>(std::max(0, want(f) - have));
    }
    for (uint32_t f : kept) local[f] = kNone;
    return truncated;
}

// Faces the matching left short: local augmenting searches with a growing budget; what is still
// short drops crossed edges instead (each drop leaves a path end).
void MatchingBuilder::repair_short(std::vector<uint32_t>& short_faces) {
    const uint32_t nf = mesh_.num_faces();
    std::vector<uint32_t> stamp(nf, 0);
    aug_prev_.assign(nf, kNone);
    aug_matched_.assign(nf, kNone);
    aug_unmatched_.assign(nf, kNone);
    uint32_t mark = 0;
    for (size_t budget : {size_t{64}, size_t{1024}}) {
        for (uint32_t f : short_faces)
            while (quota_[f] > 0 && augment_from(f, stamp, ++mark, budget)) {
            }
        std::erase_if(short_faces, [&](uint32_t f) { return quota_[f] == 0; });
    }
    // Edmonds on balls: each face's own, then one search over the union of larger balls (it
    // costs O(ball) per augmenting path).
    // Larger balls only for few faces: many faces still short are structural (no 2-factor).
    for (size_t ball : {size_t{512}, kBallOneByOne, size_t{32768}}) {
        const size_t most = ball == 512 ? SIZE_MAX : ball == kBallOneByOne ? 64 : 16;
        if (short_faces.empty() || short_faces.size() > most) break;
        if (ball > kBallOneByOne) {  // a long plain search first: far cheaper than Edmonds on the union
            for (uint32_t f : short_faces)
                while (quota_[f] > 0 && augment_from(f, stamp, ++mark, size_t{1} << 17)) {
                }
            std::erase_if(short_faces, [&](uint32_t f) { return quota_[f] == 0; });
            if (short_faces.empty()) break;
        }
        if (!repair_in_balls(short_faces, ball)) break;
    }
}

// Splits an edge of short face u, towards a face with three passable edges if it can;
// the four children get their quotas anew. The ring of four children has two sibling edges, so
// the dual graph gains odd cycles there: a region whose faces alternate like a chessboard (grids
// with holes) has no 2-factor when its two colours differ in number; one split beside a short
// face lets an augmenting path through. False if u has no such edge.
bool MatchingBuilder::split_beside(uint32_t u) {
    uint32_t best = kNone;
    for (uint32_t h = 3 * u; h < 3 * u + 3; ++h) {
        if (!passable(h) || matched_[h]) continue;
        const uint32_t g = mesh_.neighbor(h);
        if (best == kNone || degree(g) == 3) best = h;
    }
    if (best == kNone) return false;
    const SplitResult sr = split(best);
    for (uint32_t f : {sr.f_a, sr.f_b, sr.g_a, sr.g_b}) {
        const int have = matched_[3 * f] + matched_[3 * f + 1] + matched_[3 * f + 2];
        quota_[f] = static_cast<uint8_t>(std::max(0, static_cast<int>(degree(f)) - (2 - vlink_[f]) - have));
    }
    return true;
}

void MatchingBuilder::settle_leftovers() {
    std::vector<uint32_t> short_faces;
    auto collect = [&] {
        short_faces.clear();
        for (uint32_t f = 0; f < mesh_.num_faces(); ++f)
            if (quota_[f] > 0) short_faces.push_back(f);
    };
    collect();
    repair_short(short_faces);
    if (!short_faces.empty()) {  // the growth builder may have to finish (fallback())
        pre_merge_ = mesh_;
        pre_merge_splits_ = stats_.splits;
    }
    // Still short: the matching is maximum there; splits beside short faces, while they help.
    for (uint32_t round = 0; round < 4 && !short_faces.empty(); ++round) {
        const size_t before = short_faces.size();
        bool any = false;
        for (uint32_t u : std::vector<uint32_t>(short_faces))
            if (quota_[u] > 0) any |= split_beside(u);
        if (!any) break;
        collect();
        repair_short(short_faces);
        stats_.parity_splits += 1;
        if (short_faces.size() >= before) break;
    }
    const uint32_t nf = mesh_.num_faces();
    for (uint32_t h = 0; h < 3 * nf; ++h) used_[h] = passable(h) && !matched_[h];
    for (uint32_t f : short_faces)
        for (uint32_t k = 0; k < 3 && quota_[f] > 0; ++k)
            if (used_[3 * f + k]) {
                set_pair(used_, 3 * f + k, 0);
                --quota_[f];
            }
    stats_.unmatched = static_cast<uint32_t>(short_faces.size());
    if (short_faces.empty()) pre_merge_.reset();  // loops only: no fallback ahead
}

// Loops and paths: components of the crossed edges, the virtual face joining the pinned faces.
void MatchingBuilder::label_structures() {
    const uint32_t nf = mesh_.num_faces();
    sid_.assign(nf, kNone);
    uf_.clear();
    cycle_.clear();
    pinned_.clear();
    std::vector<uint32_t> stack;
    for (uint32_t s = 0; s < nf; ++s) {
        if (sid_[s] != kNone) continue;
        const uint32_t id = static_cast<uint32_t>(uf_.size());
        bool ends = false, pinned = false;
        stack.assign(1, s);
        sid_[s] = id;
        while (!stack.empty()) {
            const uint32_t f = stack.back();
            stack.pop_back();
            ends |= hdeg(f) < 2;
            auto visit = [&](uint32_t g) {
                if (sid_[g] != kNone) return;
                sid_[g] = id;
                stack.push_back(g);
            };
            for (uint32_t k = 0; k < 3; ++k)
                if (used_[3 * f + k]) visit(mesh_.neighbor(3 * f + k));
            if (vlink_[f]) {
                pinned = true;
                for (uint32_t i = 0; i < num_pins_; ++i) visit(pins_[i]);
            }
        }
        uf_.push_back(id);
        cycle_.push_back(!ends && !(pinned && num_pins_ == 1));
        pinned_.push_back(pinned);
    }
    stats_.loops = static_cast<uint32_t>(uf_.size());
}

// Walking loop from face `from` away from face `back`: true if `good` comes before `bad`
// (within a bound; false past it).
bool MatchingBuilder::meets_first(uint32_t from, uint32_t back, uint32_t good, uint32_t bad) const {
    uint32_t prev = back, cur = from;
    for (uint32_t step = 0; step < 256; ++step) {
        if (cur == good) return true;
        if (cur == bad) return false;
        uint32_t next = kNone;
        for (uint32_t h = 3 * cur; h < 3 * cur + 3; ++h)
            if (used_[h] && mesh_.neighbor(h) != prev) next = mesh_.neighbor(h);
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
bool MatchingBuilder::flip_alternating(uint32_t f1) {
    constexpr uint32_t kMaxLoops = 5;
    if (vlink_[f1]) return false;
    uint32_t m1 = kNone;  // f1's matched edge closes the cycle
    for (uint32_t h = 3 * f1; h < 3 * f1 + 3; ++h)
        if (matched_[h]) m1 = h;
    if (m1 == kNone) return false;
    const uint32_t close_face = mesh_.neighbor(m1);
    if (find(sid_[close_face]) == find(sid_[f1])) return false;  // cheap filter: rarely joins loops
    uint32_t path[2 * kMaxLoops];                                // crossed edge, then matched edge, in turn
    uint32_t roots[kMaxLoops];
    uint32_t rep_p = kNone, rep_q = kNone;  // depths of the two crossed edges of a loop met twice
    auto faces_distinct = [&](uint32_t depth) {
        uint32_t faces[2 * kMaxLoops];
        for (uint32_t i = 0; i <= depth; ++i) faces[2 * i] = Mesh::face(path[2 * i]), faces[2 * i + 1] = mesh_.neighbor(path[2 * i]);
        for (uint32_t i = 0; i < 2 * depth + 2; ++i)
            for (uint32_t j = 0; j < i; ++j)
                if (faces[i] == faces[j]) return false;
        return true;
    };
    auto closes_one_loop = [&](uint32_t depth) {
        if (rep_p == kNone) return true;
        if (!faces_distinct(depth)) return false;
        const uint32_t up = path[2 * rep_p], uq = path[2 * rep_q];
        return meets_first(mesh_.neighbor(up), Mesh::face(up), mesh_.neighbor(uq), Mesh::face(uq));
    };
    // Returns true once a cycle is flipped. `f` is the face at which a crossed edge is taken.
    auto search = [&](auto&& self, uint32_t f, uint32_t depth) -> bool {
        const uint32_t r = find(sid_[f]);
        if (!cycle_[r] || pinned_[r] || vlink_[f]) return false;
        bool repeat = false;
        for (uint32_t i = 0; i < depth; ++i)
            if (roots[i] == r) {
                if (rep_p != kNone) return false;
                rep_p = i, rep_q = depth, repeat = true;
            }
        roots[depth] = r;
        bool found = false;
        for (uint32_t h = 3 * f; h < 3 * f + 3 && !found; ++h) {
            if (!used_[h]) continue;
            const uint32_t g = mesh_.neighbor(h);
            uint32_t m = kNone;
            for (uint32_t e = 3 * g; e < 3 * g + 3; ++e)
                if (matched_[e]) m = e;
            if (m == kNone || vlink_[g]) continue;
            path[2 * depth] = h;
            path[2 * depth + 1] = m;
            if (g == close_face && mesh_.twin(m) == m1 && depth > 0 && closes_one_loop(depth)) {
                for (uint32_t i = 0; i <= 2 * depth + 1; ++i) {
                    set_pair(used_, path[i], !used_[path[i]]);
                    set_pair(matched_, path[i], !matched_[path[i]]);
                }
                for (uint32_t i = 1; i <= depth; ++i) uf_[find(roots[i])] = find(roots[0]);
                found = true;
            } else if (depth + 1 < kMaxLoops && g != close_face) {
                found = self(self, mesh_.neighbor(m), depth + 1);
            }
        }
        if (repeat) rep_p = rep_q = kNone;
        return found;
    };
    return search(search, f1, 0);
}

// Fewer loops before any split: flip alternating cycles that join loops.
void MatchingBuilder::reduce_loops() {
    for (uint32_t pass = 0, flips = 1; pass < 4 && flips > 0; ++pass) {  // a flip can enable another
        flips = 0;
        for (uint32_t f = 0; f < mesh_.num_faces(); ++f) flips += flip_alternating(f);
        stats_.ring_flips += flips;
    }
}

// The faces of a loop cut open at its crossed half-edge `cut`: from cut's face round to the face
// across it.
std::vector<uint32_t> MatchingBuilder::loop_from(uint32_t cut) const {
    std::vector<uint32_t> seq;
    uint32_t in = cut, f = Mesh::face(cut);
    for (;;) {
        seq.push_back(f);
        uint32_t out = kNone;
        for (uint32_t h = 3 * f; h < 3 * f + 3; ++h)
            if (used_[h] && h != in) out = h;
        if (out == kNone || out == mesh_.twin(cut)) return seq;
        in = mesh_.twin(out);
        f = Mesh::face(in);
    }
}

// 1 if the GL strip needs a swap at crossed half-edge h: the turns in its two faces (the faces'
// edges left uncrossed) pivot on the same endpoint of h. Path ends make no turn.
int MatchingBuilder::swap_at(uint32_t h) const {
    const uint32_t t = mesh_.twin(h);
    const uint32_t f = Mesh::face(h), g = Mesh::face(t);
    if (hdeg(f) != 2 || hdeg(g) != 2) return 0;
    const bool f_at_from = !used_[Mesh::prev(h)];  // f's uncrossed edge touches from(h)
    const bool g_at_from = !used_[Mesh::next(t)];  // g's uncrossed edge touches to(t) = from(h)
    return f_at_from == g_at_from;
}

// Swaps at the crossed edges of the given faces (each edge counted once).
int MatchingBuilder::swaps_around(std::initializer_list<uint32_t> faces) const {
    uint32_t seen[9];
    uint32_t n = 0;
    int sum = 0;
    for (uint32_t f : faces)
        for (uint32_t h = 3 * f; h < 3 * f + 3; ++h) {
            if (!used_[h]) continue;
            const uint32_t key = std::min(h, mesh_.twin(h));
            if (std::find(seen, seen + n, key) != seen + n) continue;
            seen[n++] = key;
            sum += swap_at(h);
        }
    return sum;
}

// Loops taken into one growing path for free, before any split (rotation-extension, Pósa 1976):
// a path end next to a loop opens the loop there and continues round it; a path end next to a
// face x inside the path links to x and drops x's link towards the end, so the part between turns
// round and x's old neighbour becomes the end. Rotations are searched at random from the ends and
// kept only when they lead to a loop taken in for fewer GL indices than its split would cost
// (a split: 2 triangles; each changed turn pattern may add a swap). Only loops (no pins, no other
// paths) are handled; what is left is joined by merge_all().
void MatchingBuilder::absorb_loops() {
    const uint32_t nf = mesh_.num_faces();
    if (num_pins_ > 0 || nf < 2) return;
    uint32_t loops = 0;
    for (uint32_t s = 0; s < uf_.size(); ++s)
        if (find(s) == s) {
            if (!cycle_[s] || pinned_[s]) return;
            ++loops;
        }
    if (loops < 2) return;
    uint32_t cut = kNone;
    for (uint32_t h = 0; h < 3 * nf && cut == kNone; ++h)
        if (used_[h]) cut = h;
    const uint32_t root = find(sid_[Mesh::face(cut)]);
    PathOrder path(nf);
    path.append(loop_from(cut));
    set_pair(used_, cut, 0);
    cycle_[root] = 0;
    uint32_t ends[2] = {Mesh::face(cut), mesh_.neighbor(cut)};  // front, back
    struct Take {
        uint32_t link = kNone, cut = kNone;
        int cost = 0;
    };
    // The cheapest way to take a loop in at ends[side]: link h into face g, cut one of g's links.
    auto best_take = [&](uint32_t side) {
        Take best;
        const uint32_t e = ends[side];
        for (uint32_t h = 3 * e; h < 3 * e + 3; ++h) {
            if (!passable(h) || used_[h]) continue;
            const uint32_t g = mesh_.neighbor(h), r = find(sid_[g]);
            if (r == root || !cycle_[r] || pinned_[r]) continue;
            for (uint32_t gc = 3 * g; gc < 3 * g + 3; ++gc) {
                if (!used_[gc]) continue;
                const uint32_t c = mesh_.neighbor(gc);
                const int before = swaps_around({e, g, c});
                set_pair(used_, gc, 0), set_pair(used_, h, 1);
                const int cost = swaps_around({e, g, c}) - before;
                set_pair(used_, gc, 1), set_pair(used_, h, 0);
                if (best.link == kNone || cost < best.cost) best = {h, gc, cost};
            }
        }
        return best;
    };
    auto take = [&](uint32_t side, const Take& t) {
        std::vector<uint32_t> seq = loop_from(t.cut);
        uf_[find(sid_[Mesh::face(t.cut)])] = root;
        set_pair(used_, t.cut, 0);
        set_pair(used_, t.link, 1);
        side ? path.append(seq) : path.prepend(seq);
        ends[side] = seq.back();
        --loops;
        ++stats_.absorbed;
    };
    struct Rotation {
        uint32_t side, link, dropped, from;
    };
    std::vector<Rotation> trial;  // rotations since the last loop taken in
    int trial_cost = 0;           // swaps they added
    auto reverse = [&](uint32_t side, uint32_t from) { side ? path.reverse_back(from) : path.reverse_front(from); };
    auto rotate = [&](uint32_t side, uint32_t h) {  // h: a free edge of ends[side] into the path
        const uint32_t e = ends[side], x = mesh_.neighbor(h), px = path.position(x), n = path.size();
        if (side ? px + 2 >= n : px < 2) return;  // x is the end's own neighbour
        const uint32_t y = path.at(side ? px + 1 : px - 1);
        uint32_t xy = kNone;
        for (uint32_t k = 3 * x; k < 3 * x + 3; ++k)
            if (used_[k] && mesh_.neighbor(k) == y) xy = k;
        const int before = swaps_around({e, x, y});
        set_pair(used_, xy, 0);
        set_pair(used_, h, 1);
        trial_cost += swaps_around({e, x, y}) - before;
        reverse(side, side ? px + 1 : px);
        trial.push_back({side, h, xy, side ? px + 1 : px});
        ends[side] = y;
    };
    auto undo_trial = [&] {
        for (size_t i = trial.size(); i-- > 0;) {
            const Rotation& r = trial[i];
            reverse(r.side, r.from);
            set_pair(used_, r.link, 0);
            set_pair(used_, r.dropped, 1);
            ends[r.side] = Mesh::face(r.link);
        }
        trial.clear();
        trial_cost = 0;
    };
    // A split join adds two triangles (two GL indices) and may add swaps of its own: a loop is
    // worth taking in while the turns changed cost fewer than 4 swaps (best of 2, 4, unbounded on
    // the libcgal-demo meshes; docs/algorithm.md).
    constexpr int kSplitCost = 4;
    constexpr uint64_t kWindow = 4096;  // rotations without a loop taken in before giving up
    uint64_t rng = 0x9e3779b97f4a7c15ULL, budget = 16ULL * nf, idle = 0;
    while (loops > 0 && budget > 0 && idle < kWindow) {
        bool took = false;
        for (uint32_t side = 0; side < 2; ++side)
            for (Take t; (t = best_take(side)).link != kNone && trial_cost + t.cost < kSplitCost;) {
                take(side, t);
                took = true;
                trial.clear();
                trial_cost = 0;
            }
        if (took) {
            idle = 0;
            continue;
        }
        rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
        const uint32_t side = rng & 1, h = 3 * ends[side] + (rng >> 1) % 3;
        --budget, ++idle;
        if (passable(h) && !used_[h] && find(sid_[mesh_.neighbor(h)]) == root) rotate(side, h);
        if (trial_cost >= kSplitCost + 6) undo_trial();  // too far from the pattern: start again from the last take
    }
    undo_trial();
}

// Joins along the passable edge h (not crossed): a and b are the roots of its two faces.
void MatchingBuilder::join(uint32_t h, uint32_t a, uint32_t b, bool cycle, bool pinned) {
    set_pair(used_, h, 1);
    uf_[b] = a;
    cycle_[a] = cycle;
    pinned_[a] = pinned;
}

// Path end across h joins loop a for free: the loop opens at h's face (one crossed edge dropped).
void MatchingBuilder::rotate_into(uint32_t h, uint32_t a, uint32_t b) {
    const uint32_t f = Mesh::face(h);
    for (uint32_t k = 0; k < 3; ++k)
        if (used_[3 * f + k]) {
            set_pair(used_, 3 * f + k, 0);
            break;
        }
    join(h, a, b, false, pinned_[b]);
}

// Loop a (h's face f crosses its two other edges) joins b (g = the face across h) by one
// midpoint split of h: f_a-g_a and f_b-g_b become crossed, f's and g's outer edges stay as they
// were. A loop joined to a loop stays a loop; to a path (g inside, at an end, or alone), a path.
void MatchingBuilder::merge_by_split(uint32_t h, uint32_t a, uint32_t b) {
    const uint32_t t = mesh_.twin(h);
    split(h);
    set_pair(used_, h, 1);  // f_a - g_a
    set_pair(used_, t, 1);  // g_b - f_b
    uf_[b] = a;
    cycle_[a] = cycle_[b];
    pinned_[a] = pinned_[a] || pinned_[b];
}

bool MatchingBuilder::try_merge(uint32_t h, bool allow_split) {
    const uint32_t f = Mesh::face(h), g = mesh_.neighbor(h);
    const uint32_t a = find(sid_[f]), b = find(sid_[g]);
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

// Free joins first (path ends, path ends into loops), then splits, then free joins again.
void MatchingBuilder::merge_all() {
    for (bool allow_split : {false, true, false})
        for (uint32_t f = 0; f < mesh_.num_faces(); ++f)
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t h = 3 * f + k;
                if (!passable(h) || used_[h]) continue;
                if (find(sid_[f]) == find(sid_[mesh_.neighbor(h)]) && (cycle_[find(sid_[f])] || hdeg(f) == 2)) continue;
                if (try_merge(h, allow_split)) k = kNone;  // f's edges changed: look at all three again
            }
}

bool MatchingBuilder::single_strip_ready() {
    uint32_t roots = 0, root = kNone;
    for (uint32_t s = 0; s < uf_.size(); ++s)
        if (find(s) == s) ++roots, root = s;
    if (roots != 1) return false;
    return num_pins_ != 2 || cycle_[root];
}

// The faces in strip order: from the first pinned face, else from a path end, else around the
// loop from face 0. Empty if the crossed edges do not form one strip.
std::vector<uint32_t> MatchingBuilder::walk() const {
    const uint32_t nf = mesh_.num_faces();
    uint32_t start = num_pins_ ? pins_[0] : kNone, in = kNone;
    for (uint32_t f = 0; f < nf && start == kNone; ++f)
        if (hdeg(f) < 2) start = f;
    if (start == kNone) {  // one loop: cut it at face 0, as if entered by one of its crossed edges
        start = 0;
        for (uint32_t k = 0; k < 3; ++k)
            if (used_[k]) in = k;
    }
    std::vector<uint32_t> order;
    order.reserve(nf);
    for (uint32_t f = start; order.size() < nf;) {
        order.push_back(f);
        uint32_t out = kNone;
        for (uint32_t k = 0; k < 3; ++k)
            if (used_[3 * f + k] && 3 * f + k != in) out = 3 * f + k;
        if (out == kNone) break;
        in = mesh_.twin(out);
        f = Mesh::face(in);
        if (f == start) break;
    }
    return order;
}

StripResult MatchingBuilder::finish(std::vector<uint32_t> order) {
    const uint32_t nf = mesh_.num_faces();
    if (order.size() != nf)
        throw InternalError("matching engine: strip covers " + std::to_string(order.size()) + " of " + std::to_string(nf) + " faces");
    if (num_pins_ == 2 && order.back() != pins_[1]) throw InternalError("matching engine: strip does not end at the target face");
    if (reversed_) std::reverse(order.begin(), order.end());
    stats_.swaps = count_swaps(mesh_, order);
    stats_.output_triangles = nf;
    StripResult result;
    result.order = std::move(order);
    result.stats = stats_;
    result.mesh = std::move(mesh_);
    return result;
}

// Not one strip (paths whose ends never touch): the growth builder, which always ends in one
// strip, finishes on the mesh as split so far.
StripResult MatchingBuilder::fallback() {
    // Candidates that fail (a broken precondition on a partly split mesh) are skipped; the input
    // mesh itself comes last and is the growth builder's own case.
    auto grow = [&](Mesh mesh, uint32_t splits) {
        StripOptions o = opt_;
        o.engine = StripEngine::Growth;
        if (o.seed_face && o.source && !face_has_vertex(mesh, *o.seed_face, *o.source)) o.seed_face.reset();
        try {
            StripResult r = build_strip_growth(std::move(mesh), o);
            r.stats.splits += splits;
            return r;
        } catch (const InternalError&) {
            return StripResult{};
        }
    };
    auto better = [&](StripResult& r, StripResult alt) {
        const bool ok = !alt.order.empty() && alt.stats.splits <= stats_.input_triangles;
        if (ok && (r.order.empty() || alt.stats.output_triangles < r.stats.output_triangles)) r = std::move(alt);
    };
    Mesh original = input_mesh();  // before mesh_ is handed over
    StripResult r;
    better(r, grow(std::move(mesh_), stats_.splits));
    if (pre_merge_) better(r, grow(std::move(*pre_merge_), pre_merge_splits_));  // without the joins' splits
    if (r.order.empty()) {
        StripOptions o = opt_;
        o.engine = StripEngine::Growth;
        r = build_strip_growth(std::move(original), o);
    }
    r.stats.input_triangles = stats_.input_triangles;
    r.stats.loops = stats_.loops;
    r.stats.ring_flips = stats_.ring_flips;
    r.stats.unmatched = stats_.unmatched;
    r.stats.growth_fallback = true;
    r.stats.engine = StripEngine::Matching;
    r.fundamental_positions.clear();
    r.take_time.clear();
    return r;
}

// The input mesh again (input vertices keep their positions; midpoints come after them).
Mesh MatchingBuilder::input_mesh() const {
    TriangleSoup soup;
    soup.points.assign(mesh_.points().begin(), mesh_.points().begin() + mesh_.num_input_vertices());
    soup.triangles = input_faces_;
    return Mesh::from_soup(soup);
}

StripResult MatchingBuilder::run() {
    const uint32_t nf = mesh_.num_faces();
    check_strip_request(mesh_, opt_);
    blocked_ = constraint_halfedges(mesh_, opt_);
    input_faces_.resize(nf);
    for (uint32_t f = 0; f < nf; ++f)
        for (uint32_t k = 0; k < 3; ++k) input_faces_[f][k] = mesh_.corner_vertices()[3 * f + k];
    stats_.input_triangles = nf;
    stats_.boundary_loops = mesh_.num_boundary_loops();
    stats_.genus = mesh_.genus();
    stats_.engine = StripEngine::Matching;
    matched_.assign(mesh_.num_halfedges(), 0);
    used_.assign(mesh_.num_halfedges(), 0);
    vlink_.assign(nf, 0);
    quota_.assign(nf, 0);
    choose_pins();
    split_ears();
    split_bridges();
    set_quotas();
    match_patterned();
    settle_leftovers();
    label_structures();
    reduce_loops();
    absorb_loops();
    merge_all();
    if (opt_.validate_each_split) mesh_.validate();
    if (!single_strip_ready() || stats_.splits > stats_.input_triangles) return fallback();
    std::vector<uint32_t> order = walk();
    if (order.size() != mesh_.num_faces() || (num_pins_ == 2 && order.back() != pins_[1])) return fallback();
    return finish(std::move(order));
}

}  // namespace

StripResult build_strip_matching(Mesh mesh, const StripOptions& options) {
    MatchingBuilder builder(std::move(mesh), options);
    return builder.run();
}

}  // namespace singlestrip
