// Structural diagnosis, --orient, and mesh_info on procedural, hand-made and libcgal-demo meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "cgal_data.hpp"
#include "fixtures.hpp"
#include "shell.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/validate.hpp"

using namespace singlestrip;

using singlestrip::test::test_data;

namespace {

std::vector<std::string> kinds(const std::vector<SoupProblem>& ps) {
    std::vector<std::string> k;
    for (const auto& p : ps) k.push_back(p.kind);
    return k;
}

bool has(const std::vector<SoupProblem>& ps, const std::string& kind, const std::vector<std::string>& needles) {
    for (const auto& p : ps) {
        if (p.kind != kind) continue;
        if (std::all_of(needles.begin(), needles.end(), [&](const std::string& n) { return p.message.find(n) != std::string::npos; }))
            return true;
    }
    return false;
}

std::string prepare_error(const TriangleSoup& s, const std::string& name, bool orient = false) {
    try {
        prepare_soup(s, PrepareOptions{orient}, name);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

void flip(TriangleSoup& s, size_t f) {
    std::swap(s.triangles[f][1], s.triangles[f][2]);
}

}  // namespace

TEST(Diagnose, ValidProceduralMeshesHaveNoProblemsAndRightTopology) {
    struct Case {
        const char* name;
        TriangleSoup soup;
        long long chi;
        uint64_t loops;
        long long genus;
    };
    const std::vector<Case> cases = {
        {"icosphere", make_icosphere(2), 2, 0, 0},      {"torus", make_torus(12, 8), 0, 0, 1},
        {"genus3", make_genus_surface(3, 2), -4, 0, 3}, {"disk with 3 holes", make_disk_with_holes(3, 2), -2, 4, 0},
        {"annulus", make_annulus(8, 2), 0, 2, 0},       {"grid", make_grid_disk(4, 3), 1, 1, 0},
        {"builtin", make_builtin_model(), -2, 0, 2},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_TRUE(diagnose_soup(c.soup).empty());
        MeshInfo m = mesh_info(c.soup);
        EXPECT_TRUE(m.valid());
        EXPECT_EQ(m.components, 1u);
        EXPECT_EQ(m.euler_characteristic, c.chi);
        EXPECT_EQ(m.boundary_loops, c.loops);
        ASSERT_TRUE(m.genus_valid);
        EXPECT_EQ(m.genus, c.genus);
        EXPECT_TRUE(m.orientable);
        EXPECT_TRUE(m.oriented);
        EXPECT_EQ(m.faces, c.soup.triangles.size());
        EXPECT_EQ(m.referenced_vertices, c.soup.points.size());
        // Counting identities that hold for any manifold: 3F = 2E - boundary edges.
        EXPECT_EQ(3 * m.faces, 2 * m.edges - m.boundary_edges);
        // Agreement with the mesh core, which counts on its corner table (the edge classifier
        // and the genus formula are shared: src/core/soup_edges.hpp, topology.hpp).
        Mesh mesh = Mesh::from_soup(prepare_soup(c.soup, {}, c.name));
        EXPECT_EQ(mesh.num_boundary_loops(), m.boundary_loops);
        EXPECT_EQ(mesh.euler_characteristic(), m.euler_characteristic);
        EXPECT_EQ(mesh.genus(), m.genus);
    }
}

TEST(Diagnose, EachStructuralProblemIsNamed) {
    auto probs = [](const char* f) { return diagnose_soup(read_mesh_file(test_data(f))); };
    EXPECT_TRUE(has(probs("repeated_vertex.off"), "repeated_vertex", {"face 4", "repeats a vertex"}));
    EXPECT_TRUE(has(probs("duplicate_face.off"), "duplicate_face", {"faces 3, 4", "duplicates"}));
    EXPECT_TRUE(has(probs("non_manifold_edge.off"), "non_manifold_edge", {"edge (0, 1)", "3 faces", "(0, 1, 2)"}));
    const auto nmv = probs("non_manifold_vertex.off");
    EXPECT_EQ(kinds(nmv), std::vector<std::string>{"non_manifold_vertex"});
    EXPECT_TRUE(has(nmv, "non_manifold_vertex", {"vertex 0", "2 separate fans"}));
    EXPECT_TRUE(has(probs("tetra_one_flipped.off"), "inconsistent_orientation", {"edge (0, 2)", "faces 0 and 2"}));
    // Several components are not a problem (one strip each); mesh_info still counts them.
    EXPECT_TRUE(probs("two_components.off").empty());
    const MeshInfo m = mesh_info(read_mesh_file(test_data("two_components.off")));
    EXPECT_EQ(m.components, 3u);
    EXPECT_EQ(m.component_sizes, (std::vector<uint64_t>{4, 4, 1}));
}

TEST(Diagnose, ErrorsNameTheOptionThatFixesThem) {
    const std::vector<std::pair<const char*, const char*>> cases = {
        {"repeated_vertex.off", "--repair drops faces that repeat a vertex"},
        {"duplicate_face.off", "--repair drops duplicate faces"},
        {"non_manifold_edge.off", "--repair cuts non-manifold edges and vertices apart"},
        {"non_manifold_vertex.off", "--repair cuts non-manifold edges and vertices apart"},
        {"tetra_one_flipped.off", "(fix: --orient or --repair re-orients the faces)"},
        {"moebius.off", "--repair cuts a non-orientable surface into an orientable piece"}};
    for (const auto& [file, hint] : cases) {
        SCOPED_TRACE(file);
        const std::string msg = prepare_error(read_mesh_file(test_data(file)), file);
        EXPECT_NE(msg.find(hint), std::string::npos) << msg;
    }
}

TEST(Diagnose, MoebiusIsNonOrientableAndOrientCannotFixIt) {
    for (const TriangleSoup& s : {read_mesh_file(test_data("moebius.off")), make_moebius_soup(7)}) {
        const auto ps = diagnose_soup(s);
        EXPECT_TRUE(has(ps, "non_orientable", {"not orientable", "edge ("}));
        MeshInfo m = mesh_info(s);
        EXPECT_FALSE(m.orientable);
        EXPECT_FALSE(m.genus_valid);
        TriangleSoup copy = s;
        EXPECT_EQ(orient_soup(copy), -1);
        EXPECT_EQ(copy.triangles, s.triangles);
        const std::string msg = prepare_error(s, "band.off", /*orient=*/true);
        EXPECT_EQ(msg.rfind("band.off: ", 0), 0u) << msg;
        EXPECT_NE(msg.find("not orientable"), std::string::npos) << msg;
    }
}

TEST(Orient, FlipsAnOrientableMeshConsistentlyKeepingFaceZero) {
    TriangleSoup good = make_torus(10, 6);
    TriangleSoup bad = good;
    // Flip a scattered subset of faces, but not face 0.
    for (size_t f = 1; f < bad.triangles.size(); f += 3) flip(bad, f);
    const std::string msg = prepare_error(bad, "torus.off");
    EXPECT_EQ(msg.rfind("torus.off: ", 0), 0u) << msg;
    EXPECT_NE(msg.find("inconsistent orientation"), std::string::npos) << msg;
    TriangleSoup fixed = prepare_soup(bad, PrepareOptions{true}, "torus.off");
    EXPECT_EQ(fixed.triangles, good.triangles);  // exactly the original orientation restored
    EXPECT_NO_THROW(Mesh::from_soup(fixed).validate());

    // Face 0 flipped: the majority wins, so only face 0 is flipped back (it used to turn the
    // whole mesh to face 0's orientation).
    TriangleSoup bad0 = good;
    flip(bad0, 0);
    TriangleSoup fixed0 = bad0;
    EXPECT_EQ(orient_soup(fixed0), 1);
    EXPECT_EQ(fixed0.triangles, good.triangles);
    EXPECT_TRUE(diagnose_soup(fixed0).empty());
}

TEST(Orient, NeverFlipsMostOfAComponent) {
    const TriangleSoup good = make_torus(10, 6);
    TriangleSoup bad = good;
    size_t flipped = 0;
    for (size_t f = 0; f < bad.triangles.size(); ++f)
        if (f % 7 != 0) {
            flip(bad, f);
            ++flipped;
        }
    TriangleSoup fixed = bad;
    const long long n = orient_soup(fixed);
    EXPECT_EQ(n, static_cast<long long>(bad.triangles.size() - flipped));
    EXPECT_LE(2 * n, static_cast<long long>(bad.triangles.size()));
    EXPECT_TRUE(diagnose_soup(fixed).empty());
    EXPECT_EQ(prepare_soup(bad, PrepareOptions{true}, "t.off").triangles, fixed.triangles);
}

TEST(Orient, OrientDoesNotHideOtherProblems) {
    TriangleSoup s = read_mesh_file(test_data("duplicate_face.off"));
    flip(s, 0);
    const std::string msg = prepare_error(s, "dup.off", true);
    EXPECT_NE(msg.find("duplicates"), std::string::npos) << msg;
}

TEST(Diagnose, IndexOutOfRangeInSoupArrays) {
    TriangleSoup s = make_two_triangles();
    s.triangles[1][2] = 17;
    EXPECT_TRUE(has(diagnose_soup(s), "index_out_of_range", {"face 1", "vertex 17", "only 4 vertices"}));
    TriangleSoup empty;
    EXPECT_EQ(kinds(diagnose_soup(empty)), std::vector<std::string>{"no_faces"});
}

TEST(Diagnose, ManyProblemsAreCappedAndCounted) {
    TriangleSoup s;
    for (uint32_t i = 0; i < 30; ++i) {  // 30 separate triangles -> one components problem
        s.points.push_back({double(i), 0, 0});
        s.points.push_back({double(i), 1, 0});
        s.points.push_back({double(i), 0, 1});
        s.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 1});  // each repeats a vertex
    }
    const auto ps = diagnose_soup(s);
    EXPECT_LE(ps.size(), 12u);
    EXPECT_TRUE(has(ps, "repeated_vertex", {"and 20 more"}));
    const std::string msg = prepare_error(s, "many.off");
    EXPECT_NE(msg.find("and 25 more problems"), std::string::npos) << msg;
}

TEST(DiagnoseReal, BrokenCgalDemoMeshesGiveCleanErrors) {
    struct Case {
        const char* file;
        const char* kind;
        const char* needle;
    };
    const std::vector<Case> cases = {
        {"tet-shuffled.off", "inconsistent_orientation", "both run from"},
        {"cube-shuffled.off", "inconsistent_orientation", "both run from"},
        {"polygon_mesh.off", "non_manifold_vertex", "separate fans"},
        {"pig.stl", "non_manifold_vertex", "separate fans"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.file);
        const std::string path = test::cgal_mesh_path(c.file);
        if (path.empty()) GTEST_SKIP() << "libcgal-demo data not available";
        const TriangleSoup s = read_mesh_file(path);
        EXPECT_TRUE(has(diagnose_soup(s), c.kind, {c.needle}));
        const std::string msg = prepare_error(s, path);
        EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
    }
    // Several components are valid now: one strip each.
    for (const char* f : {"blobby_3cc.off", "knot2.off"}) {
        SCOPED_TRACE(f);
        EXPECT_TRUE(diagnose_soup(read_mesh_file(test::cgal_mesh_path(f))).empty());
    }
    // Shuffled orientations are fixable with --orient, quads included.
    for (const char* f : {"tet-shuffled.off", "cube4-shuffled.off", "blobby-shuffled.off", "oblong-shuffled.off"}) {
        SCOPED_TRACE(f);
        const std::string path = test::cgal_mesh_path(f);
        const TriangleSoup s = read_mesh_file(path);
        TriangleSoup fixed = prepare_soup(s, PrepareOptions{true}, path);
        EXPECT_NO_THROW(Mesh::from_soup(fixed).validate());
        size_t flipped = 0;
        for (size_t t = 0; t < s.triangles.size(); ++t) flipped += fixed.triangles[t] != s.triangles[t] ? 1 : 0;
        EXPECT_LE(2 * flipped, s.triangles.size());  // the majority's orientation is kept
    }
    // A point cloud (no faces) is a read error.
    const std::string b9 = test::cgal_mesh_path("b9.ply");
    try {
        read_mesh_file(b9);
        ADD_FAILURE() << "b9.ply has no faces";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("no faces"), std::string::npos) << e.what();
    }
}

TEST(DiagnoseReal, InfoMatchesKnownTopology) {
    for (const test::KnownTopology& c : test::known_topologies()) {
        SCOPED_TRACE(c.name);
        const std::string path = test::cgal_mesh_path(c.name);
        if (path.empty()) GTEST_SKIP();
        MeshInfo m = mesh_info(read_mesh_file(path));
        EXPECT_TRUE(m.valid());
        EXPECT_EQ(m.genus, c.genus);
        EXPECT_EQ(m.boundary_loops, c.boundary_loops);
    }
}

namespace {

std::vector<std::string> messages_of(const std::vector<SoupProblem>& ps, const std::string& kind) {
    std::vector<std::string> m;
    for (const auto& p : ps)
        if (p.kind == kind) m.push_back(p.message);
    return m;
}

// Brute-force references for the linear-time duplicate and fan detection in validate.cpp.
std::vector<std::string> reference_duplicates(const TriangleSoup& s) {
    std::map<std::array<uint32_t, 3>, std::vector<size_t>> groups;  // ordered by sorted triple
    for (size_t f = 0; f < s.triangles.size(); ++f) {
        auto t = s.triangles[f];
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
        if (std::max({t[0], t[1], t[2]}) >= s.points.size()) continue;
        std::array<uint32_t, 3> key{t[0], t[1], t[2]};
        std::sort(key.begin(), key.end());
        groups[key].push_back(f);
    }
    std::vector<std::string> out;
    for (const auto& [key, faces] : groups) {
        if (faces.size() < 2) continue;
        std::string list;
        for (size_t i = 0; i < faces.size(); ++i) list += (i ? ", " : "") + std::to_string(faces[i]);
        out.push_back("faces " + list + " are duplicates (same vertices " + std::to_string(key[0]) + ", " + std::to_string(key[1]) + ", " +
                      std::to_string(key[2]) + ")");
    }
    return out;
}

std::vector<std::string> reference_fans(const TriangleSoup& s) {
    std::vector<std::string> out;
    const auto usable = [&](const Triangle& t) {
        return t[0] != t[1] && t[1] != t[2] && t[0] != t[2] && std::max({t[0], t[1], t[2]}) < s.points.size();
    };
    for (uint32_t v = 0; v < s.points.size(); ++v) {
        std::vector<size_t> at;  // usable faces at v
        for (size_t f = 0; f < s.triangles.size(); ++f)
            if (usable(s.triangles[f]) && std::find(s.triangles[f].begin(), s.triangles[f].end(), v) != s.triangles[f].end())
                at.push_back(f);
        std::vector<size_t> comp(at.size());
        std::iota(comp.begin(), comp.end(), size_t{0});
        // Faces at v sharing an edge (v, w) are in one fan; relabel until stable (tiny inputs).
        for (bool changed = true; changed;) {
            changed = false;
            for (size_t i = 0; i < at.size(); ++i)
                for (size_t j = 0; j < at.size(); ++j) {
                    if (comp[i] == comp[j]) continue;
                    bool share = false;
                    for (uint32_t w : s.triangles[at[i]])
                        if (w != v && std::find(s.triangles[at[j]].begin(), s.triangles[at[j]].end(), w) != s.triangles[at[j]].end())
                            share = true;
                    if (share) {
                        const size_t lo = std::min(comp[i], comp[j]);
                        comp[i] = comp[j] = lo;
                        changed = true;
                    }
                }
        }
        std::sort(comp.begin(), comp.end());
        const auto fans = static_cast<size_t>(std::unique(comp.begin(), comp.end()) - comp.begin());
        if (fans > 1)
            out.push_back("vertex " + std::to_string(v) + " is where " + std::to_string(fans) +
                          " separate fans of faces meet (non-manifold vertex)");
    }
    return out;
}

}  // namespace

// The duplicate-face and fan reports come from linear passes over the edge groups; they must
// list exactly what a brute-force search finds, in the same order, on random (mostly broken)
// soups. prepare_soup with orient (one analysis) must also agree with orient_soup followed by
// validate_soup (two analyses).
TEST(Diagnose, DuplicatesFansAndOrientMatchBruteForceOnRandomSoups) {
    std::mt19937 rng(20261122);
    size_t with_duplicates = 0, with_fans = 0, accepted = 0;
    for (int iter = 0; iter < 3000; ++iter) {
        TriangleSoup s;
        const uint32_t nv = 3 + rng() % 6;
        for (uint32_t v = 0; v < nv; ++v) s.points.push_back({double(v), double(v * v % 7), double(v % 3)});
        const size_t nf = 1 + rng() % 9;
        for (size_t f = 0; f < nf; ++f) {
            if (f > 0 && rng() % 4 == 0) {  // repeat an earlier face, sometimes reversed or rotated
                Triangle t = s.triangles[rng() % f];
                if (rng() % 2) std::swap(t[1], t[2]);
                if (rng() % 2) std::rotate(t.begin(), t.begin() + 1, t.end());
                s.triangles.push_back(t);
            } else {
                s.triangles.push_back({uint32_t(rng() % nv), uint32_t(rng() % nv), uint32_t(rng() % (nv + (rng() % 8 == 0)))});
            }
        }
        const auto ps = diagnose_soup(s);
        const auto dup = reference_duplicates(s), fans = reference_fans(s);
        if (dup.size() <= 10) {
            EXPECT_EQ(messages_of(ps, "duplicate_face"), dup) << "iteration " << iter;
        }
        if (fans.size() <= 10) {
            EXPECT_EQ(messages_of(ps, "non_manifold_vertex"), fans) << "iteration " << iter;
        }
        with_duplicates += !dup.empty();
        with_fans += !fans.empty();

        TriangleSoup two = s;
        std::string expected = "(no error)";
        orient_soup(two);
        try {
            validate_soup(two, "x");
        } catch (const InputError& e) {
            expected = e.what();
        }
        EXPECT_EQ(prepare_error(s, "x", true), expected) << "iteration " << iter;
        if (expected == "(no error)") {
            ++accepted;
            EXPECT_EQ(prepare_soup(s, PrepareOptions{true}, "x").triangles, two.triangles) << "iteration " << iter;
        }
    }
    // The generator must exercise every branch.
    EXPECT_GT(with_duplicates, 300u);
    EXPECT_GT(with_fans, 300u);
    EXPECT_GT(accepted, 100u);
}
