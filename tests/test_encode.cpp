// GL strip encoder: round trip, optimality against brute force, known lengths, preconditions.
#include <cstddef>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "fixtures.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"

using namespace singlestrip;

namespace {

/// Rotation with the smallest first index: equal for two triangles iff same vertices and winding.
Triangle canonical(Triangle t) {
    while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
    return t;
}

bool same_faces(const std::vector<Triangle>& a, const std::vector<Triangle>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (canonical(a[i]) != canonical(b[i])) return false;
    return true;
}

/// Face adjacency through shared (undirected) edges.
std::vector<std::vector<uint32_t>> face_neighbours(const TriangleSoup& s) {
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> by_edge;
    for (uint32_t f = 0; f < s.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            uint32_t a = s.triangles[f][k], b = s.triangles[f][(k + 1) % 3];
            by_edge[{std::min(a, b), std::max(a, b)}].push_back(f);
        }
    std::vector<std::vector<uint32_t>> nb(s.triangles.size());
    for (const auto& [e, fs] : by_edge)
        if (fs.size() == 2) {
            nb[fs[0]].push_back(fs[1]);
            nb[fs[1]].push_back(fs[0]);
        }
    return nb;
}

/// Random walk of edge-adjacent faces. self_avoiding: stops when stuck; otherwise consecutive
/// faces only have to differ.
std::vector<Triangle> random_walk(const TriangleSoup& s, const std::vector<std::vector<uint32_t>>& nb, size_t length, uint64_t seed,
                                  bool self_avoiding) {
    Rng rng{seed};
    std::vector<char> used(s.triangles.size(), 0);
    uint32_t f = static_cast<uint32_t>(rng.below(s.triangles.size()));
    std::vector<Triangle> out{s.triangles[f]};
    used[f] = 1;
    while (out.size() < length) {
        std::vector<uint32_t> options;
        for (uint32_t g : nb[f])
            if (!self_avoiding || !used[g]) options.push_back(g);
        if (options.empty()) break;
        f = options[rng.below(options.size())];
        used[f] = 1;
        out.push_back(s.triangles[f]);
    }
    return out;
}

/// Length of the shortest index sequence decoding to `faces`, by exhaustive depth-first search
/// over all sequences up to max_len on the faces' vertices plus one unrelated index; only
/// prefixes whose decoded triangles are a prefix of `faces` are extended. Returns max_len + 1
/// if there is none that short.
size_t brute_force_shortest(const std::vector<Triangle>& faces, size_t max_len) {
    std::set<uint32_t> letters;
    for (const Triangle& t : faces) letters.insert(t.begin(), t.end());
    letters.insert(*letters.rbegin() + 1);  // an index that is in no face
    const std::vector<uint32_t> alphabet(letters.begin(), letters.end());
    std::vector<uint32_t> seq;
    size_t best = max_len + 1;
    std::function<void(size_t)> dfs = [&](size_t matched) {
        if (matched == faces.size()) {
            best = std::min(best, seq.size());
            return;
        }
        // Each remaining face needs at least one more index.
        if (seq.size() + (faces.size() - matched) >= best) return;
        for (uint32_t z : alphabet) {
            size_t m = matched;
            if (seq.size() >= 2) {
                const size_t i = seq.size() - 2;
                const uint32_t a = seq[i], b = seq[i + 1];
                if (a != b && b != z && a != z) {
                    const Triangle t = i % 2 == 0 ? Triangle{a, b, z} : Triangle{b, a, z};
                    if (canonical(t) != canonical(faces[matched])) continue;
                    ++m;
                }
            }
            seq.push_back(z);
            dfs(m);
            seq.pop_back();
        }
    };
    dfs(0);
    return best;
}

void expect_round_trip(const std::vector<Triangle>& faces, const std::string& what) {
    const std::vector<uint32_t> s = encode_triangle_strip(faces);
    EXPECT_TRUE(same_faces(decode_triangle_strip(s), faces)) << what;
    EXPECT_GE(s.size(), faces.size() + 2) << what;
    EXPECT_LE(s.size(), triangle_strip_bound(faces.size())) << what;
}

}  // namespace

TEST(Encode, EmptyAndSingle) {
    EXPECT_TRUE(encode_triangle_strip({}).empty());
    EXPECT_TRUE(decode_triangle_strip({}).empty());
    EXPECT_TRUE(decode_triangle_strip({4, 5}).empty());
    const std::vector<Triangle> one{{7, 3, 9}};
    const auto s = encode_triangle_strip(one);
    EXPECT_EQ(s.size(), 3u);
    EXPECT_TRUE(same_faces(decode_triangle_strip(s), one));
}

TEST(Encode, DecodeRule) {
    // Odd triangles flip; degenerate ones are skipped and do not shift the parity rule.
    const std::vector<Triangle> d = decode_triangle_strip({0, 1, 2, 3, 3, 4, 5});
    ASSERT_EQ(d.size(), 3u);
    EXPECT_EQ(d[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(d[1], (Triangle{2, 1, 3}));  // i = 1
    EXPECT_EQ(d[2], (Triangle{3, 4, 5}));  // i = 4
    const std::vector<Triangle> e = decode_triangle_strip({0, 1, 2, 2, 3, 4, 5});
    ASSERT_EQ(e.size(), 3u);
    EXPECT_EQ(e[1], (Triangle{3, 2, 4}));  // i = 3
    EXPECT_EQ(e[2], (Triangle{3, 4, 5}));  // i = 4
}

TEST(Encode, SequentialStripIsNPlusTwo) {
    for (uint32_t k : {1u, 2u, 3u, 10u, 101u, 1000u}) {
        const TriangleSoup c = make_corridor(k);
        const auto s = encode_triangle_strip(c.triangles);
        EXPECT_EQ(s.size(), k + 2u);
        EXPECT_TRUE(same_faces(decode_triangle_strip(s), c.triangles));
    }
}

TEST(Encode, PreconditionViolationsThrow) {
    EXPECT_THROW(encode_triangle_strip({{0, 1, 2}, {3, 4, 5}}), InternalError);
    EXPECT_THROW(encode_triangle_strip({{0, 1, 2}, {2, 3, 4}}), InternalError);  // only a vertex
    EXPECT_THROW(encode_triangle_strip({{0, 1, 1}}), InternalError);
    EXPECT_THROW(encode_triangle_strip({{0, 1, 2}, {2, 1, 2}}), InternalError);
}

TEST(Encode, RoundTripOnRandomWalks) {
    const std::vector<std::pair<std::string, TriangleSoup>> meshes = {
        {"grid", make_grid_disk(12, 9)},  {"fan", make_fan(30)},
        {"icosphere", make_icosphere(3)}, {"torus", make_torus(20, 9)},
        {"genus2", make_builtin_model()}, {"annulus", make_annulus(16, 4)},
    };
    for (const auto& [name, mesh] : meshes) {
        const auto nb = face_neighbours(mesh);
        size_t tris = 0, idx = 0;
        for (uint64_t seed = 0; seed < 100; ++seed) {
            for (bool avoid : {true, false}) {
                const auto walk = random_walk(mesh, nb, 1 + seed * 7, seed, avoid);
                expect_round_trip(walk, name + " seed " + std::to_string(seed));
                tris += walk.size();
                idx += encode_triangle_strip(walk).size();
            }
        }
        std::printf("[ measure ] %-10s random walks: %zu triangles, %.3f indices per triangle\n", name.c_str(), tris,
                    static_cast<double>(idx) / static_cast<double>(tris));
    }
}

TEST(Encode, SameDirectionTurnsCostASwap) {
    // A fan walked in order turns the same way each time; every face after the second needs at
    // least one extra index, and the encoder must still be optimal (checked by brute force).
    for (uint32_t k = 1; k <= 5; ++k) {
        const TriangleSoup fan = make_fan(k);
        const auto s = encode_triangle_strip(fan.triangles);
        EXPECT_TRUE(same_faces(decode_triangle_strip(s), fan.triangles));
        EXPECT_EQ(s.size(), brute_force_shortest(fan.triangles, s.size())) << "fan " << k;
    }
    const TriangleSoup big = make_fan(1000);
    const auto s = encode_triangle_strip(big.triangles);
    EXPECT_TRUE(same_faces(decode_triangle_strip(s), big.triangles));
    std::printf("[ measure ] fan of 1000 in order: %.3f indices per triangle\n", s.size() / 1000.0);
}

TEST(Encode, OptimalAgainstBruteForce) {
    const std::vector<TriangleSoup> meshes = {make_grid_disk(3, 3), make_icosphere(0), make_fan(6), make_torus(3, 3), make_annulus(5, 1)};
    size_t cases = 0;
    for (size_t mi = 0; mi < meshes.size(); ++mi) {
        const auto nb = face_neighbours(meshes[mi]);
        for (uint64_t seed = 0; seed < 60; ++seed) {
            const size_t len = 1 + seed % 6;
            const auto walk = random_walk(meshes[mi], nb, len, seed * 31 + mi, seed % 3 != 0);
            const auto s = encode_triangle_strip(walk);
            ASSERT_TRUE(same_faces(decode_triangle_strip(s), walk));
            // No sequence shorter than the encoder's exists.
            EXPECT_EQ(brute_force_shortest(walk, s.size()), s.size()) << "mesh " << mi << " seed " << seed << " faces " << walk.size();
            ++cases;
        }
    }
    // Orientation that flips between neighbours (same edge direction) still encodes exactly.
    const std::vector<Triangle> odd{{0, 1, 2}, {0, 1, 3}, {3, 1, 4}};
    const auto s = encode_triangle_strip(odd);
    EXPECT_TRUE(same_faces(decode_triangle_strip(s), odd));
    EXPECT_EQ(brute_force_shortest(odd, s.size()), s.size());
    EXPECT_EQ(cases, 300u);
}

TEST(Encode, RoundTripOnBuiltStrips) {
    // Typical input: the single strips build_strip() makes of generated meshes.
    const std::vector<std::pair<std::string, TriangleSoup>> meshes = {
        {"builtin", make_builtin_model()},
        {"icosphere3", make_icosphere(3)},
        {"torus", make_torus(32, 16)},
        {"grid", make_grid_disk(30, 20)},
        {"genus3holes", make_genus_with_holes(3, 4, 4)},
    };
    for (const auto& [name, soup] : meshes) {
        const StripArrays a = strip_arrays(build_strip(Mesh::from_soup(soup)));
        const auto s = encode_triangle_strip(a.faces);
        EXPECT_TRUE(same_faces(decode_triangle_strip(s), a.faces)) << name;
        EXPECT_GE(s.size(), a.faces.size() + 2) << name;
        std::printf("[ measure ] %-12s strip of %zu triangles (%zu input): %.3f indices per strip triangle\n", name.c_str(), a.faces.size(),
                    soup.triangles.size(), static_cast<double>(s.size()) / static_cast<double>(a.faces.size()));
    }
}
