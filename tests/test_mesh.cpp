// Mesh core: topology queries on procedural meshes and the split operation's invariants.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <type_traits>
#include <unordered_set>

#include "fixtures.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/validate.hpp"

using namespace singlestrip;

namespace {
double area(const Mesh& m, FaceId f) {
    const auto& a = m.position(m.from(Mesh::halfedge(f, 0)));
    const auto& b = m.position(m.from(Mesh::halfedge(f, 1)));
    const auto& c = m.position(m.from(Mesh::halfedge(f, 2)));
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
    return 0.5 * std::sqrt(x * x + y * y + z * z);
}
}  // namespace

TEST(Mesh, TopologyOfProceduralMeshes) {
    struct Case {
        std::string name;
        TriangleSoup soup;
        long long genus;
        uint32_t loops;
    };
    std::vector<Case> cases = {
        {"icosphere", make_icosphere(2), 0, 0},
        {"torus", make_torus(12, 8), 1, 0},
        {"genus 3", make_genus_surface(3, 2), 3, 0},
        {"disk with 4 holes", make_disk_with_holes(4, 2), 0, 5},
        {"grid disk", make_grid_disk(6, 4), 0, 1},
        {"annulus", make_annulus(12, 3), 0, 2},
        {"genus 2 with 3 holes", make_genus_with_holes(2, 3, 3), 2, 3},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        const Mesh m = Mesh::from_soup(c.soup);
        m.validate();
        EXPECT_EQ(m.num_components(), 1u);
        EXPECT_EQ(m.genus(), c.genus);
        EXPECT_EQ(m.num_boundary_loops(), c.loops);
        EXPECT_EQ(m.euler_characteristic(), 2 - 2 * c.genus - c.loops);
        EXPECT_EQ(m.num_faces(), c.soup.triangles.size());
        EXPECT_EQ(2 * m.num_edges() - m.num_boundary_edges(), 3 * m.num_faces());
    }
}

TEST(Mesh, MoebiusIsRejected) {
    EXPECT_THROW(Mesh::from_soup(make_moebius_soup(8)), InputError);
}

TEST(Mesh, NonManifoldEdgeIsRejected) {
    TriangleSoup s;
    s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    s.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    EXPECT_THROW(Mesh::from_soup(s), InputError);
}

TEST(Mesh, NonManifoldVertexIsRejected) {
    // Two triangles touching at vertex 0 only.
    TriangleSoup s;
    s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    s.triangles = {{0, 1, 2}, {0, 3, 4}};
    EXPECT_THROW(Mesh::from_soup(s), InputError);
}

TEST(Mesh, RandomSplitsKeepEveryInvariant) {
    std::mt19937 rng(5);
    for (const auto& soup : {make_torus(8, 5), make_grid_disk(5, 4), make_genus_surface(2, 1)}) {
        Mesh m = Mesh::from_soup(soup);
        const long long chi = m.euler_characteristic();
        const uint32_t loops = m.num_boundary_loops();
        std::vector<double> parent_area(m.num_faces());
        for (const FaceId f : m.faces()) parent_area[f.idx()] = area(m, f);
        for (int i = 0; i < 300; ++i) {
            HalfedgeId h;
            do h = HalfedgeId(static_cast<uint32_t>(rng() % m.num_halfedges()));
            while (m.is_boundary(h));
            const VertexId a = m.from(h), b = m.to(h);
            const uint32_t nf = m.num_faces(), nv = m.num_vertices();
            const SplitResult s = m.split_edge(h);
            m.validate();
            EXPECT_EQ(m.num_faces(), nf + 2);
            EXPECT_EQ(m.num_vertices(), nv + 1);
            EXPECT_EQ(s.vertex, VertexId(nv));
            for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(m.position(s.vertex)[k], 0.5 * (m.position(a)[k] + m.position(b)[k]));
            EXPECT_EQ(m.parent(s.f_a), m.parent(s.f_b));
            EXPECT_EQ(m.parent(s.g_a), m.parent(s.g_b));
            EXPECT_TRUE(m.shared_halfedge(s.f_a, s.g_a).valid());
            EXPECT_TRUE(m.shared_halfedge(s.f_b, s.g_b).valid());
            EXPECT_TRUE(m.shared_halfedge(s.f_a, s.f_b).valid());
            EXPECT_TRUE(m.shared_halfedge(s.g_a, s.g_b).valid());
        }
        EXPECT_EQ(m.euler_characteristic(), chi);
        EXPECT_EQ(m.num_boundary_loops(), loops);
        // Children tile their parents: areas add up.
        std::vector<double> sum(parent_area.size(), 0.0);
        for (const FaceId f : m.faces()) sum[m.parent(f).idx()] += area(m, f);
        for (size_t p = 0; p < sum.size(); ++p) EXPECT_NEAR(sum[p], parent_area[p], 1e-9 * (1 + parent_area[p]));
    }
}

TEST(Mesh, SplitOfABoundaryEdgeIsAnInternalError) {
    Mesh m = Mesh::from_soup(make_single_triangle());
    EXPECT_THROW(m.split_edge(HalfedgeId(0)), InternalError);
    m.validate();  // a refused split leaves the mesh as it was
}

TEST(Ids, AreFlatTypedIndicesWithOneNone) {
    static_assert(sizeof(FaceId) == sizeof(uint32_t) && std::is_trivially_copyable_v<FaceId>);
    static_assert(!std::is_convertible_v<uint32_t, FaceId>, "an index becomes an id only explicitly");
    static_assert(!std::is_convertible_v<FaceId, uint32_t>, "idx() reads it back");
    static_assert(!std::is_convertible_v<FaceId, HalfedgeId> && !std::is_convertible_v<VertexId, FaceId>);
    EXPECT_FALSE(FaceId().valid());
    EXPECT_EQ(FaceId(), kNone);
    const HalfedgeId none = kNone;
    EXPECT_EQ(none.idx(), 0xffffffffu);
    EXPECT_TRUE(VertexId(0).valid());
    EXPECT_LT(VertexId(1), VertexId(2));
    const std::unordered_set<VertexId> set{VertexId(1), VertexId(1), VertexId(2)};
    EXPECT_EQ(set.size(), 2u);
    const Mesh m = Mesh::from_soup(make_torus(6, 4));
    uint32_t n = 0;
    for (const FaceId f : m.faces()) {
        EXPECT_EQ(f.idx(), n++);
        for (uint32_t k = 0; k < 3; ++k) EXPECT_EQ(Mesh::face(Mesh::halfedge(f, k)), f);
    }
    EXPECT_EQ(n, m.num_faces());
}

// Component labels against a search from face to face: several pieces (closed, bounded, single
// faces) with their faces interleaved at random, so each piece's first face is anywhere.
TEST(Mesh, ComponentLabelsFollowTheFirstFaceOfEachPiece) {
    std::mt19937 rng(17);
    for (int round = 0; round < 20; ++round) {
        TriangleSoup soup;
        for (const TriangleSoup& piece : {make_torus(6, 4), make_single_triangle(), make_disk_with_holes(3, 2), make_fan(5),
                                          make_icosphere(1), make_single_triangle(), make_corridor(7)}) {
            const auto base = static_cast<uint32_t>(soup.points.size());
            soup.points.insert(soup.points.end(), piece.points.begin(), piece.points.end());
            for (Triangle t : piece.triangles) soup.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
        }
        std::shuffle(soup.triangles.begin(), soup.triangles.end(), rng);
        const Mesh m = Mesh::from_soup(soup);
        std::vector<uint32_t> expect(m.num_faces(), UINT32_MAX);
        uint32_t next = 0;
        for (FaceId f0 : m.faces()) {
            if (expect[f0.idx()] != UINT32_MAX) continue;
            std::vector<FaceId> stack{f0};
            expect[f0.idx()] = next;
            while (!stack.empty()) {
                const FaceId f = stack.back();
                stack.pop_back();
                for (uint32_t k = 0; k < 3; ++k)
                    if (const FaceId g = m.neighbor(Mesh::halfedge(f, k)); g.valid() && expect[g.idx()] == UINT32_MAX) {
                        expect[g.idx()] = next;
                        stack.push_back(g);
                    }
            }
            ++next;
        }
        EXPECT_EQ(m.component_of_faces(), expect);
        EXPECT_EQ(m.num_components(), 7u);
    }
}

// Past 2^17 faces the pairing and the fan checks run in two halves at once; the error must be
// the one a single pass gives: the defect at the lowest vertex, even when the other half has one.
TEST(Mesh, LargeMeshReportsTheFirstDefectAsOnePassWould) {
    const TriangleSoup torus = make_torus(400, 400);  // 320K faces
    const auto nv = static_cast<uint32_t>(torus.points.size());
    auto with_spike_at = [&](std::initializer_list<uint32_t> vertices) {  // a second fan at each vertex
        TriangleSoup s = torus;
        for (uint32_t v : vertices) {
            const auto a = static_cast<uint32_t>(s.points.size());
            s.points.push_back({0, 0, 5});
            s.points.push_back({0, 1, 5});
            s.triangles.push_back({v, a, a + 1});
        }
        return s;
    };
    auto message = [](const TriangleSoup& s) {
        try {
            (void)Mesh::from_soup(s);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(with_spike_at({nv - 10})).find("vertex " + std::to_string(nv - 10) + " "), std::string::npos);
    EXPECT_NE(message(with_spike_at({nv - 10, 7})).find("vertex 7 "), std::string::npos);
    // Three faces on an edge: the copy of a face near the end and one near the start.
    TriangleSoup dup = torus;
    dup.triangles.push_back(torus.triangles.back());
    EXPECT_NE(message(dup).find("non-manifold edge"), std::string::npos);
    dup.triangles.push_back(torus.triangles.front());
    const Triangle& t = torus.triangles.front();
    const std::string first_edge = "(" + std::to_string(std::min({t[0], t[1], t[2]})) + ", ";  // edges come by smaller end
    EXPECT_NE(message(dup).find("edge " + first_edge), std::string::npos) << message(dup);
    // And without defects the two halves pair every edge as one pass does.
    const Mesh m = Mesh::from_soup(torus);
    m.validate();
    EXPECT_EQ(m.num_boundary_edges(), 0u);
}

// The checks' edge pairing (PreparedSoup::twin) builds the same corner table as a second sort,
// also after --orient flipped faces; the pipeline builds its mesh from it.
TEST(Mesh, PairingFromTheChecksIsTheSortedOne) {
    std::vector<TriangleSoup> soups = {make_icosphere(3), make_genus_with_holes(2, 3, 3), make_disk_with_holes(4, 2),
                                       make_cone(300, false)};
    TriangleSoup flipped = make_torus(16, 9);
    std::mt19937 rng(5);
    for (Triangle& t : flipped.triangles)  // a consistent orientation, scrambled: --orient undoes it
        if (rng() % 3 == 0) std::swap(t[1], t[2]);
    soups.push_back(std::move(flipped));
    for (size_t i = 0; i < soups.size(); ++i) {
        SCOPED_TRACE(i);
        PreparedSoup p = prepare_soup_components(soups[i], PrepareOptions{true}, "t");
        ASSERT_EQ(p.twin.size(), 3 * p.soup.triangles.size());
        const Mesh sorted = Mesh::from_soup(p.soup);
        const Mesh paired = Mesh::from_soup(p.soup, std::move(p.twin));
        paired.validate();
        for (HalfedgeId h : IdRange<HalfedgeId>(sorted.num_halfedges())) ASSERT_EQ(paired.twin(h), sorted.twin(h));
        EXPECT_EQ(paired.genus(), sorted.genus());
    }
}

TEST(Mesh, PairingFromTheChecksIsCheckedAndPairsEveryComponent) {
    TriangleSoup two = make_icosphere(1);
    const TriangleSoup other = make_icosphere(1);
    const auto nv = static_cast<uint32_t>(two.points.size());
    two.points.insert(two.points.end(), other.points.begin(), other.points.end());
    for (Triangle t : other.triangles) two.triangles.push_back({t[0] + nv, t[1] + nv, t[2] + nv});
    PreparedSoup both = prepare_soup_components(two, PrepareOptions{}, "t");
    ASSERT_EQ(both.num_components, 2u);
    const Mesh given = Mesh::from_soup(both.soup, std::move(both.twin)), own = Mesh::from_soup(both.soup);
    given.validate();
    EXPECT_EQ(given.num_components(), 2u);
    for (const HalfedgeId h : own.halfedges()) EXPECT_EQ(given.twin(h), own.twin(h));

    const TriangleSoup s = make_grid_disk(4, 3);
    const std::vector<uint32_t> good = prepare_soup_components(s, PrepareOptions{}, "t").twin;
    auto bad = [&](auto&& change) {
        std::vector<uint32_t> t = good;
        change(t);
        return t;
    };
    const uint32_t h = static_cast<uint32_t>(std::find_if(good.begin(), good.end(), [](uint32_t t) { return t != kNone; }) - good.begin());
    EXPECT_THROW(Mesh::from_soup(s, bad([](auto& t) { t.pop_back(); })), InputError);
    EXPECT_THROW(Mesh::from_soup(s, bad([&](auto& t) { t[good[h]] = kNone; })), InputError);  // one-sided
    EXPECT_THROW(Mesh::from_soup(s, bad([&](auto& t) { t[h] = h; })), InputError);            // itself
    EXPECT_THROW(Mesh::from_soup(s, bad([&](auto& t) { std::swap(t[h], t[h - h % 3 + (h + 1) % 3]); })), InputError);
    EXPECT_NO_THROW(Mesh::from_soup(s, bad([](auto&) {})).validate());
}
