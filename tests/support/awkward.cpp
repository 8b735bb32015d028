// singlestrip — test fixtures: the awkward families (issues 15, 17) by name and size.
#include <algorithm>
#include <cmath>
#include <string>

#include "fixtures.hpp"
#include "singlestrip/errors.hpp"

namespace singlestrip {
namespace {

uint32_t rounded(double x) {
    return static_cast<uint32_t>(std::max(1.0, std::round(x)));
}

}  // namespace

const char* awkward_family_name(AwkwardFamily family) noexcept {
    switch (family) {
        case AwkwardFamily::HoleCorridors:
            return "hole_corridors";
        case AwkwardFamily::SlitCorridors:
            return "slit_corridors";
        case AwkwardFamily::SlitWalls:
            return "slit_walls";
        case AwkwardFamily::SerpentineWalls:
            return "serpentine_walls";
        case AwkwardFamily::ManyHoles:
            return "many_holes";
        case AwkwardFamily::Ears:
            return "ears";
        case AwkwardFamily::OpenCone:
            return "open_cone";
        case AwkwardFamily::ClosedCone:
            return "closed_cone";
        case AwkwardFamily::SpikedComb:
            return "spiked_comb";
        case AwkwardFamily::HoleLadder:
            return "hole_ladder";
        case AwkwardFamily::HighGenus:
            return "high_genus";
        case AwkwardFamily::SparseHoles:
            return "sparse_holes";
        case AwkwardFamily::DiagonalHoles:
            return "diagonal_holes";
        case AwkwardFamily::PolygonTree:
            return "polygon_tree";
    }
    return "unknown";
}

WalledMesh make_awkward(AwkwardFamily family, uint32_t triangles) {
    const double f = std::max<double>(triangles, 1.0);
    switch (family) {
        case AwkwardFamily::HoleCorridors: {
            // F = 2((L+2)(2h+1) - hL) = 2(L(h+1) + 4h + 2); L ~ 2h keeps the grid square.
            const uint32_t h = rounded(std::sqrt(f / 4));
            const uint32_t len = rounded((f / 2 - 4.0 * h - 2) / (h + 1));
            return {make_hole_corridors(h, len), {}};
        }
        case AwkwardFamily::SlitCorridors:
        case AwkwardFamily::SlitWalls: {
            // F = 2(L+2)(s+1).
            const uint32_t rows = rounded(std::sqrt(f / 2));
            const uint32_t len = std::max(2u, rounded(f / (2.0 * rows) - 2));
            if (family == AwkwardFamily::SlitWalls) return make_slit_walls(rows - 1, len);
            return {make_slit_corridors(rows - 1, len), {}};
        }
        case AwkwardFamily::SerpentineWalls: {
            // F = 4L(w+1), grid L x 2(w+1).
            const uint32_t half_rows = rounded(std::sqrt(f / 8));
            return make_serpentine_walls(half_rows - 1, std::max(2u, rounded(f / (4.0 * half_rows))));
        }
        case AwkwardFamily::ManyHoles: {
            const uint32_t by = rounded(std::sqrt(f / 200));  // F ~ 200 bx by
            return {make_disk_many_holes(rounded(f / (200.0 * by)), by), {}};
        }
        case AwkwardFamily::Ears:
            return {make_eared_grid(rounded(f / 12), 4), {}};  // F = 12 nx
        case AwkwardFamily::OpenCone:
            return {make_cone(std::max(3u, rounded(f)), false), {}};
        case AwkwardFamily::ClosedCone:
            return {make_cone(std::max(3u, rounded(f / 4)), true), {}};  // F ~ 4k
        case AwkwardFamily::SpikedComb:
            return {make_spiked_comb(std::max(1u, rounded(f / 15)), 5), {}};  // F = 15 teeth
        case AwkwardFamily::HoleLadder:
            return {make_disk_with_holes(rounded((f - 6) / 10), 1), {}};  // F = 10k + 6
        case AwkwardFamily::HighGenus:
            return {make_genus_surface(std::max(1u, rounded((f - 28) / 36)), 1), {}};  // F = 36g + 28
        case AwkwardFamily::SparseHoles: {
            const uint32_t n = std::max(1u, rounded(std::sqrt(f / 2)));  // F ~ 2 n^2
            return {make_sparse_holes(n, std::clamp(n / 2, 3u, 70u)), {}};
        }
        case AwkwardFamily::DiagonalHoles: {
            const uint32_t n = std::max(1u, rounded(std::sqrt(f / 1.98)));  // F ~ 2 n^2 (1 - 1/100)
            return {make_random_diagonal_holes(n, 10, 1), {}};
        }
        case AwkwardFamily::PolygonTree:
            return {make_circle_polygon(std::max(3u, rounded(f) + 2)), {}};
    }
    throw RequestError("generator: unknown awkward family");
}

}  // namespace singlestrip
