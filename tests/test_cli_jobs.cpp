// The command line for the controllable and batch jobs: constraint files, endpoints, cycles,
// glTF and batch mode, end to end through the real binary, each result checked by `verify`.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "shell.hpp"

namespace fs = std::filesystem;

namespace {

using CliResult = singlestrip::test::ShellRun;

CliResult cli(const std::string& args) {
    return singlestrip::test::run_shell(singlestrip::test::shell_quote(SINGLESTRIP_CLI_PATH) + " " + args + " 2>&1");
}

std::string src(const std::string& rel) {
    return std::string(SINGLESTRIP_SOURCE_DIR) + "/" + rel;
}

fs::path fresh_dir(const std::string& name) {
    const fs::path d = fs::temp_directory_path() / ("singlestrip-cli-jobs-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

}  // namespace

TEST(CliJobs, RoomExampleFromTheReadme) {
    const fs::path d = fresh_dir("room");
    const std::string room = src("examples/room/room.off"), walls = src("examples/room/walls.txt");
    const std::string out = (d / "room.ply").string(), idx = (d / "room.txt").string();
    const CliResult s =
        cli("strip '" + room + "' -o '" + out + "' --constraints '" + walls + "' --source 0 --target 650 --indices '" + idx + "'");
    ASSERT_EQ(s.code, 0) << s.out;
    EXPECT_NE(s.out.find("1078 ->"), std::string::npos) << s.out;
    const CliResult v =
        cli("verify '" + room + "' '" + out + "' --constraints '" + walls + "' --source 0 --target 650 --indices '" + idx + "'");
    EXPECT_EQ(v.code, 0) << v.out;
    EXPECT_NE(v.out.find("OK"), std::string::npos) << v.out;
    // The same output checked against a different target must fail (exit 5).
    const CliResult bad = cli("verify '" + room + "' '" + out + "' --target 30");
    EXPECT_EQ(bad.code, 5) << bad.out;
    fs::remove_all(d);
}

TEST(CliJobs, ConstraintPairThatIsNotAnEdgeNamesTheLine) {
    const fs::path d = fresh_dir("badedge");
    const std::string walls = (d / "walls.txt").string();
    std::ofstream(walls) << "# first line is fine\n0 1 2\n\n0 650\n";
    const std::string out = (d / "x.ply").string();
    const CliResult r = cli("strip '" + src("examples/room/room.off") + "' -o '" + out + "' --constraints '" + walls + "'");
    EXPECT_EQ(r.code, 4) << r.out;
    EXPECT_NE(r.out.find("line 4: (0, 650) is not an edge of the mesh"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(out));
    fs::remove_all(d);
}

TEST(CliJobs, SeparatingConstraintsGiveThePieces) {
    const fs::path d = fresh_dir("cut");
    const std::string walls = (d / "walls.txt").string();
    // A wall across the whole room at x = 14 (vertex j*31 + 14 for j = 0..20) cuts it in two.
    std::ofstream w(walls);
    for (int j = 0; j <= 20; ++j) w << j * 31 + 14 << (j < 20 ? " " : "\n");
    w.close();
    const CliResult r =
        cli("strip '" + src("examples/room/room.off") + "' -o '" + (d / "x.ply").string() + "' --constraints '" + walls + "'");
    EXPECT_EQ(r.code, 4) << r.out;
    EXPECT_NE(r.out.find("2 pieces"), std::string::npos) << r.out;
    fs::remove_all(d);
}

TEST(CliJobs, CyclesJsonAndObjForTheBuiltinModel) {
    const fs::path d = fresh_dir("cycles");
    const std::string out = (d / "g2.ply").string(), cj = (d / "c.json").string(), co = (d / "c.obj").string();
    const CliResult s = cli("strip builtin:genus2 -o '" + out + "' --cycles '" + cj + "' --cycles-obj '" + co + "' --report '" +
                            (d / "r.json").string() + "'");
    ASSERT_EQ(s.code, 0) << s.out;
    const CliResult v = cli("verify builtin:genus2 '" + out + "' --cycles '" + cj + "'");
    EXPECT_EQ(v.code, 0) << v.out;
    EXPECT_NE(v.out.find("4 independent cycles"), std::string::npos) << v.out;
    std::ifstream obj(co);
    std::string line;
    int polylines = 0;
    while (std::getline(obj, line)) polylines += line.rfind("l ", 0) == 0;
    EXPECT_EQ(polylines, 4);
    fs::remove_all(d);
}

TEST(CliJobs, BatchReportsBadFilesAndKeepsGoing) {
    const fs::path d = fresh_dir("batch");
    const std::string good1 = src("tests/data/tetra.off"), good2 = src("examples/room/room.off");
    const std::string bad = src("tests/data/non_manifold_edge.off"), missing = (d / "missing.off").string();
    const CliResult r = cli("strip '" + good1 + "' '" + bad + "' '" + good2 + "' '" + missing + "' --out-dir '" + (d / "out").string() +
                            "' --with-indices");
    EXPECT_NE(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("4 file(s): 2 ok, 2 failed"), std::string::npos) << r.out;
    for (const char* stem : {"tetra", "room"}) {
        const fs::path result = d / "out" / (std::string(stem) + ".ply");
        ASSERT_TRUE(fs::exists(result)) << result;
        EXPECT_TRUE(fs::exists(d / "out" / (std::string(stem) + ".report.json")));
        const std::string in = std::string(stem) == "tetra" ? good1 : good2;
        const CliResult v = cli("verify '" + in + "' '" + result.string() + "' --indices '" +
                                (d / "out" / (std::string(stem) + ".indices.txt")).string() + "'");
        EXPECT_EQ(v.code, 0) << v.out;
    }
    EXPECT_FALSE(fs::exists(d / "out" / "non_manifold_edge.ply"));
    // Batch options that are per file are a usage error.
    EXPECT_EQ(cli("strip '" + good1 + "' '" + good2 + "' --out-dir '" + (d / "o2").string() + "' --source 0").code, 2);
    fs::remove_all(d);
}

TEST(CliJobs, BatchTakesTheEngine) {
    const fs::path d = fresh_dir("batch-engine");
    const std::string in1 = src("tests/data/tetra.off"), in2 = src("examples/room/room.off");
    const CliResult r = cli("strip '" + in1 + "' '" + in2 + "' --out-dir '" + (d / "out").string() + "' --engine growth --with-indices");
    ASSERT_EQ(r.code, 0) << r.out;
    for (const char* stem : {"tetra", "room"}) {
        std::ifstream rep(d / "out" / (std::string(stem) + ".report.json"));
        const std::string text((std::istreambuf_iterator<char>(rep)), std::istreambuf_iterator<char>());
        EXPECT_NE(text.find("\"engine\": \"growth\""), std::string::npos) << text;
        const std::string in = std::string(stem) == "tetra" ? in1 : in2;
        const CliResult v = cli("verify '" + in + "' '" + (d / "out" / (std::string(stem) + ".ply")).string() + "' --indices '" +
                                (d / "out" / (std::string(stem) + ".indices.txt")).string() + "'");
        EXPECT_EQ(v.code, 0) << v.out;
    }
    const CliResult bad = cli("strip '" + in1 + "' --out-dir '" + (d / "o2").string() + "' --engine none");
    EXPECT_EQ(bad.code, 2) << bad.out;
    EXPECT_NE(bad.out.find("choices: matching, growth"), std::string::npos) << bad.out;
    EXPECT_FALSE(fs::exists(d / "o2"));
    fs::remove_all(d);
}

TEST(CliJobs, GlbOutputDecodesToTheSameStripAsPly) {
    const fs::path d = fresh_dir("glb");
    const std::string in = src("tests/data/tetra.off");
    EXPECT_EQ(cli("strip '" + in + "' -o '" + (d / "t.glb").string() + "'").code, 0);
    EXPECT_GT(fs::file_size(d / "t.glb"), 100u);
    // verify checks a glTF result with float32 tolerances, and says so.
    const CliResult v = cli("verify '" + in + "' '" + (d / "t.glb").string() + "'");
    EXPECT_EQ(v.code, 0) << v.out;
    EXPECT_NE(v.out.find("float32"), std::string::npos) << v.out;
    // ... and still catches a wrong one: the strip of another mesh.
    EXPECT_EQ(cli("strip '" + src("tests/data/pyramid_quad.off") + "' -o '" + (d / "p.glb").string() + "'").code, 0);
    const CliResult w = cli("verify '" + in + "' '" + (d / "p.glb").string() + "'");
    EXPECT_EQ(w.code, 5) << w.out;
    fs::remove_all(d);
}
