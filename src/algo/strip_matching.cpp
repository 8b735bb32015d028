// singlestrip — matching engine: one strip from a 2-factor of the dual graph.
//
// Gopi & Eppstein, "Single-Strip Triangulation of Manifolds with Arbitrary Topology" (2004), and
// Diaz-Gutierrez, Eppstein & Gopi, "Single Triangle Strip and Loop on Manifolds with Boundaries"
// (2006). Every face keeps one passable edge the strip does not cross (its *matched* edge, paired
// with the neighbour's), so the crossed (*used*) edges form loops and paths; loops are joined by one
// midpoint split each, path ends for free where they touch. Design, the argument that it ends in
// one strip, and what it costs: docs/algorithm.md, "The matching engine".
//
// This file: pins, ear and bridge splits, the patterned matching, run() and the growth fallback.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/gentle_growth.hpp"
#include "matching_builder.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/strip.hpp"
#include "strip_controls.hpp"

namespace singlestrip::matching {

// Pinned faces: the strip starts at pins_[0] and ends at pins_[1] (either may be absent).
void MatchingBuilder::choose_pins() {
    const uint32_t nf = mesh_.num_faces();
    uint32_t first = kNone, last = kNone;
    if (opt_.seed_face)
        first = opt_.seed_face->idx();
    else if (opt_.source)
        first = face_at_vertex(mesh_, blocked_, opt_.source->idx(), kNone);
    if (opt_.target && nf > 1) {
        last = face_at_vertex(mesh_, blocked_, opt_.target->idx(), first);
        if (last == first) {
            // The target's only face is the first face: split it across the edge opposite the
            // target so that both children touch it; start in one, end in the other.
            uint32_t h = 3 * first;
            while (mesh_.from(HalfedgeId(h)).idx() == opt_.target->idx() || mesh_.to(HalfedgeId(h)).idx() == opt_.target->idx()) ++h;
            if (!passable(h))
                throw RequestError("cannot end at target vertex " + std::to_string(opt_.target->idx()) +
                                   ": its only face is the first face of the strip and cannot be split");
            const SplitResult sr = split(h);
            const bool a_first = !opt_.source || face_has_vertex(mesh_, sr.f_a.idx(), opt_.source->idx());
            first = a_first ? sr.f_a.idx() : sr.f_b.idx();
            last = a_first ? sr.f_b.idx() : sr.f_a.idx();
        }
    }
    if (first != kNone) pins_[num_pins_++] = first;
    if (last != kNone) pins_[num_pins_++] = last;
    reversed_ = first == kNone && last != kNone;  // target only: walk from it, then reverse
}

// Splits the interior edge of h; per-half-edge flags follow the two half-edges that move, the
// four new inner edges start clear. Pins keep their vertex.
SplitResult MatchingBuilder::split(uint32_t h) {
    const uint32_t t = mesh_.twin(HalfedgeId(h)).idx(), hn = Mesh::next(HalfedgeId(h)).idx(), tn = Mesh::next(HalfedgeId(t)).idx();
    const uint32_t pin_vertex[2] = {opt_.source ? opt_.source->idx() : kNone, opt_.target ? opt_.target->idx() : kNone};
    for (const uint32_t c : {hn, tn})  // the two corners split_edge() moves to the midpoint
        if (c < 3 * mesh_.num_input_faces()) overwritten_.emplace_back(c, mesh_.corner_vertices()[c]);
    split_log_.push_back(h);
    const SplitResult sr = mesh_.split_edge(HalfedgeId(h));
    if (opt_.validate_each_split) mesh_.validate();
    ++stats_.splits;
    const uint32_t fb0 = 3 * sr.f_b.idx(), ga0 = 3 * sr.g_a.idx();
    for (auto* a : {&blocked_, &matched_, &used_}) {
        reserve_gently(*a, mesh_.num_halfedges());
        a->resize(mesh_.num_halfedges(), 0);
        (*a)[fb0 + 1] = (*a)[hn];
        (*a)[ga0 + 1] = (*a)[tn];
        for (uint32_t x : {h, hn, t, tn, fb0, fb0 + 2, ga0, ga0 + 2}) (*a)[x] = 0;
    }
    reserve_gently(vlink_, mesh_.num_faces());
    reserve_gently(quota_, mesh_.num_faces());
    vlink_.resize(mesh_.num_faces(), 0);
    quota_.resize(mesh_.num_faces(), 0);
    if (!sid_.empty()) reserve_gently(sid_, mesh_.num_faces());
    if (!sid_.empty()) sid_.resize(mesh_.num_faces(), sid_[sr.f_a.idx()]), sid_[sr.g_a.idx()] = sid_[sr.g_b.idx()];
    for (uint32_t i = 0; i < num_pins_; ++i) {
        const uint32_t v = (i == 0 && !reversed_) ? pin_vertex[0] : pin_vertex[1];
        if (v == kNone) continue;
        const uint32_t old = pins_[i];
        if (old == sr.f_a.idx() && !face_has_vertex(mesh_, sr.f_a.idx(), v))
            pins_[i] = sr.f_b.idx();
        else if (old == sr.g_b.idx() && !face_has_vertex(mesh_, sr.g_b.idx(), v))
            pins_[i] = sr.g_a.idx();
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
        const uint32_t g = mesh_.neighbor(HalfedgeId(h)).idx();
        if (degree(g) == 1) continue;  // two faces only: an ear pair is a strip already
        const uint32_t tn = Mesh::next(mesh_.twin(HalfedgeId(h))).idx();
        const SplitResult sr = split(h);
        const uint32_t inner = tn;  // after the split: g_b's half-edge towards g_a
        const auto has_match = [&](uint32_t x) { return matched_[3 * x] | matched_[3 * x + 1] | matched_[3 * x + 2]; };
        if (degree(sr.g_a.idx()) == 3 && degree(sr.g_b.idx()) == 3 && !has_match(sr.g_a.idx()) && !has_match(sr.g_b.idx()))
            set_pair(matched_, inner, 1);
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
                if (!passable(h) || mesh_.twin(HalfedgeId(h)).idx() == parent_edge[fr.f]) continue;
                const uint32_t g = mesh_.neighbor(HalfedgeId(h)).idx();
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
            const uint32_t p = Mesh::face(HalfedgeId(parent_edge[f])).idx();
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
            if (passable(h) && mesh_.neighbor(HalfedgeId(h)).idx() != from) next = mesh_.neighbor(HalfedgeId(h)).idx();
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
        const uint32_t f = Mesh::face(HalfedgeId(h)).idx(), g = mesh_.neighbor(HalfedgeId(h)).idx();
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

// Around a vertex of high valence the turn pattern pairs fan faces across their spokes, and each
// pair leaves a small loop through the faces beyond (a cone's apex: one loop per two faces). Fan
// faces matched across their outer edges instead cross every spoke: the fan becomes one loop
// (with a swap per face, as any strip round a fan needs).
void MatchingBuilder::match_fans() {
    const uint32_t nh = mesh_.num_halfedges();
    std::vector<uint32_t> valence(mesh_.num_vertices(), 0);
    for (uint32_t h = 0; h < nh; ++h) ++valence[mesh_.from(HalfedgeId(h)).idx()];
    for (uint32_t h = 0; h < nh; ++h) {
        if (valence[mesh_.from(HalfedgeId(h)).idx()] < kFanValence) continue;
        const uint32_t outer = Mesh::next(HalfedgeId(h)).idx(), f = Mesh::face(HalfedgeId(h)).idx();
        if (!passable(outer) || matched_[outer] || quota_[f] == 0) continue;
        const uint32_t g = mesh_.neighbor(HalfedgeId(outer)).idx();
        if (quota_[g] == 0) continue;
        set_pair(matched_, outer, 1);
        --quota_[f];
        --quota_[g];
    }
}

// Swaps between faces of two crossed edges each, plus 8 per face left short (the repair of each
// costs about that many: turbine.off, 39 short faces, 894 swaps).
long MatchingBuilder::pattern_cost() const {
    const uint32_t nh = mesh_.num_halfedges();
    auto crossed = [&](uint32_t h) { return passable(h) && !matched_[h]; };
    auto turns = [&](uint32_t f) { return crossed(3 * f) + crossed(3 * f + 1) + crossed(3 * f + 2) + vlink_[f] == 2; };
    long cost = 0;
    for (uint32_t h = 0; h < nh; ++h) {
        const uint32_t t = mesh_.twin(HalfedgeId(h)).idx();
        if (!crossed(h) || t < h || !turns(face_of(h)) || !turns(face_of(t))) continue;
        cost += crossed(Mesh::prev(HalfedgeId(h)).idx()) == crossed(Mesh::next(HalfedgeId(t)).idx());
    }
    for (uint32_t f = 0; f < mesh_.num_faces(); ++f) cost += 8 * quota_[f];
    return cost;
}

// Two orders of the greedy: rows one after the other, or each face's mate queued at once (a
// clean grid pattern, where the first order starts rows in arbitrary turns: knot.off 310 swaps
// against 76). The one with the lower pattern_cost() is kept.
void MatchingBuilder::choose_pattern() {
    const std::vector<uint8_t> matched0 = matched_, quota0 = quota_;
    match_patterned(false);
    const long cost_rows = pattern_cost();
    std::vector<uint8_t> matched_rows = std::move(matched_), quota_rows = std::move(quota_);
    matched_ = matched0;
    quota_ = quota0;
    match_patterned(true);
    if (pattern_cost() < cost_rows) return;
    matched_ = std::move(matched_rows);
    quota_ = std::move(quota_rows);
}

// Greedy matching carried face to face in breadth-first order: across a crossed edge (u, v),
// if this face's matched edge touches u, the neighbour's should touch v — then the two turns
// alternate and the GL strip needs no swap there.
void MatchingBuilder::match_patterned(bool mates) {
    const uint32_t nf = mesh_.num_faces();
    std::vector<uint32_t> pref(nf, kNone), queue, critical;
    std::vector<uint8_t> seen(nf, 0);
    // Karp-Sipser: a face left with one free neighbour takes it at once, before the pattern
    // asks, so few faces are left short (each costs an augmenting path, which breaks the pattern).
    std::vector<uint8_t> free_n(nf, 0);
    auto wants = [&](uint32_t h) { return passable(h) && !matched_[h] && quota_[mesh_.neighbor(HalfedgeId(h)).idx()] > 0; };
    for (uint32_t f = 0; f < nf; ++f)
        if (quota_[f] > 0)
            for (uint32_t h = 3 * f; h < 3 * f + 3; ++h) free_n[f] += wants(h);
    for (uint32_t f = 0; f < nf; ++f)
        if (quota_[f] > 0 && free_n[f] == 1) critical.push_back(f);
    auto match = [&](uint32_t h) {
        set_pair(matched_, h, 1);
        for (uint32_t x : {Mesh::face(HalfedgeId(h)).idx(), mesh_.neighbor(HalfedgeId(h)).idx()}) {
            if (--quota_[x] > 0) continue;
            for (uint32_t e = 3 * x; e < 3 * x + 3; ++e) {
                if (!passable(e)) continue;
                const uint32_t y = mesh_.neighbor(HalfedgeId(e)).idx();
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
                if (mates && passable(h) && matched_[h] && !seen[across(h)]) {  // the mate's row next
                    seen[across(h)] = 1;
                    queue.push_back(across(h));
                }
                if (!passable(h) || matched_[h]) continue;
                const uint32_t g = mesh_.neighbor(HalfedgeId(h)).idx();
                if (seen[g]) continue;
                seen[g] = 1;
                queue.push_back(g);
                const uint32_t t = mesh_.twin(HalfedgeId(h)).idx();
                if (m == Mesh::prev(HalfedgeId(h)).idx())
                    pref[g] = Mesh::prev(HalfedgeId(t)).idx();  // m touches from(h): g's should touch to(h)
                else if (m == Mesh::next(HalfedgeId(h)).idx())
                    pref[g] = Mesh::next(HalfedgeId(t)).idx();  // and the other way round
            }
        }
    }
}

// Augmenting path from a face still wanting a matched edge to another one: alternately an
// unmatched and a matched passable edge. Faces are visited once (simple paths; blossoms are not
// searched), at most `budget` of them. True if the matching grew.
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
        in = mesh_.twin(HalfedgeId(out)).idx();
        f = Mesh::face(HalfedgeId(in)).idx();
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

// The growth builder on `mesh` (the input or a partly split copy that already cost `splits`);
// an empty result when it fails (a broken precondition on a partly split mesh).
StripResult MatchingBuilder::grow(Mesh mesh, uint32_t splits) const {
    StripOptions o = opt_;
    o.engine = StripEngine::Growth;
    if (o.seed_face && o.source && !face_has_vertex(mesh, o.seed_face->idx(), o.source->idx())) o.seed_face.reset();
    try {
        StripResult r = build_strip_growth(std::move(mesh), o);
        r.stats.splits += splits;
        return r;
    } catch (const InternalError&) {
        return StripResult{};
    }
}

// What makes one strip better than another: fewer triangles, then fewer swaps (GL indices).
static std::pair<uint32_t, uint32_t> cost(const StripResult& x) {
    return {x.stats.output_triangles, x.stats.swaps};
}

// Keeps in `r` the better strip (cost()).
void MatchingBuilder::keep_better(StripResult& r, StripResult alt) const {
    if (alt.order.empty() || alt.stats.splits > stats_.input_triangles) return;
    if (r.order.empty() || cost(alt) < cost(r)) r = std::move(alt);
}

// Marks a result the growth builder made as the matching engine's, with the engine's counts.
StripResult MatchingBuilder::as_fallback(StripResult r) const {
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

// The mesh before the joins: split numbering is deterministic, so replaying the logged splits on
// the input rebuilds it.
Mesh MatchingBuilder::pre_merge_mesh(const Mesh& original) const {
    Mesh pre(original);
    for (uint32_t i = 0; i < pre_merge_splits_; ++i) pre.split_edge(HalfedgeId(split_log_[i]));
    return pre;
}

// Not one strip (paths whose ends never touch): the growth builder, which always ends in one
// strip, finishes on the mesh as split so far.
StripResult MatchingBuilder::fallback() {
    // The input mesh is a candidate too: the engine's splits (ears, bridges, parity) can cost the
    // growth builder more than they save (boeing.off's small parts: +90% against +26%).
    Mesh original = input_mesh();  // before mesh_ is handed over
    StripResult r;
    keep_better(r, grow(std::move(mesh_), stats_.splits));
    if (pre_merge_) keep_better(r, grow(pre_merge_mesh(original), pre_merge_splits_));  // without the joins' splits
    keep_better(r, grow(Mesh(original), 0));
    if (r.order.empty()) {  // the growth builder's own case, with its own errors
        StripOptions o = opt_;
        o.engine = StripEngine::Growth;
        r = build_strip_growth(std::move(original), o);
    }
    return as_fallback(std::move(r));
}

// Parity splits come in pairs of triangles beside every face left short, where the growth
// builder's turns often need none (cylinder.off: +5.1% against +2.5%): the better of the two.
// After chain splits, the growth builder on the mesh before them is a candidate too: where the
// corridors' junctions pair up along their turns it needs fewer (hole corridors, 10K: +2.98%
// against +3.44%).
StripResult MatchingBuilder::finish_or_grow(std::vector<uint32_t> order) {
    if (stats_.parity_splits == 0) return finish(std::move(order));
    Mesh original = input_mesh();
    StripResult r = finish(std::move(order));
    StripResult g;
    if (chain_splits_ && pre_merge_) keep_better(g, grow(pre_merge_mesh(original), pre_merge_splits_));
    keep_better(g, grow(std::move(original), 0));
    if (g.order.empty()) return r;
    return cost(g) < cost(r) ? as_fallback(std::move(g)) : r;
}

// The input mesh again (input vertices keep their positions; midpoints come after them).
Mesh MatchingBuilder::input_mesh() const {
    TriangleSoup soup;
    soup.points.assign(mesh_.points().begin(), mesh_.points().begin() + mesh_.num_input_vertices());
    const auto& cv = mesh_.corner_vertices();
    soup.triangles.resize(mesh_.num_input_faces());
    for (uint32_t f = 0; f < soup.triangles.size(); ++f) soup.triangles[f] = {cv[3 * f], cv[3 * f + 1], cv[3 * f + 2]};
    for (auto it = overwritten_.rbegin(); it != overwritten_.rend(); ++it) soup.triangles[it->first / 3][it->first % 3] = it->second;
    return Mesh::from_soup(std::move(soup));
}

StripResult MatchingBuilder::run() {
    const uint32_t nf = mesh_.num_faces();
    check_strip_request(mesh_, opt_);
    blocked_ = constraint_halfedges(mesh_, opt_);
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
    match_fans();
    choose_pattern();
    settle_leftovers();
    label_structures();
    reduce_loops();
    absorb_loops();
    merge_all();
    if (opt_.validate_each_split) mesh_.validate();
    if (!single_strip_ready() || stats_.splits > stats_.input_triangles) return fallback();
    std::vector<uint32_t> order = walk();
    if (order.size() != mesh_.num_faces() || (num_pins_ == 2 && order.back() != pins_[1])) return fallback();
    return finish_or_grow(std::move(order));
}

}  // namespace singlestrip::matching

namespace singlestrip {

StripResult build_strip_matching(Mesh mesh, const StripOptions& options) {
    matching::MatchingBuilder builder(std::move(mesh), options);
    return builder.run();
}

}  // namespace singlestrip
