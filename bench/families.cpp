// singlestrip bench — parameters of the generated families (sizes near 10K, 100K, 1M, ...).
#include "families.hpp"

#include <cmath>
#include <utility>

#include "fixtures.hpp"
#include "many_centres.hpp"
#include "scaling.hpp"

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
    // make_awkward picks each family's parameters for a triangle count (tests/support/fixtures.cpp).
    std::vector<Family> out;
    for (const AwkwardFamily fam : kAwkwardFamilies) {
        Family f{awkward_family_name(fam), {}, false, fam == AwkwardFamily::SlitWalls || fam == AwkwardFamily::SerpentineWalls};
        for (const uint64_t n : {uint64_t{10000}, uint64_t{100000}, uint64_t{1000000}})
            f.sizes.push_back({n, [fam, n] {
                                   WalledMesh w = make_awkward(fam, static_cast<uint32_t>(n));
                                   return Generated{std::move(w.soup), polyline_edges(w.walls)};
                               }});
        out.push_back(std::move(f));
    }
    // Several high-valence centres (issue 17): 8 fans on a disk, and the disk glued to its mirror
    // image (16 centres, closed).
    for (const bool closed : {false, true}) {
        Family f{closed ? "many_centres_closed" : "many_centres", {}, false, false};
        for (const uint64_t n : {uint64_t{10000}, uint64_t{100000}, uint64_t{1000000}})
            f.sizes.push_back({n, [n, closed] { return Generated{testing::make_many_centres(static_cast<uint32_t>(n), 8, closed), {}}; }});
        out.push_back(std::move(f));
    }
    // Files with no order (issue 17): a torus whose faces, or whose vertices, were shuffled.
    for (const bool faces : {true, false}) {
        Family f{faces ? "shuffled_faces" : "shuffled_vertices", {}, false, false};
        for (const uint64_t n : {uint64_t{10000}, uint64_t{100000}, uint64_t{1000000}})
            f.sizes.push_back({n, [n, faces] {
                                   const auto side = static_cast<uint32_t>(std::lround(std::sqrt(static_cast<double>(n) / 2)));
                                   TriangleSoup s = make_torus(side, side);
                                   if (faces)
                                       shuffle_faces(s, 17);
                                   else
                                       shuffle_vertices(s, 17);
                                   return Generated{std::move(s), {}};
                               }});
        out.push_back(std::move(f));
    }
    return out;
}

}  // namespace singlestrip::bench
