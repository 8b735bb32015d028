// Fundamental cycles of any strip order: the replay that finds fundamental triangles when the
// engine recorded none (matching engine, or a strip whose growth records were cleared), and the
// cycles built from them — count 2g+h-1 (2g closed), closed chains, independence in H1(M; Z2)
// checked by the independent verifier (verify.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "cycle_check.hpp"
#include "fixtures.hpp"
#include "singlestrip/cycles.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/verify.hpp"

using namespace singlestrip;

namespace {

/// Closed chains (cycle_check.hpp), each with its source.
void expect_closed_chains(const StripResult& r, const Cycles& c, const std::string& what) {
    ASSERT_EQ(c.cycles.size(), c.sources.size()) << what;
    singlestrip::testing::expect_closed_chains(r, c, what);
}

long long expected_count(long long genus, long long loops) {
    return loops == 0 ? 2 * genus : 2 * genus + loops - 1;
}

/// How the strip handed to compute_fundamental_cycles() was made.
enum class Variant { Growth, Matching, Cleared };

const char* variant_name(Variant v) {
    switch (v) {
        case Variant::Growth:
            return "growth";
        case Variant::Matching:
            return "matching";
        case Variant::Cleared:
            return "growth, records cleared";
    }
    return "?";
}

StripResult strip_for(const TriangleSoup& soup, Variant v, StripOptions opt) {
    opt.engine = v == Variant::Matching ? StripEngine::Matching : StripEngine::Growth;
    StripResult r = build_strip(Mesh::from_soup(soup), opt);
    if (v == Variant::Cleared) {  // what an engine without Betti tracking hands over
        r.take_time.clear();
        r.fundamental_positions.clear();
    }
    return r;
}

/// Whether a vertex of the first strip face lies on the mesh boundary.
bool first_face_touches_boundary(const StripResult& r) {
    std::vector<uint8_t> on_boundary(r.mesh.num_vertices(), 0);
    for (uint32_t h = 0; h < r.mesh.num_halfedges(); ++h)
        if (r.mesh.is_boundary(HalfedgeId(h))) on_boundary[r.mesh.from(HalfedgeId(h)).idx()] = 1;
    for (uint32_t k = 0; k < 3; ++k)
        if (on_boundary[r.mesh.from(Mesh::halfedge(FaceId(r.order.front()), k)).idx()]) return true;
    return false;
}

/// The independent verifier on the strip and its cycles: count and Z2 rank.
void expect_verified(const TriangleSoup& soup, const StripResult& r, const Cycles& c, long long expected, const std::string& what) {
    VerifyInput in = verify_input(soup, strip_arrays(r), {});
    in.indices.reset();
    in.cycles = c.cycles;
    const VerifyReport rep = verify(in);
    for (const std::string& f : rep.failures) EXPECT_NE(f.rfind("cycles", 0), 0u) << what << ": " << f;
    EXPECT_EQ(rep.cycles_checked, static_cast<size_t>(expected)) << what;
    EXPECT_EQ(static_cast<long long>(rep.cycle_rank), expected) << what;
}

/// Replay count: the Betti number drops sum to dim H1 = 2g+h-1, plus one when the first face has
/// no vertex on the boundary of a surface with boundary (removing it opens a hole: the only rise).
void expect_replay_count(const StripResult& r, long long genus, long long loops, const std::string& what) {
    const std::vector<uint32_t> found = replay_fundamental_positions(r.mesh, r.order);
    EXPECT_TRUE(std::is_sorted(found.begin(), found.end())) << what;
    const long long dim = expected_count(genus, loops);
    const long long rise = loops > 0 && !first_face_touches_boundary(r) ? 1 : 0;
    EXPECT_EQ(static_cast<long long>(found.size()), dim + rise) << what;
    for (size_t i = 1; i < found.size(); ++i) {
        if (found[i] == found[i - 1]) {
            EXPECT_EQ(found[i], 0u) << what << ": only the first face counts twice";
        }
    }
}

/// Strip with each variant; cycles checked. Returns the cycles of the cleared variant.
Cycles check_surface(const TriangleSoup& soup, long long genus, long long loops, const std::string& what, const StripOptions& opt = {}) {
    const long long expected = expected_count(genus, loops);
    Cycles cleared;
    for (Variant v : {Variant::Growth, Variant::Matching, Variant::Cleared}) {
        const std::string which = what + " (" + variant_name(v) + ")";
        const StripResult r = strip_for(soup, v, opt);
        EXPECT_EQ(r.mesh.genus(), genus) << which;
        EXPECT_EQ(static_cast<long long>(r.mesh.num_boundary_loops()), loops) << which;
        const Cycles c = compute_fundamental_cycles(r);
        EXPECT_EQ(static_cast<long long>(c.cycles.size()), expected) << which;
        expect_closed_chains(r, c, which);
        expect_verified(soup, r, c, expected, which);
        expect_replay_count(r, genus, loops, which);
        if (v == Variant::Cleared) cleared = c;
    }
    return cleared;
}

size_t from_fundamental_triangles(const Cycles& c) {
    return static_cast<size_t>(
        std::count_if(c.sources.begin(), c.sources.end(), [](CycleSource s) { return s != CycleSource::TreeCotree; }));
}

/// Edges of the torus meridian i (make_torus numbering: vertex (i, j) = i * n_minor + j).
std::vector<std::pair<uint32_t, uint32_t>> torus_meridian(uint32_t i, uint32_t n_minor) {
    std::vector<std::pair<uint32_t, uint32_t>> e;
    for (uint32_t j = 0; j < n_minor; ++j) e.push_back({i * n_minor + j, i * n_minor + (j + 1) % n_minor});
    return e;
}

}  // namespace

TEST(CyclesReplay, TorusFindsFundamentalTriangles) {
    for (uint32_t n : {3u, 5u, 8u}) {
        const TriangleSoup s = make_torus(2 * n, n);
        const Cycles c = check_surface(s, 1, 0, "torus " + std::to_string(n));
        // The replay's own triangles give the cycles, not the tree–cotree fallback.
        EXPECT_EQ(from_fundamental_triangles(c), 2u) << "torus " << n;
        const StripResult r = strip_for(s, Variant::Cleared, {});
        EXPECT_GE(replay_fundamental_positions(r.mesh, r.order).size(), 1u);
    }
}

TEST(CyclesReplay, GenusTwoAndThree) {
    for (uint32_t g : {2u, 3u})
        for (uint32_t r : {1u, 2u, 3u}) {
            const std::string what = "genus " + std::to_string(g) + " r=" + std::to_string(r);
            const Cycles c = check_surface(make_genus_surface(g, r), g, 0, what);
            EXPECT_EQ(from_fundamental_triangles(c), 2u * g) << what;
        }
}

TEST(CyclesReplay, BoundaryLoops) {
    for (uint32_t k : {1u, 2u, 4u}) check_surface(make_disk_with_holes(k, 2), 0, k + 1, "disk with " + std::to_string(k) + " holes");
    check_surface(make_annulus(12, 3), 0, 2, "annulus");
    check_surface(make_grid_disk(5, 4), 0, 1, "disk");
    for (uint32_t g : {1u, 2u})
        for (uint32_t h : {1u, 3u})
            check_surface(make_genus_with_holes(g, h, 3), g, h, "genus " + std::to_string(g) + " with " + std::to_string(h) + " holes");
}

TEST(CyclesReplay, ClosedSurfacesWithoutCycles) {
    check_surface(make_icosphere(2), 0, 0, "icosphere");
    check_surface(make_uv_sphere(8, 5), 0, 0, "uv sphere");
}

TEST(CyclesReplay, InteriorSeedOnSurfaceWithBoundary) {
    // The seed opens a hole when removed: the replay finds one drop more than dim H1, and the
    // cycles are still a basis.
    const TriangleSoup s = make_disk_with_holes(2, 3);
    const Mesh mesh = Mesh::from_soup(s);
    uint32_t interior = kNone;
    for (uint32_t f = 21; f < mesh.num_faces() && interior == kNone; ++f) {
        bool b = false;
        for (uint32_t k = 0; k < 3; ++k) b = b || mesh.is_boundary(Mesh::halfedge(FaceId(f), k));
        if (!b) interior = f;
    }
    ASSERT_NE(interior, kNone);
    StripOptions opt;
    opt.seed_face = FaceId(interior);
    check_surface(s, 0, 3, "disk with 2 holes, interior seed", opt);
}

TEST(CyclesReplay, ClosedSurfaceAnySeed) {
    const TriangleSoup s = make_genus_surface(2, 2);
    for (uint32_t seed : {0u, 17u, 101u}) {
        StripOptions opt;
        opt.seed_face = FaceId(seed);
        check_surface(s, 2, 0, "genus 2, seed face " + std::to_string(seed), opt);
    }
}

TEST(CyclesReplay, WithConstraints) {
    // A wall around the torus tube hides a handle from the unstriped region; cycles are the
    // surface's all the same.
    StripOptions opt;
    opt.constraint_edges = as_constraints(torus_meridian(0, 6));
    check_surface(make_torus(12, 6), 1, 0, "torus with a meridian wall", opt);
    opt.constraint_edges.push_back({6 * 6 + 0, 6 * 6 + 1});  // and a short wall elsewhere
    check_surface(make_torus(12, 6), 1, 0, "torus with two walls", opt);
}

TEST(CyclesReplay, WithSourceAndTarget) {
    const TriangleSoup s = make_genus_with_holes(2, 2, 3);
    StripOptions opt;
    opt.source = VertexId(0);
    opt.target = VertexId(static_cast<uint32_t>(s.points.size() / 2));
    check_surface(s, 2, 2, "genus 2 with 2 holes, source and target", opt);
}

TEST(CyclesReplay, FlippedMeshes) {
    uint64_t seed = 7;
    for (uint32_t g : {1u, 3u}) {
        TriangleSoup s = make_genus_with_holes(g, 2, 3);
        random_edge_flips(s, s.triangles.size() / 4, seed++);
        check_surface(s, g, 2, "flipped genus " + std::to_string(g) + " with 2 holes");
    }
}

TEST(CyclesReplay, HighGenus) {
    // Many handles: the replay is one pass (union–find), whatever the genus; every cycle from it.
    const uint32_t g = 40;
    const TriangleSoup s = make_genus_surface(g, 1);
    const StripResult r = strip_for(s, Variant::Cleared, {});
    EXPECT_EQ(replay_fundamental_positions(r.mesh, r.order).size(), 2u * g);
    const Cycles c = compute_fundamental_cycles(r);
    EXPECT_EQ(c.cycles.size(), 2u * g);
    expect_closed_chains(r, c, "genus 40");
    expect_verified(s, r, c, 2 * g, "genus 40");
}

TEST(CyclesReplay, RecordsOfWrongSizeAreReplayed) {
    StripOptions opt;
    opt.engine = StripEngine::Growth;
    StripResult r = build_strip(Mesh::from_soup(make_torus(10, 5)), opt);
    r.take_time.resize(3);  // stale: not one entry per face
    const Cycles c = compute_fundamental_cycles(r);
    EXPECT_EQ(c.cycles.size(), 2u);
    expect_closed_chains(r, c, "stale take_time");
}

TEST(CyclesReplay, ReplayRejectsNonPermutation) {
    const Mesh m = Mesh::from_soup(make_torus(6, 3));
    std::vector<uint32_t> order(m.num_faces(), 0);
    EXPECT_ANY_THROW(replay_fundamental_positions(m, order));
    EXPECT_ANY_THROW(replay_fundamental_positions(m, {0, 1}));
}
