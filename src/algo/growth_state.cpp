// singlestrip — the growth builder's bookkeeping: per-face and per-half-edge arrays, region
// labels and Betti numbers, the doubly linked strip, chi of a face set, and midpoint splits that
// keep all of it in step (growth_builder.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "core/gentle_growth.hpp"
#include "growth_builder.hpp"
#include "singlestrip/errors.hpp"

namespace singlestrip::growth {

void Builder::grow_arrays(uint32_t spare_faces) {
    // Gently: splits add a few percent, and doubling 11 arrays would add up to 34 bytes a face.
    auto fit = [](auto& v, uint32_t n, uint32_t spare, auto value) {
        reserve_gently(v, size_t{n} + spare);
        v.resize(n, value);
    };
    const uint32_t nf = mesh_.num_faces(), nh = mesh_.num_halfedges(), nv = mesh_.num_vertices();
    const uint32_t sf = spare_faces, sh = 3 * spare_faces, sv = spare_faces / 2;
    fit(striped_, nf, sf, 0);
    fit(region_, nf, sf, kNone);
    fit(next_, nf, sf, kNone);
    fit(prev_, nf, sf, kNone);
    fit(stamp_, nf, sf, 0);
    fit(fundamental_, nf, sf, 0);
    fit(time_, nf, sf, kNone);
    fit(blocked_, nh, sh, 0);
    fit(vstamp_, nv, sv, 0);
    fit(striped_at_, nv, sv, 0);
    fit(rim_, nv, sv, 0);
}

void Builder::count_striped(FaceId f, int delta) {
    for (const HalfedgeId h : sides(f)) striped_at_[mesh_.from(h)] += static_cast<uint32_t>(delta);
}

// chi of a set of open faces of region r: F - (passable edges inside) + (vertices whose whole
// fan lies in the region through passable edges). Derivation in docs/algorithm.md. O(|faces|).
long long Builder::chi_of(const std::vector<FaceId>& faces, RegionId r) {
    ++vstamp_base_;
    long long inner_halfedges = 0, interior_vertices = 0;
    for (const FaceId f : faces) {
        for (const HalfedgeId h : sides(f)) {
            inner_halfedges += open_neighbor(h, r) != kNone;
            const VertexId v = mesh_.from(h);
            if (vstamp_[v] == vstamp_base_) continue;
            vstamp_[v] = vstamp_base_;
            // Interior: rotating around v never leaves the region nor crosses a blocked edge.
            HalfedgeId g = h;
            bool interior = true;
            do {
                const HalfedgeId e = Mesh::prev(g);
                if (!passable(e) || !in_region(Mesh::face(g), r)) {
                    interior = false;
                    break;
                }
                g = mesh_.twin(e);
            } while (g != h);
            interior_vertices += interior;
        }
    }
    return static_cast<long long>(faces.size()) - inner_halfedges / 2 + interior_vertices;
}

RegionId Builder::new_region(uint32_t size) {
    region_size_.push_back(size);
    region_beta_.push_back(0);
    deferred_of_region_.push_back(kNone);
    return RegionId(static_cast<uint32_t>(region_size_.size() - 1));
}

void Builder::insert_after(FaceId cursor, FaceId f) {
    if (cursor == kNone) {
        next_[f] = head_;
        prev_[f] = kNone;
        if (head_ != kNone) prev_[head_] = f;
        head_ = f;
        if (tail_ == kNone) tail_ = f;
        return;
    }
    const FaceId nx = next_[cursor];
    next_[cursor] = f;
    prev_[f] = cursor;
    next_[f] = nx;
    if (nx != kNone)
        prev_[nx] = f;
    else
        tail_ = f;
}

void Builder::take(FaceId cursor, FaceId f) {
    if (striped_[f]) throw InternalError("strip builder: face " + std::to_string(f.idx()) + " taken twice");
    striped_[f] = 1;
    count_striped(f, +1);
    time_[f] = clock_++;
    scan_credit_ += kScanCreditPerFace;
    --region_size_[region_[f]];
    insert_after(cursor, f);
}

void Builder::note_fundamental(FaceId f, RegionId r) {
    fundamental_[f] = 1;
    ++stats_.fundamental_triangles;
    --region_beta_[r];
}

void Builder::defer(RegionId region, HalfedgeId anchor) {
    deferred_of_region_[region] = DeferredId(static_cast<uint32_t>(deferred_.size()));
    deferred_.push_back({region, anchor, false});
    if (++stats_.deferred_regions > max_deferred_) throw OverBound{};
}

// Splits the edge of h at its midpoint, keeping the per-face and per-half-edge state in step.
SplitResult Builder::split_at(HalfedgeId h) {
    // Constraint flags of the two half-edges that split_edge moves into new faces.
    const HalfedgeId t = mesh_.twin(h);
    const HalfedgeId moved_f = Mesh::next(h), moved_g = Mesh::next(t);
    const uint8_t blocked_f = blocked_[moved_f], blocked_g = blocked_[moved_g];
    // The children of a striped face are striped (the host's in absorb()).
    const uint8_t striped_f = striped_[Mesh::face(h)], striped_g = striped_[Mesh::face(t)];
    if (striped_f) count_striped(Mesh::face(h), -1);
    if (striped_g) count_striped(Mesh::face(t), -1);
    const SplitResult s = mesh_.split_edge(h);
    ++stats_.splits;
    check_split_budget();
    grow_arrays();
    striped_[s.f_b] = striped_f;
    striped_[s.g_a] = striped_g;
    for (const FaceId f : {s.f_a, s.f_b, s.g_a, s.g_b})
        if (striped_[f]) count_striped(f, +1);
    blocked_[moved_f] = 0;
    blocked_[moved_g] = 0;
    blocked_[Mesh::halfedge(s.f_b, 1)] = blocked_f;
    blocked_[Mesh::halfedge(s.g_a, 1)] = blocked_g;
    if (opt_.validate_each_split) mesh_.validate();
    return s;
}

void Builder::check_split_budget() const {
    // docs/algorithm.md: splits < input faces (+1 for the target pre-split). Exceeding it means a
    // broken invariant, never a long loop.
    if (stats_.splits > mesh_.num_input_faces() + 1)
        throw InternalError("strip builder: split budget exceeded (" + std::to_string(stats_.splits) + " splits)");
}

}  // namespace singlestrip::growth
