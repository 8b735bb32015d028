// singlestrip — internal: the three half-edges of a face as a range, so a loop over a face's
// sides names no corner arithmetic (3 * f + k).
#pragma once

#include <cstdint>

#include "singlestrip/mesh.hpp"

namespace singlestrip {

/// The three half-edges of face f (k = 0, 1, 2): `for (HalfedgeId h : sides(f))`.
class Sides {
public:
    class iterator {
    public:
        constexpr iterator(FaceId f, uint32_t k) noexcept : f_(f), k_(k) {}
        HalfedgeId operator*() const noexcept { return Mesh::halfedge(f_, k_); }
        constexpr iterator& operator++() noexcept {
            ++k_;
            return *this;
        }
        // Both ends of a loop are of one face: k alone tells them apart (and lets loops unroll).
        friend constexpr bool operator==(iterator a, iterator b) noexcept { return a.k_ == b.k_; }

    private:
        FaceId f_;
        uint32_t k_;
    };
    constexpr explicit Sides(FaceId f) noexcept : f_(f) {}
    [[nodiscard]] constexpr iterator begin() const noexcept { return {f_, 0}; }
    [[nodiscard]] constexpr iterator end() const noexcept { return {f_, 3}; }

private:
    FaceId f_;
};
[[nodiscard]] constexpr Sides sides(FaceId f) noexcept {
    return Sides(f);
}

}  // namespace singlestrip
