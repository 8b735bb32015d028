// singlestrip bench — parameters of the generated families (sizes near 10K, 100K, 1M, ...).
#include "families.hpp"

#include <cmath>

#include "scaling.hpp"
#include "singlestrip/generators.hpp"

namespace singlestrip::bench {

std::vector<Family> scaling_families() {
    using S = Generated;
    auto sphere = [](uint32_t n) { return [n]() -> S { return {make_geodesic_sphere(n), {}}; }; };
    auto torus = [](uint32_t a, uint32_t b) { return [a, b]() -> S { return {make_torus(a, b), {}}; }; };
    auto genus = [](uint32_t r) { return [r]() -> S { return {make_genus_surface(20, r), {}}; }; };
    auto holes = [](uint32_t r) { return [r]() -> S { return {make_disk_with_holes(1000, r), {}}; }; };
    return {
        {"sphere",
         {{10000, sphere(22)}, {100000, sphere(71)}, {1000000, sphere(224)}, {4000000, sphere(447)}, {10000000, sphere(707)}},
         true},
        {"torus",
         {{10000, torus(100, 50)},
          {100000, torus(316, 158)},
          {1000000, torus(1000, 500)},
          {4000000, torus(2000, 1000)},
          {10000000, torus(3162, 1581)}}},
        {"genus20", {{10000, genus(5)}, {100000, genus(15)}, {1000000, genus(49)}, {4000000, genus(98)}, {10000000, genus(155)}}},
        {"holes1000", {{10000, holes(1)}, {100000, holes(3)}, {1000000, holes(10)}, {4000000, holes(20)}, {10000000, holes(32)}}},
    };
}

std::vector<Family> awkward_families() {
    using S = Generated;
    const std::vector<uint64_t> sizes = {10000, 100000, 1000000};
    auto family = [&](std::string name, std::function<S(uint64_t)> make) {
        Family f{std::move(name), {}, false, false};
        for (const uint64_t n : sizes) f.sizes.push_back({n, [make, n] { return make(n); }});
        return f;
    };
    return {
        // k unit holes in a row, one quad apart: corridors one quad wide (F = 10k + 6).
        family("corridors",
               [](uint64_t n) {
                   return S{make_disk_with_holes(static_cast<uint32_t>(n / 10), 1), {}};
               }),
        // A square grid with one single-triangle hole per 200 triangles.
        family("smallholes",
               [](uint64_t n) {
                   const auto side = static_cast<uint32_t>(std::lround(std::sqrt(double(n) / 2)));
                   S s{make_grid_disk(side, side), {}};
                   remove_random_faces_as_holes(s.soup, s.soup.triangles.size() / 200, 7);
                   return s;
               }),
        // One vertex of valence n.
        family("fan",
               [](uint64_t n) {
                   return S{make_fan(static_cast<uint32_t>(n)), {}};
               }),
    };
}

}  // namespace singlestrip::bench
