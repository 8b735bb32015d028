// Repair (repair.hpp), several components (pipeline.hpp) and their verification: every class of
// broken input strips with repair and passes the independent verifier.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "cgal_data.hpp"
#include "fixtures.hpp"
#include "shell.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/repair.hpp"
#include "singlestrip/validate.hpp"
#include "singlestrip/verify.hpp"

using namespace singlestrip;

using singlestrip::test::test_data;

namespace {

void flip(TriangleSoup& s, size_t f) {
    std::swap(s.triangles[f][1], s.triangles[f][2]);
}

/// Strips `soup` with `o` and verifies the result (arrays, parents, indices) against the input
/// replayed through the same steps.
VerifyReport strip_and_verify(const TriangleSoup& soup, PipelineOptions o, PipelineResult* out = nullptr) {
    o.self_check = true;
    PipelineResult r = stripify(soup, o);
    VerifyInput vi = verify_input(soup, r.arrays, r.indices);
    vi.restart_index = o.restart_index;
    vi.source = index_of(o.strip.source);
    vi.target = index_of(o.strip.target);
    vi.constraints = vertex_pairs(o.strip.constraint_edges);
    const auto notes = replay_input_steps(vi, {o.weld, o.repair, o.orient});
    VerifyReport rep = verify(vi);
    rep.notes.insert(rep.notes.begin(), notes.begin(), notes.end());
    if (out) *out = std::move(r);
    return rep;
}

PipelineOptions repair_options() {
    PipelineOptions o;
    o.repair = true;
    return o;
}

/// Every vertex copied to its own slot per face: a soup as some exporters write it.
TriangleSoup unweld(const TriangleSoup& s) {
    TriangleSoup u;
    for (const Triangle& t : s.triangles) {
        const auto base = static_cast<uint32_t>(u.points.size());
        for (uint32_t v : t) u.points.push_back(s.points[v]);
        u.triangles.push_back({base, base + 1, base + 2});
    }
    return u;
}

/// The faces with each one's vertices rotated to start at its smallest (winding kept).
std::vector<Triangle> canonical(std::vector<Triangle> faces) {
    for (Triangle& t : faces) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return faces;
}

}  // namespace

TEST(Repair, EachBrokenTestFileStripsWithRepairAndVerifies) {
    for (const char* f : {"repeated_vertex.off", "duplicate_face.off", "non_manifold_edge.off", "non_manifold_vertex.off",
                          "tetra_one_flipped.off", "moebius.off", "two_components.off"}) {
        SCOPED_TRACE(f);
        const TriangleSoup s = read_mesh_file(test_data(f));
        const VerifyReport rep = strip_and_verify(s, repair_options());
        EXPECT_TRUE(rep.ok()) << rep.to_string();
    }
}

TEST(Repair, DropsDegenerateAndDuplicateFacesKeepingTheFirst) {
    TriangleSoup s = make_icosphere(1);
    const auto n = static_cast<uint32_t>(s.triangles.size());
    s.triangles.push_back(s.triangles[3]);                                             // same face again
    s.triangles.push_back({s.triangles[5][0], s.triangles[5][2], s.triangles[5][1]});  // reversed copy
    s.triangles.push_back({0, 0, 1});                                                  // repeated vertex
    const RepairedSoup r = repair_soup(s);
    EXPECT_EQ(r.report.duplicate_faces, (std::vector<uint32_t>{n, n + 1}));
    EXPECT_EQ(r.report.degenerate_faces, (std::vector<uint32_t>{n + 2}));
    EXPECT_EQ(r.soup.triangles.size(), n);
    for (uint32_t t = 0; t < n; ++t) EXPECT_EQ(r.face_origin[t], t);
    EXPECT_TRUE(diagnose_soup(r.soup).empty());
    EXPECT_TRUE(strip_and_verify(s, repair_options()).ok());
}

TEST(Repair, CutsNonManifoldEdgesAndVerticesByCopyingVertices) {
    // Three fins on one edge, and two cones touching at a vertex.
    const TriangleSoup fins = read_mesh_file(test_data("non_manifold_edge.off"));
    const RepairedSoup r = repair_soup(fins);
    EXPECT_EQ(r.report.non_manifold_edges.size(), 1u);
    EXPECT_FALSE(r.report.copied_from.empty());
    EXPECT_EQ(r.soup.points.size(), fins.points.size() + r.report.copied_from.size());
    for (size_t j = 0; j < r.report.copied_from.size(); ++j)  // copies sit where their originals are
        EXPECT_EQ(r.soup.points[fins.points.size() + j], fins.points[r.report.copied_from[j]]);
    EXPECT_TRUE(diagnose_soup(r.soup).empty());
    const TriangleSoup pinch = read_mesh_file(test_data("non_manifold_vertex.off"));
    const RepairedSoup p = repair_soup(pinch);
    EXPECT_EQ(p.report.split_vertices, (std::vector<uint32_t>{0}));
    EXPECT_TRUE(diagnose_soup(p.soup).empty());
}

TEST(Repair, MostFacesFlippedEndsOutward) {
    for (const TriangleSoup& good : {make_icosphere(2), make_torus(12, 8), make_genus_surface(2, 4)}) {
        TriangleSoup bad = good;
        for (size_t f = 0; f < bad.triangles.size(); ++f)
            if (f % 7 != 0) flip(bad, f);
        ASSERT_GT(signed_volume(good.points, good.triangles), 0);
        const RepairedSoup r = repair_soup(bad);
        EXPECT_GT(signed_volume(r.soup.points, r.soup.triangles), 0);
        EXPECT_EQ(r.soup.triangles, good.triangles);
        EXPECT_EQ(r.report.turned_outward, 1u);
        PipelineResult res;
        EXPECT_TRUE(strip_and_verify(bad, repair_options(), &res).ok());
        EXPECT_GT(signed_volume(res.arrays.points, res.arrays.faces), 0);
        // Inside out as a whole: repair turns it outward; --orient alone keeps the majority.
        TriangleSoup inside = good;
        for (size_t f = 0; f < inside.triangles.size(); ++f) flip(inside, f);
        EXPECT_EQ(repair_soup(inside).soup.triangles, good.triangles);
    }
}

TEST(Repair, MoebiusIsCutIntoAnOrientablePiece) {
    for (uint32_t n : {5u, 7u, 12u}) {
        SCOPED_TRACE(n);
        const TriangleSoup band = make_moebius_soup(n);
        const RepairedSoup r = repair_soup(band);
        EXPECT_EQ(r.report.non_orientable_components, 1u);
        EXPECT_FALSE(r.report.orientation_cuts.empty());
        EXPECT_FALSE(r.report.copied_from.empty());
        EXPECT_EQ(r.soup.triangles.size(), band.triangles.size());
        EXPECT_TRUE(diagnose_soup(r.soup).empty());
        const VerifyReport rep = strip_and_verify(band, repair_options());
        EXPECT_TRUE(rep.ok()) << rep.to_string();
    }
}

TEST(Repair, UnweldedSoupIsWeldedIntoOneStrip) {
    const TriangleSoup good = make_torus(10, 6);
    const TriangleSoup soup = unweld(good);
    PipelineOptions plain;
    const PipelineResult many = stripify(soup, plain);
    EXPECT_EQ(many.components.size(), soup.triangles.size());  // one strip per triangle ...
    ASSERT_EQ(many.warnings.size(), 1u);                       // ... and a hint to weld
    EXPECT_NE(many.warnings[0].find("--weld"), std::string::npos) << many.warnings[0];
    for (bool weld_only : {true, false}) {
        PipelineOptions o;
        (weld_only ? o.weld : o.repair) = true;
        PipelineResult r;
        const VerifyReport rep = strip_and_verify(soup, o, &r);
        EXPECT_TRUE(rep.ok()) << rep.to_string();
        EXPECT_EQ(r.components.size(), 1u);
        EXPECT_EQ(r.strip.stats.genus, 1);
    }
}

TEST(Components, OneStripPerComponentWithEitherJoin) {
    // Three separate surfaces: a sphere, a torus (shifted), a disk (shifted).
    TriangleSoup s = make_icosphere(1);
    for (const TriangleSoup& part : {make_torus(8, 5), make_grid_disk(4, 3)}) {
        const auto base = static_cast<uint32_t>(s.points.size());
        const double shift = 10.0 * static_cast<double>(s.triangles.size());
        for (Point3 p : part.points) s.points.push_back({p[0] + shift, p[1], p[2]});
        for (Triangle t : part.triangles) s.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    for (JoinMode join : {JoinMode::Degenerate, JoinMode::Restart}) {
        PipelineOptions o;
        o.join = join;
        PipelineResult r;
        const VerifyReport rep = strip_and_verify(s, o, &r);
        EXPECT_TRUE(rep.ok()) << rep.to_string();
        EXPECT_EQ(rep.strips, 3u);
        ASSERT_EQ(r.components.size(), 3u);
        EXPECT_EQ(
            canonical(decode_triangle_strip(r.indices, join == JoinMode::Restart ? std::optional<uint32_t>(0xffffffffu) : std::nullopt)),
            canonical(r.arrays.faces));
        EXPECT_EQ(canonical(decode_triangle_strip(degenerate_joined_indices(r))), canonical(r.arrays.faces));
        const auto restarts = std::count(r.indices.begin(), r.indices.end(), 0xffffffffu);
        EXPECT_EQ(restarts, join == JoinMode::Restart ? 2 : 0);
    }
    // source and target pick the first strip; in two components they are refused by name.
    PipelineOptions o;
    const uint32_t torus_vertex = static_cast<uint32_t>(make_icosphere(1).points.size()) + 3;
    o.strip.source = VertexId(torus_vertex);
    PipelineResult r;
    EXPECT_TRUE(strip_and_verify(s, o, &r).ok());
    EXPECT_EQ(r.components[0].input_triangles, make_torus(8, 5).triangles.size());
    o.strip.target = VertexId(0);
    PipelineStage stage = PipelineStage::Done;
    try {
        stripify(s, o, &stage);
        ADD_FAILURE() << "source and target in different components";
    } catch (const RequestError& e) {
        EXPECT_NE(std::string(e.what()).find("same component"), std::string::npos) << e.what();
        EXPECT_EQ(stage, PipelineStage::Strip) << "a request error belongs to the strip stage (the fuzz check expects it there)";
    }
    // Constraint edges go to the component holding them; a pair across components is no edge.
    PipelineOptions c;
    const Triangle& t = s.triangles[make_icosphere(1).triangles.size() + 5];  // a torus face
    c.strip.constraint_edges = {{t[0], t[1]}, {s.triangles[0][0], s.triangles[0][1]}};
    EXPECT_TRUE(strip_and_verify(s, c).ok());
    c.strip.constraint_edges = {{0, t[0]}};
    try {
        stripify(s, c);
        ADD_FAILURE() << "a constraint across components";
    } catch (const RequestError& e) {
        EXPECT_NE(std::string(e.what()).find("is not an edge of the mesh"), std::string::npos) << e.what();
    }
}

TEST(Components, VerifierRejectsAComponentSplitIntoTwoRuns) {
    TriangleSoup s = make_icosphere(0);
    const auto base = static_cast<uint32_t>(s.points.size());
    for (Point3 p : make_icosphere(0).points) s.points.push_back({p[0] + 5, p[1], p[2]});
    for (Triangle t : make_icosphere(0).triangles) s.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    const PipelineResult r = stripify(s, PipelineOptions{});
    VerifyInput vi = verify_input(s, r.arrays, r.indices);
    vi.indices.reset();  // the faces are reordered below; the indices would no longer match
    EXPECT_TRUE(verify(vi).ok());
    // Move the first face of the first strip to the end: that component is now two runs.
    std::rotate(vi.out_faces.begin(), vi.out_faces.begin() + 1, vi.out_faces.end());
    std::rotate(vi.out_parent.begin(), vi.out_parent.begin() + 1, vi.out_parent.end());
    const VerifyReport bad = verify(vi);
    EXPECT_FALSE(bad.ok());
    EXPECT_NE(bad.to_string().find("already stripped"), std::string::npos) << bad.to_string();
}

TEST(RepairReal, RefusedCgalDemoMeshesStripWithRepair) {
    for (const char* f : {"pig.stl", "polygon_mesh.off", "tet-shuffled.off", "cube-shuffled.off", "blobby_3cc.off", "knot2.off",
                          "tetra_intersected_by_triangle.off", "quads_to_stitch.off", "fold.off"}) {
        SCOPED_TRACE(f);
        const std::string path = test::cgal_mesh_path(f);
        if (path.empty()) GTEST_SKIP() << "libcgal-demo data not available";
        const TriangleSoup s = read_mesh_file(path);
        const VerifyReport rep = strip_and_verify(s, repair_options());
        EXPECT_TRUE(rep.ok()) << rep.to_string();
    }
}

TEST(Repair, RandomlyBrokenSoupsAlwaysRepairStripAndVerify) {
    // Scrambled real structure: random vertex merges (pinches, non-manifold edges, folds),
    // flipped, duplicated and dropped faces. Repair must always end in a strippable soup.
    std::mt19937 rng(12345);
    const std::vector<TriangleSoup> bases = {make_torus(9, 6), make_icosphere(1), make_genus_with_holes(2, 1, 3), make_moebius_soup(9)};
    for (int round = 0; round < 200; ++round) {
        SCOPED_TRACE(round);
        TriangleSoup s = bases[static_cast<size_t>(round) % bases.size()];
        const auto nv = static_cast<uint32_t>(s.points.size());
        std::uniform_int_distribution<uint32_t> vert(0, nv - 1);
        for (int k = 0; k < 1 + round % 13; ++k) {  // glue two vertices: re-point faces of one to the other
            const uint32_t a = vert(rng), b = vert(rng);
            for (Triangle& t : s.triangles)
                for (uint32_t& v : t)
                    if (v == a) v = b;
        }
        std::uniform_int_distribution<size_t> face(0, s.triangles.size() - 1);
        for (int k = 0; k < round % 7; ++k) flip(s, face(rng));
        for (int k = 0; k < round % 3; ++k) s.triangles.push_back(s.triangles[face(rng)]);
        if (round % 4 == 0) s.triangles.erase(s.triangles.begin() + static_cast<std::ptrdiff_t>(face(rng)));
        const RepairedSoup r = repair_soup(s);  // throws InternalError if a post-condition fails
        if (r.soup.triangles.empty()) continue;
        const VerifyReport rep = strip_and_verify(s, repair_options());
        EXPECT_TRUE(rep.ok()) << rep.to_string();
    }
}
