// singlestrip — single-strip builder: the growth engine's run() and its steps (seed, ends, the
// seed's pieces, the finished strip; the method and the builder's other parts in
// growth_builder.hpp), build_strip() choosing the engine, and strip_arrays().
#include "singlestrip/strip.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>

#include "core/topology.hpp"
#include "growth_builder.hpp"
#include "singlestrip/errors.hpp"

namespace singlestrip {

namespace growth {

FaceId Builder::choose_seed() const {
    if (opt_.seed_face) return *opt_.seed_face;
    // Prefer a face with two blocked sides (it has one open neighbour: always safe), then one
    // with one blocked side whose opposite vertex is interior, then any face with a blocked side.
    FaceId best(0);
    int best_score = -1;
    for (const FaceId f : mesh_.faces()) {
        int closed = 0;
        for (const HalfedgeId h : sides(f)) closed += !passable(h);
        const int score = closed >= 3 ? 0 : closed;
        if (score > best_score) {
            best_score = score;
            best = f;
            if (score == 2) break;
        }
    }
    return best;
}

// Per-face state, constraints, the rim flags of the cavity test, the input's statistics, and
// region 0 holding every face.
void Builder::prepare() {
    // Room for splits adding an eighth of the faces (the builder adds 8-17% on real meshes)
    // before any array of ours exists: growing later copies arrays while all of them are live.
    // Reserved pages that no split touches cost address space, not memory.
    const uint32_t spare = mesh_.num_faces() / 8 + 64;
    mesh_.reserve_splits(spare / 2);
    grow_arrays(spare);
    blocked_ = constraint_halfedges(mesh_, opt_);
    for (const HalfedgeId h : mesh_.halfedges())
        if (!passable(h)) rim_[mesh_.from(h)] = rim_[mesh_.to(h)] = 1;
    stats_.input_triangles = mesh_.num_faces();
    stats_.boundary_loops = mesh_.num_boundary_loops();
    stats_.genus = genus_from_euler(mesh_.euler_characteristic(), stats_.boundary_loops, 1);  // loops counted once
    source_ = opt_.source.value_or(kNone);
    target_ = opt_.target.value_or(kNone);
    const RegionId r0 = new_region(mesh_.num_faces());
    region_.assign(region_.size(), r0);
}

// The first face (seed) and the face the strip must end with (dest, kNone without a target).
std::pair<FaceId, FaceId> Builder::choose_ends() {
    const uint32_t nf = mesh_.num_faces();
    FaceId seed = opt_.seed_face ? *opt_.seed_face : opt_.source ? face_at_vertex(*opt_.source, kNone) : choose_seed();
    if (!opt_.target) return {seed, kNone};
    FaceId dest = face_at_vertex(*opt_.target, seed);
    if (dest == seed && nf > 1) {
        // The target's only face is the first face: split it across the edge opposite the
        // target so that both children touch the target; start in one, end in the other.
        HalfedgeId h = Mesh::halfedge(seed, 0);
        while (mesh_.from(h) == target_ || mesh_.to(h) == target_) h = Mesh::next(h);
        if (!passable(h))
            throw RequestError("cannot end at target vertex " + std::to_string(target_.idx()) +
                               ": its only face is the first face of the strip and cannot be split");
        const SplitResult sr = split_at(h);
        const bool a_first = source_ == kNone || has_vertex(sr.f_a, source_);
        seed = a_first ? sr.f_a : sr.f_b;
        dest = a_first ? sr.f_b : sr.f_a;
        for (const FaceId f : {sr.f_b, sr.g_a}) region_[f] = kRegion0;
        region_size_[kRegion0] += 2;
    }
    if (nf == 1) dest = kNone;
    return {seed, dest};
}

// chi of the whole surface (through passable edges) before anything is taken: chi_of() of every
// face, where an interior vertex is one off the rim (a flat pass, no walk around the vertices).
long long Builder::surface_chi() const {
    long long passable_halfedges = 0, interior_vertices = 0;
    for (const HalfedgeId h : mesh_.halfedges()) passable_halfedges += passable(h);
    for (const VertexId v : mesh_.vertices()) interior_vertices += mesh_.vertex_halfedge(v) != kNone && !rim_[v];
    return static_cast<long long>(mesh_.num_faces()) - passable_halfedges / 2 + interior_vertices;
}

// Marks (stamp_base_) the faces of region 0 reachable from f without crossing striped faces.
void Builder::mark_piece(FaceId f) {
    stamp_base_ += 2;
    stamp_[f] = stamp_base_;
    scratch_.assign(1, f);
    while (!scratch_.empty()) {
        const FaceId x = scratch_.back();
        scratch_.pop_back();
        for (const HalfedgeId h : sides(x)) {
            const FaceId g = open_neighbor(h, kRegion0);
            if (g != kNone && stamp_[g] != stamp_base_) {
                stamp_[g] = stamp_base_;
                scratch_.push_back(g);
            }
        }
    }
}

// Moves the piece of region 0 holding f (not connected to the first piece) to a new region.
RegionId Builder::relabel_piece(FaceId f) {
    const RegionId r = new_region(0);
    region_[f] = r;
    scratch_.assign(1, f);
    while (!scratch_.empty()) {
        const FaceId x = scratch_.back();
        scratch_.pop_back();
        ++region_size_[r];
        --region_size_[kRegion0];
        for (const HalfedgeId h : sides(x)) {
            const FaceId g = open_neighbor(h, kRegion0);
            if (g != kNone) {
                region_[g] = r;
                scratch_.push_back(g);
            }
        }
    }
    return r;
}

// The seed (already taken) may cut U apart, into up to three pieces: labels each piece, sets
// their Betti numbers, notes the seed as fundamental if it lowered the total (a face joining
// two boundary loops, paper Fig. 4), defers every piece but the one to grow (the destination's,
// or the first), anchored at the seed. Returns the region to grow. chi_all: surface_chi().
RegionId Builder::split_at_seed(FaceId seed, FaceId dest, long long chi_all) {
    const long long beta_all = 1 - chi_all;
    FaceId nbr[3];
    HalfedgeId arm[3];
    uint32_t cnt = 0;
    for (const HalfedgeId h : sides(seed)) {
        const FaceId g = open_neighbor(h, kRegion0);
        if (g != kNone) {
            nbr[cnt] = g;
            arm[cnt++] = h;
        }
    }
    if (cnt <= 1) {
        // One piece: chi_of() of every face but the seed, from chi_all without another pass. The
        // seed takes one face and its cnt passable edges away, and its vertices off the rim are
        // no longer interior (their fans hold a striped face). Beta cannot drop: not fundamental.
        if (cnt == 0) return kRegion0;
        long long interior = 0;
        for (const HalfedgeId h : sides(seed)) interior += !rim_[mesh_.from(h)];
        region_beta_[kRegion0] = beta_all + 1 - cnt + interior;
        if (opt_.validate_each_split) {  // tests: the same by chi_of() and a walk around every vertex
            std::vector<FaceId> rest;
            for (const FaceId f : mesh_.faces())
                if (!striped_[f]) rest.push_back(f);
            if (region_beta_[kRegion0] != 1 - chi_of(rest, kRegion0))
                throw InternalError("strip builder: Betti number after the seed is wrong");
        }
        return kRegion0;
    }
    RegionId piece_region[3] = {kRegion0, kNone, kNone};
    for (uint32_t i = 1; i < cnt; ++i) {
        if (i == 1) mark_piece(nbr[0]);  // the first neighbour's piece keeps region 0
        if (stamp_[nbr[i]] == stamp_base_)
            piece_region[i] = kRegion0;
        else if (region_[nbr[i]] != kRegion0)  // relabelled with an earlier neighbour
            piece_region[i] = region_[nbr[i]];
        else
            piece_region[i] = relabel_piece(nbr[i]);
    }
    // Each piece's faces (of a target pre-split too), sized first: the lists hold every face.
    IdVector<RegionId, uint32_t> count(region_size_.size(), 0);
    for (const FaceId f : mesh_.faces())
        if (!striped_[f]) ++count[region_[f]];
    IdVector<RegionId, std::vector<FaceId>> members(region_size_.size(), {});
    for (const RegionId r : IdRange<RegionId>(static_cast<uint32_t>(members.size()))) members[r].reserve(count[r]);
    for (const FaceId f : mesh_.faces())
        if (!striped_[f]) members[region_[f]].push_back(f);
    long long beta_pieces = 0;
    for (const RegionId r : IdRange<RegionId>(static_cast<uint32_t>(members.size()))) {
        if (members[r].empty()) continue;
        region_beta_[r] = 1 - chi_of(members[r], r);
        beta_pieces += region_beta_[r];
    }
    if (beta_all > beta_pieces) {
        fundamental_[seed] = 1;
        stats_.fundamental_triangles += static_cast<uint32_t>(beta_all - beta_pieces);
    }
    const RegionId grow_region = dest != kNone ? region_[dest] : kRegion0;
    std::vector<RegionId> done_regions{grow_region};
    for (uint32_t i = 0; i < cnt; ++i) {
        const RegionId r = piece_region[i];
        if (std::find(done_regions.begin(), done_regions.end(), r) != done_regions.end()) continue;
        done_regions.push_back(r);
        defer(r, mesh_.twin(arm[i]));
    }
    return grow_region;
}

// The strip's faces in order, the positions of fundamental triangles, and the swap count.
StripResult Builder::finish() {
    StripResult result;
    result.order.reserve(mesh_.num_faces());
    for (FaceId f = head_; f != kNone; f = next_[f]) {
        if (result.order.size() > mesh_.num_faces()) throw InternalError("strip builder: strip list has a cycle");
        if (fundamental_[f]) result.fundamental_positions.push_back(static_cast<uint32_t>(result.order.size()));
        result.order.push_back(f.idx());
    }
    if (result.order.size() != mesh_.num_faces())
        throw InternalError("strip builder: strip covers " + std::to_string(result.order.size()) + " of " +
                            std::to_string(mesh_.num_faces()) + " faces");
    stats_.swaps += count_swaps(mesh_, result.order);
    stats_.output_triangles = mesh_.num_faces();
    result.stats = stats_;
    result.take_time = std::move(time_).release();
    result.mesh = std::move(mesh_);
    return result;
}

StripResult Builder::run() {
    check_strip_request(mesh_, opt_);
    prepare();
    const auto [seed, dest] = choose_ends();
    const long long chi_all = surface_chi();
    if (opt_.validate_each_split) {  // tests: the same by chi_of()
        std::vector<FaceId> all;
        for (const FaceId f : mesh_.faces()) all.push_back(f);
        if (chi_all != chi_of(all, kRegion0)) throw InternalError("strip builder: chi of the surface is wrong");
    }
    take(kNone, seed);
    const RegionId region = split_at_seed(seed, dest, chi_all);
    grow(seed, region, dest);
    absorb_all();
    return finish();
}

StripResult build_strip_growth_bounded(Mesh mesh, const StripOptions& options, uint32_t max_deferred) {
    try {
        Builder builder(std::move(mesh), options, max_deferred);
        StripResult r = builder.run();
        r.stats.engine = StripEngine::Growth;
        return r;
    } catch (const OverBound&) {
        return StripResult{};
    }
}

}  // namespace growth

StripResult build_strip_growth(Mesh mesh, const StripOptions& options) {
    return growth::build_strip_growth_bounded(std::move(mesh), options, UINT32_MAX);  // never over the bound
}

StripResult build_strip(Mesh mesh, const StripOptions& options) {
    // One strip covers one edge-connected piece; the engines' invariants assume it.
    if (const uint32_t parts = mesh.num_components(); parts > 1)
        throw RequestError("the mesh has " + std::to_string(parts) +
                           " edge-connected components; build_strip() strips one (stripify() strips each)");
    return build_strip_connected(std::move(mesh), options);
}

StripResult build_strip_connected(Mesh mesh, const StripOptions& options) {
    return options.engine == StripEngine::Growth ? build_strip_growth(std::move(mesh), options)
                                                 : build_strip_matching(std::move(mesh), options);
}

const char* engine_name(StripEngine engine) noexcept {
    return engine == StripEngine::Growth ? "growth" : "matching";
}

std::optional<StripEngine> parse_engine(std::string_view name) noexcept {
    if (name == "matching") return StripEngine::Matching;
    if (name == "growth") return StripEngine::Growth;
    return std::nullopt;
}

namespace {

/// The faces in strip order and their input faces (the points are the caller's to copy or move).
StripArrays faces_in_order(const StripResult& result) {
    StripArrays out;
    out.faces.reserve(result.order.size());
    out.parent.reserve(result.order.size());
    const auto& cv = result.mesh.corner_vertices();
    for (const uint32_t f : result.order) {
        out.faces.push_back({cv[3 * f], cv[3 * f + 1], cv[3 * f + 2]});
        out.parent.push_back(result.mesh.parent(FaceId(f)).idx());
    }
    return out;
}

}  // namespace

StripArrays strip_arrays(const StripResult& result) {
    StripArrays out = faces_in_order(result);
    out.points = result.mesh.points();
    return out;
}

StripArrays strip_arrays(StripResult&& result) {
    StripArrays out = faces_in_order(result);
    out.points = std::move(result.mesh).release_points();
    StripResult kept;
    kept.stats = result.stats;
    result = std::move(kept);
    return out;
}

}  // namespace singlestrip
