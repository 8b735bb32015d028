// The one edge classifier (src/core/soup_edges.hpp) and the one genus formula
// (src/core/topology.hpp) that Mesh, validate.cpp, repair.cpp and the generators share.
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <tuple>
#include <vector>

#include "../src/core/soup_edges.hpp"
#include "../src/core/topology.hpp"
#include "fixtures.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/validate.hpp"

using namespace singlestrip;

namespace {

struct Seen {
    uint32_t lo, hi;
    EdgeKind kind;
    std::vector<uint32_t> halfedges;
    bool operator==(const Seen&) const = default;
};

void PrintTo(const Seen& e, std::ostream* os) {
    *os << "(" << e.lo << ", " << e.hi << ") kind " << static_cast<int>(e.kind) << " half-edges";
    for (uint32_t h : e.halfedges) *os << " " << h;
}

std::vector<Seen> edges_of(const std::vector<Triangle>& tris, size_t nv, const std::vector<char>* usable = nullptr) {
    std::vector<Seen> out;
    SoupEdges(tris, nv, usable).for_each_edge([&](const SoupEdges::Edge& e) {
        out.push_back({e.lo, e.hi, e.kind, std::vector<uint32_t>(e.first, e.last)});
    });
    return out;
}

}  // namespace

TEST(SoupEdges, ClassifiesEveryKindInVertexPairOrder) {
    // Faces 0 and 1 share (1, 2) the opposite ways; face 2 runs along (0, 1) the way face 0 does;
    // faces 3, 4 and 5 all hold (3, 4).
    const std::vector<Triangle> tris = {{0, 1, 2}, {2, 1, 5}, {0, 1, 6}, {3, 4, 7}, {4, 3, 8}, {3, 4, 9}};
    const std::vector<Seen> e = edges_of(tris, 10);
    const std::vector<Seen> want = {
        {0, 1, EdgeKind::inconsistent, {0, 6}}, {0, 2, EdgeKind::boundary, {2}},
        {0, 6, EdgeKind::boundary, {8}},        {1, 2, EdgeKind::manifold, {1, 3}},
        {1, 5, EdgeKind::boundary, {4}},        {1, 6, EdgeKind::boundary, {7}},
        {2, 5, EdgeKind::boundary, {5}},        {3, 4, EdgeKind::non_manifold, {9, 12, 15}},
        {3, 7, EdgeKind::boundary, {11}},       {3, 8, EdgeKind::boundary, {13}},
        {3, 9, EdgeKind::boundary, {17}},       {4, 7, EdgeKind::boundary, {10}},
        {4, 8, EdgeKind::boundary, {14}},       {4, 9, EdgeKind::boundary, {16}},
    };
    EXPECT_EQ(e, want);
}

TEST(SoupEdges, LeavesOutUnusableFacesAndOutOfRangeEnds) {
    const std::vector<Triangle> tris = {{0, 1, 2}, {2, 1, 3}, {1, 0, 9}};
    const std::vector<char> usable = {1, 0, 1};
    // Face 1 is left out; face 2's half-edges to and from vertex 9 (>= 4 vertices) are too.
    const std::vector<Seen> want = {{0, 1, EdgeKind::manifold, {0, 6}}, {0, 2, EdgeKind::boundary, {2}}, {1, 2, EdgeKind::boundary, {1}}};
    EXPECT_EQ(edges_of(tris, 4, &usable), want);
    const SoupEdges all(tris, 4);
    EXPECT_TRUE(all.has_edge(3, 1));
    EXPECT_TRUE(all.has_edge(0, 1));
    EXPECT_FALSE(all.has_edge(0, 3));
    EXPECT_FALSE(all.has_edge(0, 9));
}

TEST(SoupEdges, PairsTheTwoHalfEdgesOfAnEdge) {
    const std::vector<Triangle> tris = {{0, 1, 2}, {2, 1, 3}};
    std::vector<uint32_t> twin(6, kNone);
    SoupEdges(tris, 4).for_each_edge([&](const SoupEdges::Edge& e) {
        if (e.kind == EdgeKind::manifold) SoupEdges::pair(e, twin);
    });
    EXPECT_EQ(twin, (std::vector<uint32_t>{kNone, 3, kNone, 1, kNone, kNone}));
}

TEST(Topology, GenusFromEulerCharacteristic) {
    EXPECT_EQ(euler_characteristic(12, 30, 20), 2);  // icosahedron
    EXPECT_EQ(euler_characteristic(0, 5, 0), -5);
    // (chi, boundary loops, components) -> genus
    const std::vector<std::tuple<long long, uint64_t, uint64_t, long long>> cases = {
        {2, 0, 1, 0}, {0, 0, 1, 1}, {-4, 0, 1, 3}, {1, 1, 1, 0}, {0, 2, 1, 0}, {-2, 4, 1, 0}, {4, 0, 2, 0}, {2, 0, 2, 1}, {-1, 1, 1, 1},
    };
    for (const auto& [chi, loops, components, genus] : cases) EXPECT_EQ(genus_from_euler(chi, loops, components), genus);
}

TEST(Topology, MeshAndSoupAnalysisAgree) {
    for (const TriangleSoup& soup : {make_torus(12, 8), make_genus_surface(3, 2), make_disk_with_holes(3, 2), make_builtin_model()}) {
        const MeshInfo info = mesh_info(soup);
        const Mesh mesh = Mesh::from_soup(soup);
        ASSERT_TRUE(info.genus_valid);
        EXPECT_EQ(mesh.euler_characteristic(), info.euler_characteristic);
        EXPECT_EQ(mesh.genus(), info.genus);
        EXPECT_EQ(mesh.num_edges(), info.edges);
        EXPECT_EQ(mesh.num_boundary_edges(), info.boundary_edges);
    }
}
