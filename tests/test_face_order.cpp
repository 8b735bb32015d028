// Faces of large shuffled soups are stripped in a Z-order of their centroids, and scattered
// vertex numbers renumbered by first use (face_order.hpp, stripify()); the outputs still verify
// against the caller's soup, and parents and vertices are the caller's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "../src/algo/face_order.hpp"
#include "fixtures.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/validate.hpp"
#include "singlestrip/verify.hpp"
#include "strip_check.hpp"

namespace singlestrip {
namespace {

/// Every input vertex of an output face is a corner of that face's parent.
bool parents_hold_their_faces(const TriangleSoup& in, const StripArrays& out) {
    for (size_t i = 0; i < out.faces.size(); ++i) {
        const Triangle& p = in.triangles[out.parent[i]];
        for (uint32_t v : out.faces[i])
            if (v < in.points.size() && std::find(p.begin(), p.end(), v) == p.end()) return false;
    }
    return true;
}

double mean_step(const TriangleSoup& s, const std::vector<uint32_t>& order) {
    auto centre = [&](uint32_t f) {
        Point3 c{};
        for (uint32_t v : s.triangles[f])
            for (int i = 0; i < 3; ++i) c[i] += s.points[v][i] / 3;
        return c;
    };
    double sum = 0;
    for (size_t i = 1; i < order.size(); ++i) {
        const Point3 a = centre(order[i - 1]), b = centre(order[i]);
        sum += std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
    }
    return sum / static_cast<double>(order.size() - 1);
}

TEST(FaceOrder, IsAPermutationThatFollowsTheSurface) {
    TriangleSoup s = make_torus(64, 32);
    shuffle_faces(s, 7);
    const std::vector<uint32_t> order = spatial_face_order(s.points, s.triangles);
    std::vector<uint32_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<uint32_t> identity(s.triangles.size());
    std::iota(identity.begin(), identity.end(), 0u);
    EXPECT_EQ(sorted, identity);
    // Consecutive faces of the curve are near each other; of the shuffle, a torus apart.
    EXPECT_LT(mean_step(s, order) * 8, mean_step(s, identity));
}

TEST(FaceOrder, NonFiniteAndFlatPointsStillGiveAPermutation) {
    TriangleSoup s = make_grid_disk(20, 20);  // flat: one axis has no extent
    s.points[0][0] = std::nan("");
    const std::vector<uint32_t> order = spatial_face_order(s.points, s.triangles);
    std::vector<char> seen(s.triangles.size(), 0);
    for (uint32_t f : order) seen[f]++;
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](char c) { return c == 1; }));
}

TEST(FaceOrder, OnlyLargeScatteredSoupsAreReordered) {
    TriangleSoup s = make_torus(363, 363);  // 263538 faces, written row by row
    EXPECT_TRUE(locality_order(s).empty());
    shuffle_faces(s, 3);
    EXPECT_EQ(locality_order(s).size(), s.triangles.size());
    TriangleSoup small = make_torus(300, 300);
    shuffle_faces(small, 3);
    EXPECT_TRUE(locality_order(small).empty());
    s.triangles[5][1] = static_cast<uint32_t>(s.points.size());  // out of range: left to the checks
    EXPECT_TRUE(locality_order(s).empty());
}

/// A large shuffled torus with two faces turned the wrong way round.
TriangleSoup shuffled_with_flips() {
    TriangleSoup s = make_torus(363, 363);
    shuffle_faces(s, 9);
    std::swap(s.triangles[17][1], s.triangles[17][2]);
    std::swap(s.triangles[40000][1], s.triangles[40000][2]);
    return s;
}

std::string refusal(const TriangleSoup& s, bool locality) {
    try {
        prepare_soup_components(s, PrepareOptions{false, locality, locality}, "t.off");
    } catch (const InputError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(FaceOrder, RefusalNamesTheGivenFaces) {
    const TriangleSoup s = shuffled_with_flips();
    const std::string plain = refusal(s, false);
    EXPECT_NE(plain, "accepted");
    EXPECT_EQ(refusal(s, true), plain);
}

TEST(FaceOrder, ReorderedSoupIsTheGivenOneOrientedAndNumberedAlike) {
    const TriangleSoup s = shuffled_with_flips();
    const PreparedSoup given = prepare_soup_components(s, PrepareOptions{true, false}, "t.off");
    const PreparedSoup local = prepare_soup_components(s, PrepareOptions{true, true}, "t.off");
    ASSERT_EQ(local.face_origin.size(), s.triangles.size());
    EXPECT_EQ(local.num_components, given.num_components);
    for (size_t i = 0; i < local.face_origin.size(); ++i) {
        ASSERT_EQ(local.soup.triangles[i], given.soup.triangles[local.face_origin[i]]) << i;
        ASSERT_EQ(local.component[i], given.component[local.face_origin[i]]) << i;
    }
}

TEST(FaceOrder, OrientationTieKeepsTheGivenLowestFace) {
    TriangleSoup s = make_torus(363, 363);
    for (size_t f = 0; f < s.triangles.size() / 2; ++f) std::swap(s.triangles[f][1], s.triangles[f][2]);
    shuffle_faces(s, 21);
    const PreparedSoup given = prepare_soup_components(s, PrepareOptions{true, false}, "t.off");
    const PreparedSoup local = prepare_soup_components(s, PrepareOptions{true, true}, "t.off");
    ASSERT_EQ(local.face_origin.size(), s.triangles.size());
    for (size_t i = 0; i < local.face_origin.size(); ++i)
        ASSERT_EQ(local.soup.triangles[i], given.soup.triangles[local.face_origin[i]]) << i;
}

/// A large torus whose vertices and faces are both shuffled; `new_of_old` maps the torus's
/// vertex numbers to the soup's.
TriangleSoup shuffled_both(std::vector<uint32_t>* new_of_old = nullptr) {
    TriangleSoup s = make_torus(363, 363);
    std::vector<uint32_t> map = shuffle_vertices(s, 13);
    shuffle_faces(s, 17);
    if (new_of_old) *new_of_old = std::move(map);
    return s;
}

TEST(VertexOrder, ShuffledVerticesAreNumberedByFirstUse) {
    const TriangleSoup s = shuffled_both();
    const PreparedSoup given = prepare_soup_components(s, PrepareOptions{false, false, false}, "t.off");
    const PreparedSoup local = prepare_soup_components(s, PrepareOptions{false, true, true}, "t.off");
    ASSERT_EQ(local.vertex_origin.size(), s.points.size());
    std::vector<uint32_t> sorted = local.vertex_origin;
    std::sort(sorted.begin(), sorted.end());
    for (uint32_t v = 0; v < sorted.size(); ++v) ASSERT_EQ(sorted[v], v);
    for (size_t i = 0; i < local.soup.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k)
            ASSERT_EQ(local.vertex_origin[local.soup.triangles[i][k]], given.soup.triangles[local.face_origin[i]][k]) << i;
    for (uint32_t v = 0; v < s.points.size(); ++v) ASSERT_EQ(local.soup.points[v], s.points[local.vertex_origin[v]]);
    // First use: the first face's corners are vertices 0, 1, 2.
    EXPECT_EQ(local.soup.triangles[0], (Triangle{0, 1, 2}));
    EXPECT_TRUE(prepare_soup_components(s, PrepareOptions{false, true, false}, "t.off").vertex_origin.empty());
}

TEST(VertexOrder, OnlyScatteredNumbersAreRenumbered) {
    TriangleSoup s = make_torus(363, 363);
    shuffle_faces(s, 3);  // rows of vertices stay local along the Z-order
    const PreparedSoup local = prepare_soup_components(s, PrepareOptions{false, true, true}, "t.off");
    EXPECT_FALSE(local.face_origin.empty());
    EXPECT_TRUE(local.vertex_origin.empty());
}

TEST(VertexOrder, PermuteVerticesAndBackRestoresTheSoup) {
    TriangleSoup s = make_torus(20, 12);
    VertexAttribute uv;
    uv.name = "TEXCOORD_0";
    uv.components = 2;
    for (size_t v = 0; v < s.points.size(); ++v) uv.values.insert(uv.values.end(), {double(v), -double(v)});
    s.attributes.push_back(uv);
    const TriangleSoup given = s;
    std::vector<uint32_t> origin(s.points.size());
    std::iota(origin.begin(), origin.end(), 0u);
    std::reverse(origin.begin(), origin.end());
    permute_vertices(s, origin, false);
    EXPECT_EQ(s.points[0], given.points.back());
    EXPECT_EQ(s.attributes[0].values[0], double(given.points.size() - 1));
    EXPECT_EQ(s.triangles[0][0], origin.size() - 1 - given.triangles[0][0]);
    permute_vertices(s, origin, true);
    EXPECT_EQ(s.points, given.points);
    EXPECT_EQ(s.triangles, given.triangles);
    EXPECT_EQ(s.attributes[0].values, given.attributes[0].values);
}

TEST(VertexOrder, RefusalNamesTheGivenVertices) {
    TriangleSoup s = shuffled_both();
    std::swap(s.triangles[17][1], s.triangles[17][2]);
    const std::string plain = refusal(s, false);
    EXPECT_NE(plain, "accepted");
    try {
        prepare_soup_components(s, PrepareOptions{false, true, true}, "t.off");
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.what(), plain);
    }
}

TEST(VertexOrder, MeshRenumberingKeepsTheInvariants) {
    Mesh m = Mesh::from_soup(make_torus(12, 8));
    m.split_edge(HalfedgeId(4));  // a midpoint keeps its number
    const auto n = m.num_input_vertices();
    std::vector<uint32_t> to(n);
    for (uint32_t v = 0; v < n; ++v) to[v] = (v * 7 + 3) % n;  // 7 is prime to 96
    const std::vector<uint32_t> before = m.corner_vertices();
    const std::vector<Point3> points = m.points();
    m.renumber_input_vertices(to);
    m.validate();
    for (size_t c = 0; c < before.size(); ++c) ASSERT_EQ(m.corner_vertices()[c], before[c] < n ? to[before[c]] : before[c]);
    for (uint32_t v = 0; v < n; ++v) ASSERT_EQ(m.points()[to[v]], points[v]);
    EXPECT_EQ(m.points().back(), points.back());
    to[0] = to[1];
    EXPECT_THROW(m.renumber_input_vertices(to), InternalError);
    to.pop_back();
    EXPECT_THROW(m.renumber_input_vertices(to), InternalError);
}

class ShuffledLarge : public EngineTest {};

/// Constraint pairs of `s`: one edge of every 20000th face (single edges never separate).
std::vector<ConstraintEdge> scattered_walls(const TriangleSoup& s) {
    std::vector<ConstraintEdge> walls;
    for (size_t f = 0; f < s.triangles.size(); f += 20000) walls.push_back({s.triangles[f][0], s.triangles[f][1], 0});
    return walls;
}

TEST_P(ShuffledLarge, ShuffledVerticesComeBackInTheGivenNumbers) {
    const TriangleSoup s0 = shuffled_both();
    TriangleSoup s = s0;
    VertexAttribute id;
    id.name = "_ID";
    for (size_t v = 0; v < s.points.size(); ++v) id.values.push_back(static_cast<double>(v));
    s.attributes.push_back(id);
    PipelineOptions o;
    o.strip = opts();
    o.strip.constraint_edges = scattered_walls(s);
    o.self_check = true;
    o.release_intermediates = false;
    ASSERT_FALSE(prepare_soup_components(s, PrepareOptions{false, true, true}, "t.off").vertex_origin.empty()) << "not renumbered";
    const PipelineResult r = stripify(s, o);
    EXPECT_EQ(r.options.strip.constraint_edges, o.strip.constraint_edges);
    EXPECT_EQ(r.input.points, s.points);
    for (size_t v = 0; v < s.points.size(); ++v) {
        ASSERT_EQ(r.arrays.points[v], s.points[v]);
        ASSERT_EQ(r.arrays.attributes.at(0).values.at(v), static_cast<double>(v));
    }
    r.strip.mesh.validate();
    EXPECT_TRUE(std::equal(s.points.begin(), s.points.end(), r.strip.mesh.points().begin()));
    EXPECT_TRUE(parents_hold_their_faces(s, r.arrays));
    VerifyInput vi = verify_input(s0, r.arrays, r.indices);
    for (const ConstraintEdge& e : o.strip.constraint_edges) vi.constraints.emplace_back(e.a, e.b);
    const VerifyReport rep = verify(vi);
    EXPECT_TRUE(rep.ok()) << rep.to_string();
}

TEST_P(ShuffledLarge, ShuffledVerticesWithSourceAndTargetAndRestarts) {
    TriangleSoup s = shuffled_both();
    const TriangleSoup b = make_torus(40, 40);  // a second component: restart joins
    const auto base = static_cast<uint32_t>(s.points.size());
    for (Point3 p : b.points) s.points.push_back({p[0] + 10, p[1], p[2]});
    for (Triangle t : b.triangles) s.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    PipelineOptions o;
    o.strip = opts();
    o.join = JoinMode::Restart;
    for (const bool ends : {false, true}) {
        if (ends) o.strip.source = VertexId(s.triangles[5][0]), o.strip.target = VertexId(s.triangles[9][2]);
        const PipelineResult r = stripify(s, o);
        VerifyInput vi = verify_input(s, r.arrays, r.indices);
        vi.restart_index = o.restart_index;
        if (ends) vi.source = s.triangles[5][0], vi.target = s.triangles[9][2];
        const VerifyReport rep = verify(vi);
        EXPECT_TRUE(rep.ok()) << rep.to_string();
    }
}

TEST(VertexOrder, ConstraintMessageNamesTheGivenVertices) {
    const TriangleSoup s = shuffled_both();
    const uint32_t a = s.triangles[0][0], far = s.triangles[s.triangles.size() / 2][0];
    PipelineOptions o;
    o.strip.constraint_edges = {{a, far, 0}};
    try {
        (void)stripify(s, o);
        ADD_FAILURE() << "accepted";
    } catch (const RequestError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "constraint 0: (" + std::to_string(a) + ", " + std::to_string(far) + ") is not an edge of the mesh");
    }
}

// 2 * 363 * 363 = 263538 faces: above the size from which stripify() reorders.
TEST_P(ShuffledLarge, ReorderedStripVerifiesWithTheCallersFaces) {
    TriangleSoup s = make_torus(363, 363);
    shuffle_faces(s, 11);
    PipelineOptions o;
    o.strip = opts();
    o.self_check = true;
    const PipelineResult r = stripify(s, o);
    EXPECT_EQ(r.face_origin.size(), s.triangles.size()) << "the shuffled soup was not reordered";
    EXPECT_TRUE(parents_hold_their_faces(s, r.arrays));
    const VerifyReport rep = verify(verify_input(s, r.arrays, r.indices));
    EXPECT_TRUE(rep.ok()) << rep.to_string();
}

TEST_P(ShuffledLarge, OrderedSoupIsLeftAsItIs) {
    const TriangleSoup s = make_torus(363, 363);
    PipelineOptions o;
    o.strip = opts();
    const PipelineResult r = stripify(s, o);
    EXPECT_TRUE(r.face_origin.empty());
}

TEST_P(ShuffledLarge, SeveralComponentsAndAttributesFollowTheirFaces) {
    TriangleSoup s = make_torus(370, 370);  // with the small one: 276,000 faces
    const TriangleSoup b = make_torus(40, 40);
    const auto base = static_cast<uint32_t>(s.points.size());
    for (Point3 p : b.points) s.points.push_back({p[0] + 10, p[1], p[2]});
    for (Triangle t : b.triangles) s.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    VertexAttribute id;
    id.name = "_ID";
    id.components = 1;
    for (size_t v = 0; v < s.points.size(); ++v) id.values.push_back(static_cast<double>(v));
    s.attributes.push_back(id);
    shuffle_faces(s, 5);
    PipelineOptions o;
    o.strip = opts();
    o.self_check = true;
    const PipelineResult r = stripify(s, o);
    EXPECT_EQ(r.components.size(), 2u);
    EXPECT_FALSE(r.face_origin.empty());
    EXPECT_TRUE(parents_hold_their_faces(s, r.arrays));
    for (size_t v = 0; v < s.points.size(); ++v) ASSERT_EQ(r.arrays.attributes.at(0).values.at(v), static_cast<double>(v));
    const VerifyReport rep = verify(verify_input(s, r.arrays, r.indices));
    EXPECT_TRUE(rep.ok()) << rep.to_string();
}

INSTANTIATE_TEST_SUITE_P(Engines, ShuffledLarge, kBothEngines, engine_test_name);

}  // namespace
}  // namespace singlestrip
