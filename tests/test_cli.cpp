// The command line tool end to end: exit codes, messages, outputs never partial.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "cgal_data.hpp"
#include "fixtures.hpp"
#include "shell.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/io.hpp"

namespace fs = std::filesystem;

using singlestrip::test::test_data;

namespace {

using CliRun = singlestrip::test::ShellRun;  // out: stdout and stderr, merged
using singlestrip::test::shell_quote;

std::string q(const std::string& s) {
    return shell_quote(s);
}

/// Runs the CLI with `args` (already shell-quoted where needed).
CliRun cli(const std::string& args) {
    return singlestrip::test::run_shell(q(SINGLESTRIP_CLI_PATH) + " " + args + " 2>&1");
}

struct Scratch : singlestrip::test::ScratchDir {
    explicit Scratch(const std::string& tag) : ScratchDir("cli-" + tag) {}
    size_t count() const { return static_cast<size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator())); }
};

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace

TEST(Cli, InfoExitCodesAndReport) {
    CliRun ok = cli("info " + q(test_data("pyramid_quad.off")));
    EXPECT_EQ(ok.code, 0) << ok.out;
    EXPECT_NE(ok.out.find("valid for stripping:  yes"), std::string::npos) << ok.out;
    EXPECT_NE(ok.out.find("from 5 polygons"), std::string::npos) << ok.out;

    CliRun bad = cli("info " + q(test_data("tetra_one_flipped.off")));
    EXPECT_EQ(bad.code, 3) << bad.out;
    EXPECT_NE(bad.out.find("[inconsistent_orientation] edge (0, 2)"), std::string::npos) << bad.out;

    CliRun fixed = cli("info --orient " + q(test_data("tetra_one_flipped.off")));
    EXPECT_EQ(fixed.code, 0) << fixed.out;

    CliRun js = cli("info --json " + q(test_data("two_components.off")));
    EXPECT_EQ(js.code, 0) << js.out;  // several components: one strip each
    auto j = nlohmann::json::parse(js.out);
    EXPECT_EQ(j["components"], 3);
    EXPECT_EQ(j["valid"], true);
    EXPECT_TRUE(j["problems"].empty());

    CliRun dup = cli("info --json " + q(test_data("duplicate_face.off")));
    EXPECT_EQ(dup.code, 3) << dup.out;
    CliRun rep = cli("info --json --repair " + q(test_data("duplicate_face.off")));
    EXPECT_EQ(rep.code, 0) << rep.out;
    const auto rj = nlohmann::json::parse(rep.out.substr(rep.out.find('{')));
    EXPECT_EQ(rj["repair"]["duplicate_faces"], 1);

    CliRun moebius = cli("info --orient --json " + q(test_data("moebius.off")));
    EXPECT_EQ(moebius.code, 3);
    EXPECT_EQ(nlohmann::json::parse(moebius.out)["orientable"], false);

    CliRun builtin = cli("info --json builtin:genus2");
    EXPECT_EQ(builtin.code, 0) << builtin.out;
    EXPECT_EQ(nlohmann::json::parse(builtin.out)["genus"], 2);
}

TEST(Cli, ReadErrorsExitThreeWithMessage) {
    for (const char* f : {"empty.off", "nan.off", "index_out_of_range.off", "truncated_binary.stl", "missing.off"}) {
        SCOPED_TRACE(f);
        CliRun r = cli("info " + q(test_data(f)));
        EXPECT_EQ(r.code, 3) << r.out;
        EXPECT_EQ(r.out.rfind("singlestrip: error: " + test_data(f) + ": ", 0), 0u) << r.out;
    }
}

TEST(Cli, UsageErrorsExitTwo) {
    EXPECT_EQ(cli("").code, 2);
    EXPECT_EQ(cli("strip").code, 2);
    EXPECT_EQ(cli("info a.off --no-such-option").code, 2);
    EXPECT_EQ(cli("strip " + q(test_data("tetra.off")) + " -o x.ply --seed-face notanumber").code, 2);
    EXPECT_EQ(cli("--help").code, 0);
}

TEST(Cli, StripWritesConsistentOutputsAndReport) {
    Scratch s("strip");
    CliRun r = cli("strip " + q(test_data("pyramid_slashes.obj")) + " -o " + q(s / "o.ply") + " --indices " + q(s / "i.txt") +
                   " --report " + q(s / "r.json"));
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("6 ->"), std::string::npos) << r.out;  // one-line summary
    auto rep = nlohmann::json::parse(slurp(s / "r.json"));
    for (const char* key : {"input_triangles", "output_triangles", "splits", "swaps", "strip_indices", "genus", "boundary_loops",
                            "fundamental_triangles", "indices_per_triangle", "extra_percent"})
        EXPECT_TRUE(rep.contains(key)) << key;
    for (const char* key : {"read", "build", "strip", "write"}) EXPECT_TRUE(rep["seconds"].contains(key)) << key;
    EXPECT_EQ(rep["input_triangles"], 6);

    // The output keeps the input vertices first, unchanged, and the index file decodes to its faces.
    singlestrip::TriangleSoup in = singlestrip::read_mesh_file(test_data("pyramid_slashes.obj"));
    singlestrip::TriangleSoup out = singlestrip::read_mesh_file(s / "o.ply");
    ASSERT_GE(out.points.size(), in.points.size());
    for (size_t v = 0; v < in.points.size(); ++v) EXPECT_EQ(out.points[v], in.points[v]);
    EXPECT_EQ(out.triangles.size(), rep["output_triangles"].get<size_t>());
    std::vector<uint32_t> idx;
    std::istringstream is(slurp(s / "i.txt"));
    for (uint32_t v; is >> v;) idx.push_back(v);
    EXPECT_EQ(idx.size(), rep["strip_indices"].get<size_t>());
    // Same faces in the same order, each with the same cyclic vertex order (winding).
    auto canonical = [](std::vector<singlestrip::Triangle> ts) {
        for (auto& t : ts) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        return ts;
    };
    EXPECT_EQ(canonical(singlestrip::decode_triangle_strip(idx)), canonical(out.triangles));

    CliRun v = cli("verify " + q(test_data("pyramid_slashes.obj")) + " " + q(s / "o.ply") + " --indices " + q(s / "i.txt"));
    EXPECT_EQ(v.code, 0) << v.out;
}

TEST(Cli, EngineChoiceReachesTheStripAndTheReport) {
    Scratch s("engine");
    const std::string in = test_data("pyramid_slashes.obj");
    for (const char* engine : {"matching", "growth"}) {
        SCOPED_TRACE(engine);
        const std::string out = s / (std::string(engine) + ".ply"), idx = s / (std::string(engine) + ".txt"),
                          rep = s / (std::string(engine) + ".json");
        CliRun r = cli("strip " + q(in) + " -o " + q(out) + " --indices " + q(idx) + " --report " + q(rep) + " --engine " + engine);
        ASSERT_EQ(r.code, 0) << r.out;
        const auto j = nlohmann::json::parse(slurp(rep));
        EXPECT_EQ(j["engine"], engine);
        EXPECT_EQ(j["options"]["engine"], engine);
        CliRun v = cli("verify " + q(in) + " " + q(out) + " --indices " + q(idx));
        EXPECT_EQ(v.code, 0) << v.out;
    }
    // The default is the matching engine.
    ASSERT_EQ(cli("strip " + q(in) + " -o " + q(s / "d.ply") + " --report " + q(s / "d.json")).code, 0);
    EXPECT_EQ(nlohmann::json::parse(slurp(s / "d.json"))["options"]["engine"], "matching");
}

// 600K faces: the mesh's per-half-edge arrays (7 MB each) and most of the engines' are above the
// CLI's 4 MB threshold for huge pages (src/app/big_pages.cpp), so this strip is built in blocks
// from that allocator; both engines, every output verified.
TEST(Cli, LargeMeshStripsThroughTheLargeBlockAllocatorAndVerifies) {
    Scratch s("large");
    const singlestrip::TriangleSoup torus = singlestrip::make_torus(600, 500);
    ASSERT_GE(3 * torus.triangles.size() * sizeof(uint32_t), size_t{4} << 20);
    const std::string in = s / "torus.ply";
    singlestrip::write_strip_mesh(in, torus.points, torus.triangles, std::vector<uint32_t>(torus.triangles.size(), 0));
    for (const char* engine : {"matching", "growth"}) {
        SCOPED_TRACE(engine);
        const std::string out = s / (std::string(engine) + ".ply"), idx = s / (std::string(engine) + ".txt");
        CliRun r = cli("strip " + q(in) + " -o " + q(out) + " --indices " + q(idx) + " --engine " + engine);
        ASSERT_EQ(r.code, 0) << r.out;
        CliRun v = cli("verify " + q(in) + " " + q(out) + " --indices " + q(idx));
        EXPECT_EQ(v.code, 0) << v.out;
    }
}

TEST(Cli, UnknownEngineIsAUsageError) {
    Scratch s("bad-engine");
    CliRun r = cli("strip " + q(test_data("tetra.off")) + " -o " + q(s / "o.ply") + " --engine greedy");
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("unknown engine 'greedy' (choices: matching, growth)"), std::string::npos) << r.out;
    EXPECT_EQ(cli("strip " + q(test_data("tetra.off")) + " -o " + q(s / "o.ply") + " --engine").code, 2);
    EXPECT_EQ(s.count(), 0u);
}

TEST(Cli, RenderStripsAnInputWithTheEngine) {
    // `render --help` exits 0 even without the subcommand (CLI11 prints the main help): look for it.
    if (cli("--help").out.find("render") == std::string::npos) GTEST_SKIP() << "render not built";
    Scratch s("render-engine");
    for (const char* engine : {"matching", "growth"}) {
        SCOPED_TRACE(engine);
        CliRun r = cli("render builtin:genus2 -o " + q(s / (std::string(engine) + ".png")) + " --engine " + engine +
                       " --with-cycles --width 64 --height 48");
        EXPECT_EQ(r.code, 0) << r.out;
        EXPECT_GT(fs::file_size(s / (std::string(engine) + ".png")), 0u);
    }
    EXPECT_EQ(cli("render builtin:genus2 -o " + q(s / "x.png") + " --engine slow").code, 2);
    EXPECT_EQ(cli("render builtin:genus2 -o " + q(s / "x.png") + " --engine growth --cycles c.json").code, 2);
    // Without --engine the input must be a strip result, as before.
    EXPECT_EQ(cli("render " + q(test_data("tetra.off")) + " -o " + q(s / "x.png") + " --with-cycles").code, 2);
    EXPECT_FALSE(fs::exists(s / "x.png"));
}

TEST(Cli, InvalidInputLeavesNoOutput) {
    Scratch s("noout");
    for (const char* f : {"moebius.off", "non_manifold_edge.off", "repeated_vertex.off", "tetra_one_flipped.off"}) {
        SCOPED_TRACE(f);
        CliRun r =
            cli("strip " + q(test_data(f)) + " -o " + q(s / "o.ply") + " --indices " + q(s / "i.txt") + " --report " + q(s / "r.json"));
        EXPECT_EQ(r.code, 3) << r.out;
        EXPECT_EQ(r.out.rfind("singlestrip: error: " + test_data(f) + ": ", 0), 0u) << r.out;
        EXPECT_EQ(s.count(), 0u);
    }
    // --orient repairs the flipped tetrahedron.
    CliRun r = cli("strip --orient " + q(test_data("tetra_one_flipped.off")) + " -o " + q(s / "o.off"));
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(fs::exists(s / "o.off"));
}

TEST(Cli, RequestAndOutputErrors) {
    Scratch s("req");
    CliRun ext = cli("strip " + q(test_data("tetra.off")) + " -o " + q(s / "o.xyz"));
    EXPECT_EQ(ext.code, 4) << ext.out;
    CliRun seed = cli("strip " + q(test_data("tetra.off")) + " -o " + q(s / "o.ply") + " --seed-face 4");
    EXPECT_EQ(seed.code, 4) << seed.out;
    CliRun cons =
        cli("strip " + q(test_data("tetra.off")) + " -o " + q(s / "o.ply") + " --constraints " + q(test_data("constraints_bad_token.txt")));
    EXPECT_EQ(cons.code, 3) << cons.out;
    EXPECT_NE(cons.out.find("line 2"), std::string::npos) << cons.out;
    EXPECT_EQ(s.count(), 0u);
    // The mesh is written but the report cannot be: nothing is left behind.
    CliRun out = cli("strip " + q(test_data("tetra.off")) + " -o " + q(s / "o.ply") + " --report " + q(s / "no_dir/r.json"));
    EXPECT_EQ(out.code, 7) << out.out;
    EXPECT_EQ(s.count(), 0u);
}

TEST(Cli, VerifyCatchesATamperedOutput) {
    Scratch s("verify");
    ASSERT_EQ(cli("strip " + q(test_data("pyramid_quad.off")) + " -o " + q(s / "o.off") + " --indices " + q(s / "i.txt")).code, 0);
    EXPECT_EQ(cli("verify " + q(test_data("pyramid_quad.off")) + " " + q(s / "o.off") + " --indices " + q(s / "i.txt")).code, 0);
    // Drop the last face: the output no longer covers the input.
    singlestrip::TriangleSoup o = singlestrip::read_mesh_file(s / "o.off");
    o.triangles.pop_back();
    singlestrip::write_strip_mesh(s / "bad.off", o.points, o.triangles, std::vector<uint32_t>(o.triangles.size(), 0));
    CliRun v = cli("verify " + q(test_data("pyramid_quad.off")) + " " + q(s / "bad.off"));
    EXPECT_EQ(v.code, 5) << v.out;
}

TEST(CliReal, FandiskStripsAndVerifies) {
    const std::string fandisk = singlestrip::test::cgal_mesh_path("fandisk.off");
    if (fandisk.empty()) GTEST_SKIP() << "libcgal-demo data not available";
    Scratch s("fandisk");
    CliRun r = cli("strip " + q(fandisk) + " -o " + q(s / "f.ply") + " --indices " + q(s / "f.txt") + " --report " + q(s / "f.json"));
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(nlohmann::json::parse(slurp(s / "f.json"))["input_triangles"], 12946);
    CliRun v = cli("verify " + q(fandisk) + " " + q(s / "f.ply") + " --indices " + q(s / "f.txt"));
    EXPECT_EQ(v.code, 0) << v.out;
    // Several components: three strips, verified with the index file.
    const std::string three = singlestrip::test::cgal_mesh_path("blobby_3cc.off");
    CliRun b = cli("strip " + q(three) + " -o " + q(s / "b.ply") + " --indices " + q(s / "b.txt"));
    EXPECT_EQ(b.code, 0) << b.out;
    EXPECT_NE(b.out.find("3 strips"), std::string::npos) << b.out;
    CliRun bv = cli("verify " + q(three) + " " + q(s / "b.ply") + " --indices " + q(s / "b.txt"));
    EXPECT_EQ(bv.code, 0) << bv.out;
}

// --polish: fewer GL indices than the default on fandisk, the report says so, verify accepts it.
TEST(CliReal, PolishGivesFewerIndices) {
    const std::string fandisk = singlestrip::test::cgal_mesh_path("fandisk.off");
    if (fandisk.empty()) GTEST_SKIP() << "libcgal-demo data not available";
    Scratch s("polish");
    ASSERT_EQ(cli("strip " + q(fandisk) + " -o " + q(s / "d.ply") + " --report " + q(s / "d.json")).code, 0);
    CliRun r =
        cli("strip " + q(fandisk) + " --polish -o " + q(s / "p.ply") + " --indices " + q(s / "p.txt") + " --report " + q(s / "p.json"));
    ASSERT_EQ(r.code, 0) << r.out;
    const auto plain = nlohmann::json::parse(slurp(s / "d.json")), polished = nlohmann::json::parse(slurp(s / "p.json"));
    EXPECT_EQ(plain["options"]["polish"], false);
    EXPECT_EQ(polished["options"]["polish"], true);
    EXPECT_GT(polished["polished"].get<int>(), 0);
    EXPECT_FALSE(plain.contains("polished"));
    EXPECT_LT(polished["strip_indices"].get<int>(), plain["strip_indices"].get<int>());
    CliRun v = cli("verify " + q(fandisk) + " " + q(s / "p.ply") + " --indices " + q(s / "p.txt"));
    EXPECT_EQ(v.code, 0) << v.out;
}

TEST(CliReal, RepairStripsARefusedMeshAndVerifyReplaysIt) {
    const std::string pig = singlestrip::test::cgal_mesh_path("pig.stl");
    if (pig.empty()) GTEST_SKIP() << "libcgal-demo data not available";
    Scratch s("repair");
    CliRun refused = cli("strip " + q(pig) + " -o " + q(s / "p.ply"));
    EXPECT_EQ(refused.code, 3) << refused.out;
    EXPECT_NE(refused.out.find("(fix: --repair"), std::string::npos) << refused.out;
    CliRun r = cli("strip " + q(pig) + " --repair -o " + q(s / "p.ply") + " --indices " + q(s / "p.txt") + " --join restart --report " +
                   q(s / "p.json"));
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("repair: "), std::string::npos) << r.out;
    const auto j = nlohmann::json::parse(slurp(s / "p.json"));
    EXPECT_GT(j["repair"]["vertex_copies"].get<int>(), 0);
    EXPECT_EQ(j["repair"]["elements"]["copied_from"].size(), j["repair"]["vertex_copies"].get<size_t>());
    EXPECT_EQ(j["strips"].get<size_t>(), j["components"].size());
    EXPECT_EQ(j["options"]["join"], "restart");
    CliRun v = cli("verify " + q(pig) + " " + q(s / "p.ply") + " --indices " + q(s / "p.txt") + " --repair");
    EXPECT_EQ(v.code, 0) << v.out;
    EXPECT_NE(v.out.find("depends on the library"), std::string::npos) << v.out;
    CliRun plain = cli("verify " + q(pig) + " " + q(s / "p.ply"));
    EXPECT_EQ(plain.code, 5) << plain.out;  // against the unrepaired input the check cannot pass
}

TEST(Cli, UnweldedSoupHintsWeldAndOrientFollowsTheMajority) {
    Scratch s("weld");
    // A tetrahedron written as a soup: every face with its own three vertices.
    std::string off = "OFF\n12 4 0\n";
    const double P[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const int F[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    for (const auto& f : F)
        for (int v : f) off += std::to_string(P[v][0]) + " " + std::to_string(P[v][1]) + " " + std::to_string(P[v][2]) + "\n";
    for (int f = 0; f < 4; ++f)
        off += "3 " + std::to_string(3 * f) + " " + std::to_string(3 * f + 1) + " " + std::to_string(3 * f + 2) + "\n";
    { std::ofstream(s / "soup.off") << off; }
    CliRun r = cli("strip " + q(s / "soup.off") + " -o " + q(s / "o.ply"));
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("4 strips"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("--weld"), std::string::npos) << r.out;
    CliRun w = cli("strip " + q(s / "soup.off") + " --weld -o " + q(s / "o.ply"));
    EXPECT_EQ(w.code, 0) << w.out;
    EXPECT_NE(w.out.find("1 strip of"), std::string::npos) << w.out;
    EXPECT_EQ(cli("verify " + q(s / "soup.off") + " " + q(s / "o.ply") + " --weld").code, 0);
}

TEST(Cli, GltfSceneInAndOut) {
    Scratch s("gltfin");
    const std::string scene = test_data("scene.gltf");
    CliRun r = cli("strip " + q(scene) + " -o " + q(s / "o.glb") + " --report " + q(s / "r.json"));
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("mesh 2 primitive 0: kept as it was"), std::string::npos) << r.out;
    const auto j = nlohmann::json::parse(slurp(s / "r.json"));
    ASSERT_EQ(j["primitives"].size(), 4u);
    EXPECT_EQ(j["primitives"][0]["stripped"], true);
    EXPECT_EQ(cli("strip " + q(scene) + " -o " + q(s / "o2.glb") + " --indices " + q(s / "i.txt")).code, 4);
    CliRun sv = cli("verify " + q(scene) + " " + q(s / "o.glb"));
    EXPECT_EQ(sv.code, 0) << sv.out;
    EXPECT_NE(sv.out.find("8 strips"), std::string::npos) << sv.out;
    // Any other output: all triangle primitives as one mesh, verified like any input.
    EXPECT_EQ(cli("info " + q(test_data("scene.glb"))).code, 0);
    CliRun p = cli("strip " + q(test_data("scene.glb")) + " -o " + q(s / "o.ply") + " --indices " + q(s / "o.txt"));
    ASSERT_EQ(p.code, 0) << p.out;
    CliRun v = cli("verify " + q(test_data("scene.glb")) + " " + q(s / "o.ply") + " --indices " + q(s / "o.txt"));
    EXPECT_EQ(v.code, 0) << v.out;
}
