// Tests of the independent verifier on hand-made outputs: valid ones pass; deliberately broken
// ones are caught with the right check named (readers and real meshes: test_verify_outputs.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "singlestrip/errors.hpp"
#include "singlestrip/verify.hpp"
#include "verify_cases.hpp"

namespace ss = singlestrip;
using ss::Point3;
using ss::Triangle;
using namespace ss::testing;  // verify_cases.hpp: the report helpers, quad(), split_quad()

namespace {

// Octahedron, one face per octant, outward; strip order along the Gray code of the octants.
ss::VerifyInput octahedron() {
    ss::VerifyInput in;
    in.in_points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const int gray[8] = {0, 1, 3, 2, 6, 7, 5, 4};
    std::vector<Triangle> faces;
    for (int code = 0; code < 8; ++code) {
        const uint32_t x = (code & 1) ? 1 : 0, y = (code & 2) ? 3 : 2, z = (code & 4) ? 5 : 4;
        Triangle t{x, y, z};
        const Point3 a = in.in_points[x], b = in.in_points[y], c = in.in_points[z];
        const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
        const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
        const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        if (nx * (a[0] + b[0] + c[0]) + ny * (a[1] + b[1] + c[1]) + nz * (a[2] + b[2] + c[2]) < 0) std::swap(t[1], t[2]);
        faces.push_back(t);
    }
    in.in_faces = faces;
    in.out_points = in.in_points;
    for (int g : gray) {
        in.out_faces.push_back(faces[static_cast<size_t>(g)]);
        in.out_parent.push_back(static_cast<uint32_t>(g));
    }
    return in;
}

/// m x n grid of quads (2 triangles each). wrap_j: torus; else an annulus in the plane.
/// Output = input faces in a strip order (rows, each row cyclic), parents = input indices.
struct Grid {
    ss::VerifyInput in;
    uint32_t m, n;
    std::vector<uint32_t> pos_of;  // input face -> position in the output
    uint32_t lower(uint32_t i, uint32_t j) const { return 2 * ((j % n) * m + (i % m)); }
    uint32_t upper(uint32_t i, uint32_t j) const { return lower(i, j) + 1; }
};

Grid grid(uint32_t m, uint32_t n, bool torus) {
    Grid g;
    g.m = m;
    g.n = n;
    const uint32_t rows = torus ? n : n + 1;
    auto vid = [&](uint32_t i, uint32_t j) { return (j % rows) * m + (i % m); };
    for (uint32_t j = 0; j < rows; ++j)
        for (uint32_t i = 0; i < m; ++i) {
            const double th = 2 * std::numbers::pi * i / m;
            if (torus) {
                const double ph = 2 * std::numbers::pi * j / n;
                const double R = 3 + std::cos(ph);
                g.in.in_points.push_back({R * std::cos(th), R * std::sin(th), std::sin(ph)});
            } else {
                const double R = 1 + j;
                g.in.in_points.push_back({R * std::cos(th), R * std::sin(th), 0});
            }
        }
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < m; ++i) {
            g.in.in_faces.push_back({vid(i, j), vid(i + 1, j), vid(i + 1, j + 1)});  // lower
            g.in.in_faces.push_back({vid(i, j), vid(i + 1, j + 1), vid(i, j + 1)});  // upper
        }
    g.in.out_points = g.in.in_points;
    g.pos_of.assign(g.in.in_faces.size(), 0);
    for (uint32_t j = 0; j < n; ++j) {
        std::vector<uint32_t> row{g.lower(0, j)};
        for (uint32_t i = 1; i < m; ++i) {
            row.push_back(g.upper(i, j));
            row.push_back(g.lower(i, j));
        }
        row.push_back(g.upper(0, j));
        for (uint32_t f : row) {
            g.pos_of[f] = static_cast<uint32_t>(g.in.out_faces.size());
            g.in.out_faces.push_back(g.in.in_faces[f]);
            g.in.out_parent.push_back(f);
        }
    }
    return g;
}

/// Row j (along i) or column i (along j) of the grid, as strip positions: a closed chain.
std::vector<uint32_t> grid_cycle(const Grid& g, bool row, uint32_t k) {
    std::vector<uint32_t> c;
    for (uint32_t t = 0; t < (row ? g.m : g.n); ++t) {
        const uint32_t i = row ? t : k, j = row ? k : t;
        c.push_back(g.pos_of[row ? g.upper(i, j) : g.lower(i, j)]);
        c.push_back(g.pos_of[row ? g.lower(i, j) : g.upper(i, j)]);
    }
    return c;
}

std::vector<uint32_t> row_cycle(const Grid& g, uint32_t j) {
    return grid_cycle(g, true, j);
}

std::vector<uint32_t> column_cycle(const Grid& g, uint32_t i) {
    return grid_cycle(g, false, i);
}

/// The faces around output vertex v, as a closed chain (v interior).
std::vector<uint32_t> vertex_ring(const ss::VerifyInput& in, uint32_t v) {
    std::vector<uint32_t> faces;
    for (uint32_t f = 0; f < in.out_faces.size(); ++f)
        if (std::find(in.out_faces[f].begin(), in.out_faces[f].end(), v) != in.out_faces[f].end()) faces.push_back(f);
    std::vector<uint32_t> chain{faces[0]};
    std::vector<bool> used(faces.size(), false);
    used[0] = true;
    for (size_t step = 1; step < faces.size(); ++step) {
        const Triangle& a = in.out_faces[chain.back()];
        for (size_t k = 0; k < faces.size(); ++k) {
            if (used[k]) continue;
            const Triangle& b = in.out_faces[faces[k]];
            int common = 0;
            for (uint32_t x : a) common += std::count(b.begin(), b.end(), x) > 0;
            if (common == 2) {
                chain.push_back(faces[k]);
                used[k] = true;
                break;
            }
        }
    }
    return chain;
}

// ------------------------------------------------------------------------------------------

TEST(Verify, QuadPasses) {
    auto in = quad();
    in.indices = std::vector<uint32_t>{1, 2, 0, 3};
    const auto r = ss::verify(in);
    EXPECT_TRUE(r.ok()) << joined(r);
    EXPECT_EQ(r.faces_checked, 2u);
    EXPECT_EQ(r.euler_characteristic, 1);
    EXPECT_EQ(r.boundary_loops, 1u);
}

TEST(Verify, SplitQuadPasses) {
    auto in = split_quad();
    in.indices = std::vector<uint32_t>{0, 1, 4, 2, 4, 3, 0};
    const auto r = ss::verify(in);
    EXPECT_TRUE(r.ok()) << joined(r);
    EXPECT_EQ(r.faces_checked, 4u);
}

TEST(Verify, SplitQuadInfersParents) {
    auto in = split_quad();
    in.out_parent.clear();
    const auto r = ss::verify(in);
    EXPECT_TRUE(r.ok()) << joined(r);
    EXPECT_EQ(r.faces_checked, 4u);
}

TEST(Verify, OctahedronPasses) {
    auto in = octahedron();
    in.cycles = std::vector<std::vector<uint32_t>>{};
    const auto r = ss::verify(in);
    EXPECT_TRUE(r.ok()) << joined(r);
    EXPECT_EQ(r.euler_characteristic, 2);
    EXPECT_EQ(r.boundary_loops, 0u);
    EXPECT_EQ(r.genus, 0);
}

TEST(Verify, TorusWithTwoIndependentCyclesPasses) {
    Grid g = grid(6, 4, true);
    g.in.cycles = std::vector<std::vector<uint32_t>>{row_cycle(g, 1), column_cycle(g, 2)};
    const auto r = ss::verify(g.in);
    EXPECT_TRUE(r.ok()) << joined(r);
    EXPECT_EQ(r.genus, 1);
    EXPECT_EQ(r.cycle_rank, 2u);
}

TEST(Verify, TorusInferredParentsPasses) {
    Grid g = grid(6, 4, true);
    g.in.out_parent.clear();
    const auto r = ss::verify(g.in);
    EXPECT_TRUE(r.ok()) << joined(r);
}

TEST(Verify, AnnulusOneCyclePasses) {
    Grid g = grid(8, 2, false);
    g.in.cycles = std::vector<std::vector<uint32_t>>{row_cycle(g, 1)};
    const auto r = ss::verify(g.in);
    EXPECT_TRUE(r.ok()) << joined(r);
    EXPECT_EQ(r.boundary_loops, 2u);
    EXPECT_EQ(r.cycle_rank, 1u);
}

// --- broken outputs are caught --------------------------------------------------------------

TEST(VerifyCatches, TwoFacesSwapped) {
    auto in = split_quad();
    std::swap(in.out_faces[1], in.out_faces[2]);
    std::swap(in.out_parent[1], in.out_parent[2]);
    const auto r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "strip", "faces 0 and 1")) << joined(r);
}

TEST(VerifyCatches, FaceDropped) {
    auto in = split_quad();
    in.out_faces.erase(in.out_faces.begin() + 3);
    in.out_parent.erase(in.out_parent.begin() + 3);
    const auto r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "coverage", "input face 1")) << joined(r);
    EXPECT_TRUE(has_failure_prefix(r, "conformity")) << joined(r);
}

TEST(VerifyCatches, WholeParentDropped) {
    auto in = quad();
    in.out_faces.pop_back();
    in.out_parent.pop_back();
    const auto r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "coverage", "has no child")) << joined(r);
}

TEST(VerifyCatches, InsertedVertexMoved) {
    auto in = split_quad();
    in.out_points[4] = {0.6, 0.5, 0};  // off the diagonal: children leave their parents
    const auto r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "geometry", "not inside its parent")) << joined(r);
}

TEST(VerifyCatches, InsertedVertexMovedOutOfPlane) {
    auto in = split_quad();
    in.out_points[4] = {0.5, 0.5, 1e-3};
    const auto r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "geometry", "plane")) << joined(r);
}

TEST(VerifyCatches, OriginalVertexMoved) {
    auto in = quad();
    in.out_points[2][0] += 1e-12;
    const auto r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "vertices", "vertex 2 moved")) << joined(r);
}

TEST(VerifyCatches, FaceFlipped) {
    auto in = split_quad();
    std::swap(in.out_faces[1][1], in.out_faces[1][2]);
    const auto r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "orientation", "face 1 (parent 0)")) << joined(r);
    EXPECT_TRUE(has_failure_prefix(r, "manifold")) << joined(r);
}

TEST(VerifyCatches, BadIndexSequence) {
    auto in = split_quad();
    in.indices = std::vector<uint32_t>{0, 1, 4, 2, 3, 0};  // the swap is missing
    auto r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "indices")) << joined(r);
    // Right triangles, wrong parity: every winding reversed.
    in.indices = std::vector<uint32_t>{1, 0, 4, 2, 4, 3, 0};
    r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "indices", "opposite winding")) << joined(r);
    // Index out of range: reported, no crash.
    in.indices = std::vector<uint32_t>{0, 1, 99};
    r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "indices", "out of range")) << joined(r);
}

TEST(VerifyCatches, DuplicatedFace) {
    auto in = split_quad();
    in.out_faces.push_back(in.out_faces[3]);
    in.out_parent.push_back(1);
    const auto r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "manifold", "duplicate face")) << joined(r);
}

TEST(VerifyCatches, TJunction) {
    // Split only face 0 at the diagonal's midpoint: face 1 keeps the whole diagonal.
    auto in = quad();
    in.out_points.push_back({0.5, 0.5, 0});
    in.out_faces = {{0, 2, 3}, {0, 1, 4}, {4, 1, 2}};
    in.out_parent = {1, 0, 0};
    const auto r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "conformity", "T-junction")) << joined(r);
}

TEST(Verify, BoundaryPointSplitPassesSliverFails) {
    // Face 0 split by a vertex on its boundary edge 0-1: a conforming refinement.
    auto in = quad();
    in.out_points.push_back({0.5, 0, 0});
    in.out_faces = {{4, 1, 2}, {0, 4, 2}, {0, 2, 3}};
    in.out_parent = {0, 0, 1};
    auto r = ss::verify(in);
    EXPECT_TRUE(r.ok()) << joined(r);
    // A zero-area sliver on that boundary edge added to the unsplit quad.
    in.out_faces = {{0, 4, 1}, {0, 1, 2}, {0, 2, 3}};
    in.out_parent = {0, 0, 1};
    r = ss::verify(in);
    // Topologically this is a valid fold (edge 0-1 has two faces, 0-4-1 is boundary): only the
    // zero area gives it away.
    EXPECT_TRUE(has_failure(r, "geometry", "degenerate")) << joined(r);
}

// A polygon's ear on a circle of 20,000 points (height 5e-8, coordinates near 1) and the face
// across its long edge, that edge split at its midpoint: valid. The verifier allows a midpoint's
// rounding there (16 ulps of the coordinates; Engines.ThinEarsOfAPolygonOnACircle needs it), so
// a point moved off the edge by 1e-12, far above rounding, must still be caught.
ss::VerifyInput thin_ear_split(double move) {
    ss::VerifyInput in;
    const double d = 2 * std::numbers::pi / 20000;
    auto at = [](double t) { return Point3{std::cos(t), std::sin(t), 0}; };
    in.in_points = {at(0), at(d), at(2 * d), at(std::numbers::pi)};  // A B C D
    in.in_faces = {{0, 1, 2}, {0, 2, 3}};                            // the ear, the face across C-A
    in.out_points = in.in_points;
    const Point3 m{0.5 * (in.in_points[0][0] + in.in_points[2][0]) - move, 0.5 * (in.in_points[0][1] + in.in_points[2][1]), 0};
    in.out_points.push_back(m);  // 4
    in.out_faces = {{0, 1, 4}, {1, 2, 4}, {4, 2, 3}, {0, 4, 3}};
    in.out_parent = {0, 0, 1, 1};
    return in;
}

TEST(Verify, ThinEarSplitFarFromTheOriginPasses) {
    auto in = thin_ear_split(0);
    auto r = ss::verify(in);
    EXPECT_TRUE(r.ok()) << joined(r);
    in.out_parent.clear();  // inferred
    r = ss::verify(in);
    EXPECT_TRUE(r.ok()) << joined(r);
}

TEST(VerifyCatches, ThinEarSplitPointMovedOffItsEdge) {
    const auto r = ss::verify(thin_ear_split(1e-12));
    EXPECT_TRUE(has_failure(r, "geometry", "not inside")) << joined(r);
}

TEST(VerifyCatches, WrongCycleCount) {
    Grid g = grid(6, 4, true);
    g.in.cycles = std::vector<std::vector<uint32_t>>{row_cycle(g, 0)};
    const auto r = ss::verify(g.in);
    EXPECT_TRUE(has_failure(r, "cycles", "expected 2g+h-1 = 2")) << joined(r);
}

TEST(VerifyCatches, TwoIdenticalCycles) {
    Grid g = grid(6, 4, true);
    g.in.cycles = std::vector<std::vector<uint32_t>>{row_cycle(g, 0), row_cycle(g, 0)};
    const auto r = ss::verify(g.in);
    EXPECT_TRUE(has_failure(r, "cycles", "not linearly independent")) << joined(r);
    EXPECT_EQ(r.cycle_rank, 1u);
}

TEST(VerifyCatches, HomologousCycles) {
    // Two different rows are homologous on the torus: rank 1.
    Grid g = grid(6, 4, true);
    g.in.cycles = std::vector<std::vector<uint32_t>>{row_cycle(g, 0), row_cycle(g, 2)};
    const auto r = ss::verify(g.in);
    EXPECT_TRUE(has_failure(r, "cycles", "not linearly independent")) << joined(r);
}

TEST(VerifyCatches, ContractibleCycle) {
    Grid g = grid(6, 4, true);
    const uint32_t v = 1 * 6 + 2;  // vertex (2, 1)
    g.in.cycles = std::vector<std::vector<uint32_t>>{row_cycle(g, 0), vertex_ring(g.in, v)};
    ASSERT_EQ((*g.in.cycles)[1].size(), 6u);
    const auto r = ss::verify(g.in);
    EXPECT_TRUE(has_failure(r, "cycles", "cycle 1 is null-homologous")) << joined(r);
}

TEST(VerifyCatches, ContractibleCycleOnAnnulus) {
    Grid g = grid(8, 2, false);
    const uint32_t v = 1 * 8 + 3;  // an interior vertex of the annulus
    g.in.cycles = std::vector<std::vector<uint32_t>>{vertex_ring(g.in, v)};
    const auto r = ss::verify(g.in);
    EXPECT_TRUE(has_failure(r, "cycles", "null-homologous")) << joined(r);
}

TEST(VerifyCatches, OpenChainAsCycle) {
    Grid g = grid(6, 4, true);
    auto open = row_cycle(g, 0);
    open.pop_back();
    g.in.cycles = std::vector<std::vector<uint32_t>>{open, column_cycle(g, 0)};
    const auto r = ss::verify(g.in);
    EXPECT_TRUE(has_failure(r, "cycles", "not closed")) << joined(r);
}

TEST(VerifyCatches, ConstraintCrossed) {
    auto in = quad();
    in.constraints = {{0, 2}};
    auto r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "constraints", "crosses a constraint")) << joined(r);
    // A boundary constraint changes nothing.
    in.constraints = {{1, 2}};
    r = ss::verify(in);
    EXPECT_TRUE(r.ok()) << joined(r);
    // A pair that is not an input edge.
    in.constraints = {{1, 3}};
    r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "constraints", "not an edge of the input")) << joined(r);
}

TEST(VerifyCatches, ConstraintSplitAndPieceCrossed) {
    auto in = split_quad();
    in.constraints = {{0, 2}};
    const auto r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "constraints", "was split")) << joined(r);
    EXPECT_TRUE(has_failure(r, "constraints", "faces 1 and 2 share edge (4,2)")) << joined(r);
}

TEST(VerifyCatches, WrongSourceTarget) {
    auto in = quad();
    in.source = 1;
    in.target = 3;
    auto r = ss::verify(in);
    EXPECT_TRUE(r.ok()) << joined(r);
    in.source = 3;
    in.target = 1;
    r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "source", "source vertex 3")) << joined(r);
    EXPECT_TRUE(has_failure(r, "target", "target vertex 1")) << joined(r);
    in.source = 77;
    r = ss::verify(in);
    EXPECT_TRUE(has_failure(r, "source", "not an input vertex")) << joined(r);
}

TEST(VerifyCatches, GarbageIsReportedNotThrown) {
    auto in = split_quad();
    in.out_faces[2] = {4, 2, 1000};
    in.out_parent[3] = 55;
    in.cycles = std::vector<std::vector<uint32_t>>{{0, 1, 999}};
    ss::VerifyReport r;
    EXPECT_NO_THROW(r = ss::verify(in));
    EXPECT_TRUE(has_failure(r, "manifold", "out of range")) << joined(r);
    EXPECT_TRUE(has_failure(r, "parent", "out of range")) << joined(r);
    in = split_quad();
    in.out_parent.resize(2);
    EXPECT_NO_THROW(r = ss::verify(in));
    EXPECT_TRUE(has_failure(r, "parent", "entries")) << joined(r);
    in = split_quad();
    in.out_faces.clear();
    in.out_parent.clear();
    EXPECT_NO_THROW(r = ss::verify(in));
    EXPECT_FALSE(r.ok());
    in = split_quad();
    in.out_points.resize(2);
    EXPECT_NO_THROW(r = ss::verify(in));
    EXPECT_FALSE(r.ok());
    in = split_quad();
    in.out_parent.clear();
    in.out_points[4] = {5, 5, 5};  // not a midpoint: parents from the input edges the faces hold
    EXPECT_NO_THROW(r = ss::verify(in));
    EXPECT_TRUE(has_failure(r, "geometry", "not in its parent's plane")) << joined(r);
}

TEST(VerifyCatches, TorusFaceDroppedChangesTopology) {
    Grid g = grid(6, 4, true);
    g.in.out_faces.pop_back();
    g.in.out_parent.pop_back();
    const auto r = ss::verify(g.in);
    EXPECT_TRUE(has_failure_prefix(r, "topology")) << joined(r);
    EXPECT_TRUE(has_failure_prefix(r, "coverage")) << joined(r);
}

}  // namespace
