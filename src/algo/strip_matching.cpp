// singlestrip — matching engine: one strip from a 2-factor of the dual graph.
//
// Gopi & Eppstein, "Single-Strip Triangulation of Manifolds with Arbitrary Topology" (2004), and
// Diaz-Gutierrez, Eppstein & Gopi, "Single Triangle Strip and Loop on Manifolds with Boundaries"
// (2006). Every face keeps one passable edge the strip does not cross (its *matched* edge, paired
// with the neighbour's), so the crossed (*used*) edges form loops and paths; loops are joined by one
// midpoint split each, path ends for free where they touch. Design, the argument that it ends in
// one strip, and what it costs: docs/algorithm.md, "The matching engine".
//
// This file: pins, the patterned matching, run() and the growth fallback.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "core/gentle_growth.hpp"
#include "core/topology.hpp"
#include "growth_builder.hpp"
#include "matching_builder.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/strip.hpp"
#include "strip_controls.hpp"

namespace singlestrip::matching {

// Pinned faces: the strip starts at pins_[0] and ends at pins_[1] (either may be absent).
void MatchingBuilder::choose_pins() {
    const uint32_t nf = mesh_.num_faces();
    FaceId first = kNone, last = kNone;
    if (opt_.seed_face)
        first = *opt_.seed_face;
    else if (opt_.source)
        first = face_at_vertex(mesh_, blocked_, *opt_.source, kNone);
    if (opt_.target && nf > 1) {
        last = face_at_vertex(mesh_, blocked_, *opt_.target, first);
        if (last == first) {
            // The target's only face is the first face: split it across the edge opposite the
            // target so that both children touch it; start in one, end in the other.
            HalfedgeId h = Mesh::halfedge(first, 0);
            while (mesh_.from(h) == *opt_.target || mesh_.to(h) == *opt_.target) h = Mesh::next(h);
            if (!passable(h))
                throw RequestError("cannot end at target vertex " + std::to_string(opt_.target->idx()) +
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
SplitResult MatchingBuilder::split(HalfedgeId h) {
    const HalfedgeId t = mesh_.twin(h), hn = Mesh::next(h), tn = Mesh::next(t);
    const VertexId pin_vertex[2] = {opt_.source.value_or(kNone), opt_.target.value_or(kNone)};
    for (const HalfedgeId c : {hn, tn})  // the two corners split_edge() moves to the midpoint
        if (Mesh::face(c).idx() < mesh_.num_input_faces()) overwritten_.emplace_back(c, mesh_.from(c));
    // Room for ears, bridges and joins (a few percent; see the growth builder's prepare()),
    // taken at the first split: a closed mesh often needs none, and the points would be copied.
    if (split_log_.empty()) mesh_.reserve_splits(mesh_.num_input_faces() / 32 + 64);
    split_log_.push_back(h);
    const SplitResult sr = mesh_.split_edge(h);
    if (opt_.validate_each_split) mesh_.validate();
    ++stats_.splits;
    const HalfedgeId fb[3] = {Mesh::halfedge(sr.f_b, 0), Mesh::halfedge(sr.f_b, 1), Mesh::halfedge(sr.f_b, 2)};
    const HalfedgeId ga[3] = {Mesh::halfedge(sr.g_a, 0), Mesh::halfedge(sr.g_a, 1), Mesh::halfedge(sr.g_a, 2)};
    for (EdgeFlags* a : {&blocked_, &matched_, &used_}) {
        if (a == &used_ && used_.empty()) continue;  // before the matching is settled: all clear
        reserve_gently(*a, mesh_.num_halfedges());
        a->resize(mesh_.num_halfedges(), 0);
        (*a)[fb[1]] = (*a)[hn];
        (*a)[ga[1]] = (*a)[tn];
        for (HalfedgeId x : {h, hn, t, tn, fb[0], fb[2], ga[0], ga[2]}) (*a)[x] = 0;
    }
    reserve_gently(vlink_, mesh_.num_faces());
    reserve_gently(quota_, mesh_.num_faces());
    vlink_.resize(mesh_.num_faces(), 0);
    quota_.resize(mesh_.num_faces(), 0);
    if (!sid_.empty()) reserve_gently(sid_, mesh_.num_faces());
    if (!sid_.empty()) sid_.resize(mesh_.num_faces(), sid_[sr.f_a]), sid_[sr.g_a] = sid_[sr.g_b];
    for (uint32_t i = 0; i < num_pins_; ++i) {
        const VertexId v = (i == 0 && !reversed_) ? pin_vertex[0] : pin_vertex[1];
        if (v == kNone) continue;
        const FaceId old = pins_[i];
        if (old == sr.f_a && !face_has_vertex(mesh_, sr.f_a, v))
            pins_[i] = sr.f_b;
        else if (old == sr.g_b && !face_has_vertex(mesh_, sr.g_b, v))
            pins_[i] = sr.g_a;
        if (pins_[i] != old) std::swap(vlink_[old], vlink_[pins_[i]]);  // the virtual link moves along
    }
    return sr;
}

// Matched edges wanted per face: passable edges beyond the two the strip crosses (one crossed
// edge for a pinned face, whose other link is the virtual face).
void MatchingBuilder::set_quotas() {
    const uint32_t nf = mesh_.num_faces();
    vlink_.assign(nf, 0);
    for (uint32_t i = 0; i < num_pins_; ++i) vlink_[pins_[i]] = 1;
    if (num_pins_ == 2 && pins_[0] == pins_[1]) throw InternalError("matching engine: source and target faces coincide");
    quota_.assign(nf, 0);
    for (FaceId f : mesh_.faces()) {
        const int cap = 2 - vlink_[f];
        quota_[f] = static_cast<uint8_t>(std::max(0, static_cast<int>(degree(f)) - cap - num_matched(f)));
    }
}

// Around a vertex of high valence the turn pattern pairs fan faces across their spokes, and each
// pair leaves a small loop through the faces beyond (a cone's apex: one loop per two faces). Fan
// faces matched across their outer edges instead cross every spoke: the fan becomes one loop
// (with a swap per face, as any strip round a fan needs).
void MatchingBuilder::match_fans() {
    IdVector<VertexId, uint32_t> valence(mesh_.num_vertices(), 0);
    for (HalfedgeId h : mesh_.halfedges()) ++valence[mesh_.from(h)];
    for (HalfedgeId h : mesh_.halfedges()) {
        if (valence[mesh_.from(h)] < kFanValence) continue;
        const HalfedgeId outer = Mesh::next(h);
        const FaceId f = Mesh::face(h);
        if (!passable(outer) || matched_[outer] || quota_[f] == 0) continue;
        const FaceId g = across(outer);
        if (quota_[g] == 0) continue;
        set_pair(matched_, outer, 1);
        --quota_[f];
        --quota_[g];
    }
}

// Swaps between faces of two crossed edges each, plus 8 per face left short (the repair of each
// costs about that many: turbine.off, 39 short faces, 894 swaps).
// Each face's crossed edges are read once into three bits: swap_test() on them reads two bytes
// an edge instead of about eight edges' flags.
long MatchingBuilder::pattern_cost(const Pattern& p) const {
    auto crossed = [&](HalfedgeId h) { return passable(h) && !p.matched[h]; };
    IdVector<FaceId, uint8_t> bits(mesh_.num_faces(), 0);
    for (FaceId f : mesh_.faces())
        for (uint32_t k = 0; k < 3; ++k) bits[f] |= static_cast<uint8_t>(crossed(Mesh::halfedge(f, k)) << k);
    auto bit = [&](HalfedgeId h) { return (bits[Mesh::face(h)] >> Mesh::index_in_face(h)) & 1; };
    // Bits set in three bits, by table: std::popcount is a library call without -mpopcnt.
    static constexpr std::array<uint8_t, 8> kOnes = {0, 1, 1, 2, 1, 2, 2, 3};
    auto links = [&](FaceId f) { return kOnes[bits[f]] + vlink_[f]; };
    long cost = 0;
    for (FaceId f : mesh_.faces()) {
        cost += 8 * p.quota[f];
        if (links(f) != 2) continue;
        for (HalfedgeId h : sides(f)) {
            if (!bit(h)) continue;
            const HalfedgeId t = mesh_.twin(h);
            // As swap_test(): f's uncrossed edge touches from(h) iff prev(h) is crossed.
            if (h < t && links(Mesh::face(t)) == 2) cost += bit(Mesh::prev(h)) == bit(Mesh::next(t));
        }
    }
    return cost;
}

// Two orders of the greedy: rows one after the other, or each face's mate queued at once (a
// clean grid pattern, where the first order starts rows in arbitrary turns: knot.off 310 swaps
// against 76). The one with the lower pattern_cost() is kept (rows on a tie). They only read the
// mesh, so on a large mesh the second runs on another thread.
void MatchingBuilder::choose_pattern() {
    Pattern rows{matched_, quota_}, mates{std::move(matched_), std::move(quota_)};
    long cost_rows = 0, cost_mates = 0;
    auto run_mates = [&] {
        match_patterned(true, mates);
        cost_mates = pattern_cost(mates);
    };
    if (mesh_.num_faces() >= kParallelPattern) {
        std::exception_ptr failure;
        std::thread other([&] {
            try {
                run_mates();
            } catch (...) {
                failure = std::current_exception();
            }
        });
        match_patterned(false, rows);
        cost_rows = pattern_cost(rows);
        other.join();
        if (failure) std::rethrow_exception(failure);
    } else {
        match_patterned(false, rows);
        cost_rows = pattern_cost(rows);
        run_mates();
    }
    Pattern& best = cost_mates < cost_rows ? mates : rows;
    matched_ = std::move(best.matched);
    quota_ = std::move(best.quota);
}

// Greedy matching carried face to face in breadth-first order: across a crossed edge (u, v),
// if this face's matched edge touches u, the neighbour's should touch v — then the two turns
// alternate and the GL strip needs no swap there.
void MatchingBuilder::match_patterned(bool mates, Pattern& p) {
    const uint32_t nf = mesh_.num_faces();
    IdVector<FaceId, HalfedgeId> pref(nf, kNone);
    std::vector<FaceId> queue, critical;
    IdVector<FaceId, uint8_t> seen(nf, 0);
    // Karp-Sipser: a face left with one free neighbour takes it at once, before the pattern
    // asks, so few faces are left short (each costs an augmenting path, which breaks the pattern).
    IdVector<FaceId, uint8_t> free_n(nf, 0);
    auto wants = [&](HalfedgeId h) { return passable(h) && !p.matched[h] && p.quota[across(h)] > 0; };
    for (FaceId f : mesh_.faces())
        if (p.quota[f] > 0)
            for (HalfedgeId h : sides(f)) free_n[f] += wants(h);
    for (FaceId f : mesh_.faces())
        if (p.quota[f] > 0 && free_n[f] == 1) critical.push_back(f);
    auto match = [&](HalfedgeId h) {
        set_pair(p.matched, h, 1);
        for (FaceId x : {Mesh::face(h), across(h)}) {
            if (--p.quota[x] > 0) continue;
            for (HalfedgeId e : sides(x)) {
                if (!passable(e)) continue;
                const FaceId y = across(e);
                if (p.quota[y] > 0 && free_n[y] > 0 && --free_n[y] == 1) critical.push_back(y);
            }
        }
    };
    auto drain = [&] {
        while (!critical.empty()) {
            const FaceId x = critical.back();
            critical.pop_back();
            for (uint32_t k = 0; k < 3 && p.quota[x] > 0; ++k)
                if (wants(Mesh::halfedge(x, k))) match(Mesh::halfedge(x, k));
        }
    };
    drain();
    queue.reserve(nf);
    size_t credit = size_t{nf} / 4 + 3 * kBandProbe;  // seed_direction()'s steps, O(F) in all
    for (FaceId s : mesh_.faces()) {
        if (seen[s]) continue;
        seen[s] = 1;
        if (p.quota[s] == 1 && pref[s] == kNone) pref[s] = seed_direction(s, credit);
        queue.assign(1, s);
        for (size_t head = 0; head < queue.size(); ++head) {
            const FaceId f = queue[head];
            // The preferred edge first, then on round the face.
            HalfedgeId h = pref[f] != kNone ? pref[f] : Mesh::halfedge(f, 0);
            for (uint32_t i = 0; i < 3 && p.quota[f] > 0; ++i, h = Mesh::next(h))
                if (wants(h)) match(h), drain();
            HalfedgeId m = kNone;  // the edge this face does not cross
            for (HalfedgeId e : sides(f))
                if (p.matched[e] || !passable(e)) m = e;
            for (HalfedgeId e : sides(f)) {
                if (mates && passable(e) && p.matched[e] && !seen[across(e)]) {  // the mate's row next
                    seen[across(e)] = 1;
                    queue.push_back(across(e));
                }
                if (!passable(e) || p.matched[e]) continue;
                const FaceId g = across(e);
                if (seen[g]) continue;
                seen[g] = 1;
                queue.push_back(g);
                if (const HalfedgeId a = alternate(m, e); a != kNone) pref[g] = a;
            }
        }
    }
}

// The matched edge for a seed face of the greedy (kNone: the first free one, as any other face).
// The pattern propagates from the seed in zigzag bands, one per choice of its matched edge. Where
// the first choice's band is a short loop and another's is at least 8 times as long without
// closing over itself (or runs past kBandProbe faces), the short loops would each need a join (a
// torus 8 faces round and 10,000 long: 10,000 loops around it at two swaps each, 1.125 GL
// indices a triangle; along it, 8 loops and 1.000). Elsewhere the first choice stays: a band that
// ends early says little, and one that closes after winding over itself neither (spool.off, a
// surface of revolution: taking such a band, 1.0966 -> 1.1762).
HalfedgeId MatchingBuilder::seed_direction(FaceId s, size_t& credit) const {
    if (degree(s) != 3 || vlink_[s] != 0 || credit < 3 * kBandProbe) return kNone;
    Band band[3];
    for (uint32_t k = 0; k < 3; ++k) {
        band[k] = follow_band(s, Mesh::halfedge(s, k));
        credit -= band[k].faces;
    }
    if (!band[0].loop || band[0].faces > kBandProbe / 8) return kNone;
    auto score = [&](uint32_t k) { return band[k].faces >= kBandProbe || (band[k].loop && !band[k].crossed) ? band[k].faces : 0; };
    const uint32_t best = score(1) >= score(2) ? 1 : 2;
    return score(best) >= 8 * band[0].faces ? Mesh::halfedge(s, best) : HalfedgeId(kNone);
}

// The band through s when its matched edge is m (at most kBandProbe faces): across each crossed
// edge the next face's matched edge follows match_patterned()'s alternation rule, until the band
// reaches a face without three passable edges or comes back to s (a loop); `crossed` if it met
// one of its faces again on the way.
MatchingBuilder::Band MatchingBuilder::follow_band(FaceId s, HalfedgeId m) const {
    Band band;
    // The faces met, in an open-addressing table a quarter full at most, sized for the mesh (a
    // full-size one per tetrahedron: 42% of stripping 250,000; a node-based set: 2% of libcgal-demo).
    static_assert((kBandProbe & (kBandProbe - 1)) == 0, "the table's mask needs a power of two");
    const uint32_t slots = 4 * std::min(kBandProbe, std::bit_ceil(mesh_.num_faces() + 1)), kEmpty = ~0u;
    std::vector<uint32_t> table(slots, kEmpty);
    auto insert = [&, shift = 32 - std::countr_zero(slots)](uint32_t x) {  // false if x was in already
        for (uint32_t i = (x * 2654435761u) >> shift;; i = (i + 1) & (slots - 1)) {
            if (table[i] == x) return false;
            if (table[i] == kEmpty) return table[i] = x, true;
        }
    };
    insert(s.idx());
    for (HalfedgeId first : sides(s)) {
        if (first == m) continue;
        HalfedgeId mf = m, e = first;
        while (band.faces < kBandProbe && passable(e)) {
            const HalfedgeId t = mesh_.twin(e);
            const FaceId g = Mesh::face(t);
            if (g == s) return Band{band.faces, true, band.crossed};
            if (degree(g) != 3) break;
            band.crossed |= !insert(g.idx());
            mf = alternate(mf, e);
            e = mf == Mesh::next(t) ? Mesh::prev(t) : Mesh::next(t);
            ++band.faces;
        }
    }
    return band;
}

// The faces in strip order: from the first pinned face, else (loop mode) around the loop from a
// face of the pin, else from a path end, else around the loop from face 0. Plain face indices,
// as StripResult::order holds them.
std::vector<uint32_t> MatchingBuilder::walk(uint32_t& swaps) const {
    const uint32_t nf = mesh_.num_faces();
    FaceId start = num_pins_ ? pins_[0] : loop_mode_ ? loop_start() : FaceId(kNone);
    HalfedgeId in = kNone;
    if (loop_mode_)
        for (HalfedgeId h : sides(start))
            if (used_[h]) in = h;
    for (FaceId f : mesh_.faces()) {
        if (start != kNone) break;
        if (hdeg(f) < 2) start = f;
    }
    if (start == kNone) {  // one loop: cut it at face 0, as if entered by one of its crossed edges
        start = FaceId(0);
        for (HalfedgeId h : sides(start))
            if (used_[h]) in = h;
    }
    std::vector<uint32_t> order;
    order.reserve(nf);
    swaps = 0;  // as count_swaps(), from the edges crossed on the way (no search for them)
    int prev_turn = 0;
    for (FaceId f = start; order.size() < nf;) {
        order.push_back(f.idx());
        const HalfedgeId out = next_crossed(f, in);
        if (out == kNone || across(out) == start) break;
        if (order.size() > 1 && order.size() < nf) {  // a turn between two strip faces
            const int turn = out == Mesh::next(in) ? +1 : -1;
            swaps += turn == prev_turn ? 1 : 0;
            prev_turn = turn;
        }
        in = mesh_.twin(out);
        f = Mesh::face(in);
    }
    return order;
}

StripResult MatchingBuilder::finish(std::vector<uint32_t> order, uint32_t swaps) {
    const uint32_t nf = mesh_.num_faces();
    if (order.size() != nf)
        throw InternalError("matching engine: strip covers " + std::to_string(order.size()) + " of " + std::to_string(nf) + " faces");
    if (num_pins_ == 2 && order.back() != pins_[1].idx()) throw InternalError("matching engine: strip does not end at the target face");
    if (reversed_) std::reverse(order.begin(), order.end());
    stats_.swaps = swaps;  // the same read backwards: every turn changes side
    stats_.output_triangles = nf;
    StripResult result;
    result.order = std::move(order);
    result.stats = stats_;
    result.mesh = std::move(mesh_);
    return result;
}

// Before the growth builder runs: the matching's arrays are done with (the growth builder's
// own and a second mesh would otherwise sit beside them at the peak).
void MatchingBuilder::release_work_arrays() noexcept {
    blocked_.reset(), matched_.reset(), used_.reset(), vlink_.reset(), quota_.reset(), sid_.reset();
    uf_.reset(), cycle_.reset(), pinned_.reset(), ch_stamp_.reset(), ball_local_.reset(), ball_whole_.reset();
    aug_prev_.reset(), aug_step_.reset();
    release_blossom_arrays();
}

// The growth builder on `mesh` (the input or a partly split copy that already cost `splits`);
// an empty result when it fails (a broken precondition on a partly split mesh) or, against a
// strip of beat_splits_ splits, once it defers more than twice the islands it could split and
// still win: detours splice islands in for free, but on libcgal-demo at most 26% of them.
StripResult MatchingBuilder::grow(Mesh mesh, uint32_t splits) const {
    StripOptions o = opt_;
    o.engine = StripEngine::Growth;
    if (o.seed_face && o.source && !face_has_vertex(mesh, *o.seed_face, *o.source)) o.seed_face.reset();
    if (beat_splits_ != kNoBound && splits > beat_splits_) return StripResult{};
    const uint32_t bound = beat_splits_ == kNoBound ? kNoBound : 2 * (beat_splits_ - splits) + kDeferSlack;
    try {
        StripResult r = growth::build_strip_growth_bounded(std::move(mesh), o, bound);
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
    for (uint32_t i = 0; i < pre_merge_splits_; ++i) pre.split_edge(split_log_[i]);
    return pre;
}

// Two growth runs, on two threads when the mesh is large enough to gain and small enough that
// two builders at once (about 60 bytes a face each) stay far from issue 17's memory bound.
std::pair<StripResult, StripResult> MatchingBuilder::grow_two(Mesh a, uint32_t splits_a, Mesh b, uint32_t splits_b) const {
    const uint32_t nf = std::max(a.num_faces(), b.num_faces());
    if (nf < kParallelPattern || nf > kParallelGrowMax) {
        StripResult ra = grow(std::move(a), splits_a);
        return {std::move(ra), grow(std::move(b), splits_b)};
    }
    StripResult ra;
    std::exception_ptr failure;
    std::thread other([&] {
        try {
            ra = grow(std::move(a), splits_a);
        } catch (...) {
            failure = std::current_exception();
        }
    });
    StripResult rb;
    try {
        rb = grow(std::move(b), splits_b);
    } catch (...) {
        other.join();
        throw;
    }
    other.join();
    if (failure) std::rethrow_exception(failure);
    return {std::move(ra), std::move(rb)};
}

// Not one strip (paths whose ends never touch): the growth builder, which always ends in one
// strip, finishes on the mesh as split so far.
StripResult MatchingBuilder::fallback(bool split_mesh_too) {
    // The input mesh is a candidate too: the engine's splits (ears, bridges, parity) can cost the
    // growth builder more than they save (boeing.off's small parts: +90% against +26%).
    Mesh original = input_mesh();  // before mesh_ is handed over
    release_work_arrays();
    StripResult r;
    if (split_mesh_too && pre_merge_) {          // the mesh as split so far, and without the joins' splits
        Mesh before = pre_merge_mesh(original);  // built before mesh_ is moved (arguments have no order)
        auto [split, before_joins] = grow_two(std::move(mesh_), stats_.splits, std::move(before), pre_merge_splits_);
        keep_better(r, std::move(split));
        keep_better(r, std::move(before_joins));
    } else if (split_mesh_too) {
        keep_better(r, grow(std::move(mesh_), stats_.splits));
    }
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
// against +3.44%). Not below 1% extra: there the growth builder hardly ever wins (libcgal-demo:
// +10 to +17% where the engine had under +1%), and on a grid with a hole every 70 x 70 cells it
// cost a fifth of the stage and grew faster than the mesh (docs/algorithm.md, step 9). Above,
// the growth runs give up once they cannot win (grow()).
StripResult MatchingBuilder::finish_or_grow(std::vector<uint32_t> order, uint32_t swaps) {
    if (stats_.parity_splits == 0 || !growth_may_win()) return finish(std::move(order), swaps);
    Mesh original = input_mesh();
    StripResult r = finish(std::move(order), swaps);
    beat_splits_ = r.stats.splits;
    release_work_arrays();
    StripResult g;
    if (chain_splits_ && pre_merge_) {
        Mesh before = pre_merge_mesh(original);  // built before original is moved (arguments have no order)
        auto [before_chains, plain] = grow_two(std::move(before), pre_merge_splits_, std::move(original), 0);
        keep_better(g, std::move(before_chains));
        keep_better(g, std::move(plain));
    } else {
        keep_better(g, grow(std::move(original), 0));
    }
    if (g.order.empty()) return r;
    return cost(g) < cost(r) ? as_fallback(std::move(g)) : r;
}

// Whether the growth builder can beat the strip as split now by kGrowthWorthPercent: the splits
// any single strip needs for the dual graph's bridges are no margin (ears 1M: +66.7%, all of it
// forced; the growth candidate was a third of the strip stage and never won).
bool MatchingBuilder::growth_may_win() const {
    const uint64_t extra = uint64_t{mesh_.num_faces()} - stats_.input_triangles;
    const uint64_t forced = 2 * uint64_t{forced_splits_};
    return (extra - std::min(extra, forced)) * 100 >= kGrowthWorthPercent * uint64_t{stats_.input_triangles};
}

// The bridges force splits on more than half the faces (+100% triangles): the dual graph is
// mostly a tree, with no loops to match, and the engine's repair ended in the growth fallback
// anyway (a random triangulation of a polygon, 1M: 14.6 s against 1.4 s; spiked_comb: +200%
// against the fallback's +146.7%): the growth builder on the input, whose splits there are the
// fewest (ears and bridges split first cost it time, not triangles). Ears alone force +66.7% at
// most (two a face).
bool MatchingBuilder::mostly_tree() const {
    return uint64_t{2} * forced_splits_ > stats_.input_triangles;
}

// A tree of faces has many leaves (ears): a random triangulation of a polygon a third of its
// faces. There the bridges are counted on the input, before the ears are split (then undone by
// rebuilding the input: 1M, 2.6 s against the growth builder's 1.3).
bool MatchingBuilder::many_ears() const {
    if (!may_have_bridges()) return false;
    uint32_t ears = 0;
    for (FaceId f : mesh_.faces()) ears += degree(f) == 1;
    return uint64_t{8} * ears >= mesh_.num_faces();
}

bool MatchingBuilder::mostly_tree_before_splits() {
    const DualBridges b = dual_bridges();
    forced_splits_ = b.all - std::min(b.all, b.on_one_path);
    return mostly_tree();
}

StripResult MatchingBuilder::grow_unsplit() {
    release_work_arrays();
    StripOptions o = opt_;
    o.engine = StripEngine::Growth;
    return as_fallback(build_strip_growth(std::move(mesh_), o));
}

// The input mesh again (input vertices keep their positions; midpoints come after them).
Mesh MatchingBuilder::input_mesh() const {
    TriangleSoup soup;
    soup.points.assign(mesh_.points().begin(), mesh_.points().begin() + mesh_.num_input_vertices());
    soup.triangles.resize(mesh_.num_input_faces());
    for (FaceId f : IdRange<FaceId>(mesh_.num_input_faces()))
        for (uint32_t k = 0; k < 3; ++k) soup.triangles[f.idx()][k] = mesh_.from(Mesh::halfedge(f, k)).idx();
    for (auto it = overwritten_.rbegin(); it != overwritten_.rend(); ++it) {
        const auto [corner, vertex] = *it;
        soup.triangles[Mesh::face(corner).idx()][Mesh::index_in_face(corner)] = vertex.idx();
    }
    return Mesh::from_soup(std::move(soup));
}

// The fewest-swap paths of step 6 leave a few more faces for the searches that do not always
// succeed (random constraints with source and target: 14 growth fallbacks in 232 cases against
// 11 with plain paths); before the growth builder, the engine runs again with plain paths.
StripResult MatchingBuilder::retry_or_fallback() {
    if (loop_mode_) return rerun(plain_paths_, true);
    if (plain_paths_) return fallback();
    return rerun(true, pinned_only_);
}

// The engine again on the input, with these settings; this one's arrays are given back first.
StripResult MatchingBuilder::rerun(bool plain_paths, bool pinned_only) {
    MatchingBuilder again(input_mesh(), opt_);
    again.plain_paths_ = plain_paths;
    again.pinned_only_ = pinned_only;
    release_work_arrays();
    mesh_ = Mesh();
    return again.run();
}

StripResult MatchingBuilder::run() {
    const uint32_t nf = mesh_.num_faces();
    check_strip_request(mesh_, opt_);
    blocked_ = constraint_halfedges(mesh_, opt_);
    stats_.input_triangles = nf;
    stats_.boundary_loops = mesh_.num_boundary_loops();
    stats_.genus = genus_from_euler(mesh_.euler_characteristic(), stats_.boundary_loops, 1);  // loops counted once
    stats_.engine = StripEngine::Matching;
    matched_.assign(mesh_.num_halfedges(), 0);
    used_.reset();
    vlink_.assign(nf, 0);
    quota_.assign(nf, 0);
    choose_pins();
    // One pin: the strip starts (or, a target, ends) there and ends anywhere. Built first as one
    // loop with no pin, cut at a face of the pin: a pinned face left the matching one short face
    // (the free end) that the repair cannot place, and the growth builder then finished (a source
    // inside an annulus: +7% against +0.1%).
    if (num_pins_ == 1 && !pinned_only_) {
        loop_mode_ = true;
        loop_pin_ = opt_.seed_face ? pins_[0] : FaceId(kNone);
        pins_[0] = kNone;
        num_pins_ = 0;
    }
    if (stats_.splits == 0 && many_ears() && mostly_tree_before_splits()) return grow_unsplit();  // no pin split
    split_ears();
    split_bridges();
    if (mostly_tree()) return fallback(false);
    set_quotas();
    match_fans();
    choose_pattern();
    settle_leftovers();
    label_structures();
    reduce_loops();
    absorb_loops();
    merge_all();
    if (opt_.validate_each_split) mesh_.validate();
    if (!single_strip_ready() || stats_.splits > stats_.input_triangles) return retry_or_fallback();
    if (loop_mode_ && !cycle_[find(StructId(0))]) return rerun(plain_paths_, true);  // no loop to cut: pinned
    uint32_t swaps = 0;
    std::vector<uint32_t> order = walk(swaps);
    if (order.size() != mesh_.num_faces() || (num_pins_ == 2 && order.back() != pins_[1].idx())) return retry_or_fallback();
    return finish_or_grow(std::move(order), swaps);
}

}  // namespace singlestrip::matching

namespace singlestrip {

StripResult build_strip_matching(Mesh mesh, const StripOptions& options) {
    matching::MatchingBuilder builder(std::move(mesh), options);
    return builder.run();
}

}  // namespace singlestrip
