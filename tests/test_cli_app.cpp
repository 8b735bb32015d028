// The command line tool as a new user meets it (issue 19): messages, refused overwrites, "-" for
// standard input and output, --index-base, --path, batch notes, STL, `render` in its own program.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "shell.hpp"

namespace fs = std::filesystem;
using json = nlohmann::json;

using singlestrip::test::test_data;

namespace {

const std::string kSource = SINGLESTRIP_SOURCE_DIR;
const std::string kRoom = kSource + "/examples/room/room.off";
const std::string kWalls = kSource + "/examples/room/walls.txt";

std::string q(const std::string& s) {
    return singlestrip::test::shell_quote(s);
}

using Exec = singlestrip::test::ShellRun;  // out: stdout only, or stdout and stderr merged

Exec shell(const std::string& cmd) {
    return singlestrip::test::run_shell(cmd);
}

/// The CLI with `args`; stderr merged into the output unless `stdout_only`.
Exec cli(const std::string& args, bool stdout_only = false) {
    return shell(q(SINGLESTRIP_CLI_PATH) + " " + args + (stdout_only ? " 2>/dev/null" : " 2>&1"));
}

bool has(const Exec& r, const std::string& text) {
    return r.out.find(text) != std::string::npos;
}

struct Scratch : singlestrip::test::ScratchDir {
    explicit Scratch(const std::string& tag) : ScratchDir("app-" + tag) {}
};

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void spit(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

bool render_built() {
    return fs::exists(fs::path(SINGLESTRIP_CLI_PATH).parent_path() / "singlestrip-render");
}

}  // namespace

TEST(CliApp, VersionDoesNotLoadTheRenderer) {
    const Exec ldd = shell("ldd " + q(SINGLESTRIP_CLI_PATH));
    ASSERT_EQ(ldd.code, 0) << ldd.out;
    EXPECT_FALSE(has(ldd, "OSMesa")) << ldd.out;
    EXPECT_FALSE(has(ldd, "LLVM")) << ldd.out;
    const Exec v = cli("--version");
    EXPECT_EQ(v.code, 0);
    EXPECT_TRUE(has(v, "singlestrip 0.1.0")) << v.out;
}

TEST(CliApp, CommandMessages) {
    const Exec none = cli("");
    EXPECT_EQ(none.code, 2);
    EXPECT_TRUE(has(none, "a command is required: info, strip, verify or render")) << none.out;
    const Exec foo = cli("foo");
    EXPECT_EQ(foo.code, 2);
    EXPECT_TRUE(has(foo, "unknown command 'foo'")) << foo.out;
    const Exec ext = cli("strip builtin:genus2 -o x.xyz");
    EXPECT_EQ(ext.code, 4);
    EXPECT_TRUE(has(ext, ".glb or .gltf")) << ext.out;
}

TEST(CliApp, OutputsThatOverwriteAreRefused) {
    Scratch s("overwrite");
    const Exec same = cli("strip builtin:genus2 -o " + q(s / "w.ply") + " --report " + q(s / "w.ply"));
    EXPECT_EQ(same.code, 4) << same.out;
    EXPECT_TRUE(has(same, "are the same file")) << same.out;
    EXPECT_FALSE(fs::exists(s / "w.ply"));
    EXPECT_EQ(cli("strip builtin:genus2 -o " + q(s / "w.ply") + " --indices " + q(s / "./w.ply")).code, 4);

    fs::copy_file(test_data("tetra.off"), s / "tetra.off");
    const std::string before = slurp(s / "tetra.off");
    const Exec input = cli("strip " + q(s / "tetra.off") + " -o " + q(s / "tetra.off"));
    EXPECT_EQ(input.code, 4) << input.out;
    EXPECT_TRUE(has(input, "would overwrite the input")) << input.out;
    EXPECT_EQ(slurp(s / "tetra.off"), before);
    fs::copy_file(test_data("constraints_ok.txt"), s / "c.txt");
    EXPECT_EQ(cli("strip " + q(test_data("tetra.off")) + " -o " + q(s / "o.ply") + " --constraints " + q(s / "c.txt") + " --path " +
                  q(s / "c.txt"))
                  .code,
              4);
    // Batch: --out-dir next to the inputs with their own format would overwrite them.
    const Exec batch = cli("strip " + q(s / "tetra.off") + " --out-dir " + q(s.dir.string()) + " --format off");
    EXPECT_EQ(batch.code, 4) << batch.out;
    EXPECT_EQ(slurp(s / "tetra.off"), before);
}

TEST(CliApp, DashIsStandardInputAndOutput) {
    const Exec obj = cli("strip - --input-format off -o - --format obj < " + q(test_data("tetra.off")), true);
    EXPECT_EQ(obj.code, 0);
    EXPECT_EQ(obj.out.rfind("# singlestrip", 0), 0u) << obj.out;
    EXPECT_TRUE(has(obj, "\nf ")) << obj.out;
    const Exec need = cli("strip - -o x.ply < " + q(test_data("tetra.off")));
    EXPECT_EQ(need.code, 4);
    EXPECT_TRUE(has(need, "needs --input-format")) << need.out;
    const Exec info = cli("info - --input-format off < " + q(test_data("tetra.off")), true);
    EXPECT_EQ(info.code, 0);
    EXPECT_TRUE(has(info, "valid for stripping:  yes")) << info.out;
    Scratch s("dash");
    const Exec idx = cli("strip " + q(test_data("tetra.off")) + " -o " + q(s / "t.ply") + " --indices -", true);
    EXPECT_EQ(idx.code, 0);
    EXPECT_FALSE(idx.out.empty());
    EXPECT_EQ(cli("strip " + q(test_data("tetra.off")) + " -o - --indices -").code, 4);  // both to stdout
}

TEST(CliApp, IndexBaseOne) {
    Scratch s("base");
    // The room's walls, renumbered from 1.
    std::ifstream in(kWalls);
    std::ostringstream one;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ws(line);
        for (long v; ws >> v;) one << v + 1 << ' ';
        one << '\n';
    }
    spit(s / "walls1.txt", one.str());
    ASSERT_EQ(cli("strip " + q(kRoom) + " -o " + q(s / "zero.ply") + " --constraints " + q(kWalls) + " --source 0 --target 650").code, 0);
    const Exec r = cli("strip " + q(kRoom) + " -o " + q(s / "one.ply") + " --constraints " + q(s / "walls1.txt") +
                       " --source 1 --target 651 --index-base 1");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(slurp(s / "zero.ply"), slurp(s / "one.ply"));
    const Exec v = cli("verify " + q(kRoom) + " " + q(s / "one.ply") + " --constraints " + q(s / "walls1.txt") +
                       " --source 1 --target 651 --index-base 1");
    EXPECT_EQ(v.code, 0) << v.out;
    const Exec zero = cli("strip " + q(kRoom) + " -o " + q(s / "x.ply") + " --source 0 --index-base 1");
    EXPECT_EQ(zero.code, 4);
    EXPECT_TRUE(has(zero, "numbering starts at 1")) << zero.out;
    spit(s / "bad1.txt", "0 1\n");
    const Exec bad = cli("strip " + q(kRoom) + " -o " + q(s / "x.ply") + " --constraints " + q(s / "bad1.txt") + " --index-base 1");
    EXPECT_EQ(bad.code, 3);
    EXPECT_TRUE(has(bad, "line 1: vertex 0 does not exist")) << bad.out;
    EXPECT_EQ(cli("strip " + q(kRoom) + " -o " + q(s / "x.ply") + " --index-base 2").code, 2);
    spit(s / "notedge1.txt", "1 651\n");
    const Exec edge = cli("strip " + q(kRoom) + " -o " + q(s / "x.ply") + " --constraints " + q(s / "notedge1.txt") + " --index-base 1");
    EXPECT_EQ(edge.code, 4);
    EXPECT_TRUE(has(edge, "counted from 0 here")) << edge.out;
}

// Coordinates near the top of double's range (+-1.7e308): a midpoint summed first would be
// infinite (an output with a non-finite vertex, exit 0, before the fix); float32 formats cannot
// hold them at all and are refused before anything is written; a route longer than double's
// range has a null length in JSON.
std::string grid_off(double cell, double offset) {
    std::ostringstream off;
    off.precision(17);
    const int n = 20;
    off << "OFF\n" << (n + 1) * (n + 1) << ' ' << 2 * n * n << " 0\n";
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) off << offset + cell * (x - n / 2) << ' ' << offset + cell * (y - n / 2) << " 0\n";
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const int a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
            off << "3 " << a << ' ' << b << ' ' << d << "\n3 " << a << ' ' << d << ' ' << c << '\n';
        }
    return off.str();
}

TEST(CliApp, CoordinatesNearTheTopOfDoublesRange) {
    Scratch s("huge");
    spit(s / "huge.off", grid_off(1.7e307, 0));
    for (const char* engine : {"matching", "growth"}) {
        const Exec r =
            cli("strip " + q(s / "huge.off") + " -o " + q(s / "huge.ply") + " --engine " + engine + " --path " + q(s / "r.json"));
        ASSERT_EQ(r.code, 0) << r.out;
        const Exec v = cli("verify " + q(s / "huge.off") + " " + q(s / "huge.ply"));
        EXPECT_EQ(v.code, 0) << engine << ": " << v.out;
        const json j = json::parse(slurp(s / "r.json"));
        EXPECT_TRUE(j["length"].is_null());
        for (const json& p : j["points"]) EXPECT_TRUE(std::isfinite(p["x"].get<double>()));
    }
    for (const char* ext : {"glb", "stl"}) {
        const fs::path out = s / (std::string("huge.") + ext);
        const Exec r = cli("strip " + q(s / "huge.off") + " -o " + q(out) + " --indices " + q(s / "huge.idx"));
        EXPECT_EQ(r.code, 4) << r.out;
        EXPECT_TRUE(has(r, "beyond float32's range")) << r.out;
        EXPECT_FALSE(fs::exists(out));
        EXPECT_FALSE(fs::exists(s / "huge.idx"));
    }
    // A mesh inside float32's subnormals (largest coordinate 1e-40): glTF would keep a step of
    // 1.4e-45, 1e-5 of the mesh; double formats keep it whole.
    spit(s / "tiny.off", grid_off(1e-41, 0));
    const Exec tiny = cli("strip " + q(s / "tiny.off") + " -o " + q(s / "tiny.glb"));
    EXPECT_EQ(tiny.code, 4) << tiny.out;
    EXPECT_TRUE(has(tiny, "below float32's normal range")) << tiny.out;
    EXPECT_FALSE(fs::exists(s / "tiny.glb"));
    ASSERT_EQ(cli("strip " + q(s / "tiny.off") + " -o " + q(s / "tiny.ply")).code, 0);
    EXPECT_EQ(cli("verify " + q(s / "tiny.off") + " " + q(s / "tiny.ply")).code, 0);
}

TEST(CliApp, PathFiles) {
    Scratch s("path");
    const std::string base = "strip " + q(kRoom) + " -o " + q(s / "room.ply") + " --constraints " + q(kWalls) + " --source 0 --target 650";
    for (const char* ext : {"csv", "json", "obj", "geojson"}) {
        const Exec r = cli(base + " --path " + q(s / (std::string("route.") + ext)));
        ASSERT_EQ(r.code, 0) << ext << ": " << r.out;
    }
    const std::string csv = slurp(s / "route.csv");
    EXPECT_EQ(csv.rfind("x,y,z,face,parent,kind,distance\n", 0), 0u);
    const json j = json::parse(slurp(s / "route.json"));
    const size_t n = j["points"].size();
    EXPECT_EQ(n % 2, 1u);
    EXPECT_EQ(j["points"][0]["kind"], "centroid");
    EXPECT_EQ(j["points"][1]["kind"], "edge");
    EXPECT_EQ(j["points"][n - 1]["face"], (n - 1) / 2);
    EXPECT_DOUBLE_EQ(j["points"][n - 1]["distance"].get<double>(), j["length"].get<double>());
    EXPECT_TRUE(j["planar_z"].get<bool>());
    const json g = json::parse(slurp(s / "route.geojson"));
    EXPECT_EQ(g["features"][0]["geometry"]["type"], "LineString");
    EXPECT_EQ(g["features"][0]["geometry"]["coordinates"].size(), n);
    EXPECT_TRUE(has(Exec{0, slurp(s / "route.obj")}, "\nl 1 2 3"));

    const Exec curved = cli("strip builtin:genus2 -o " + q(s / "g.ply") + " --path " + q(s / "g.geojson"));
    EXPECT_EQ(curved.code, 4);
    EXPECT_TRUE(has(curved, "planar in z")) << curved.out;
    EXPECT_FALSE(fs::exists(s / "g.ply"));
    const Exec ext = cli("strip builtin:genus2 -o " + q(s / "g.ply") + " --path " + q(s / "g.txt"));
    EXPECT_EQ(ext.code, 4);
    EXPECT_TRUE(has(ext, ".csv, .json, .obj or .geojson")) << ext.out;
    const Exec out = cli("strip builtin:genus2 -o " + q(s / "g.ply") + " --path - --path-format json", true);
    EXPECT_EQ(out.code, 0);
    EXPECT_GT(json::parse(out.out)["length"].get<double>(), 0.0);
}

TEST(CliApp, BatchNamesAndFormats) {
    Scratch s("batch");
    fs::create_directories(s / "b");
    fs::copy_file(test_data("tetra.off"), s / "b/tetra.off");
    const Exec r = cli("strip " + q(test_data("tetra.obj")) + " " + q(s / "b/tetra.off") + " " + q(test_data("moebius.off")) +
                       " --out-dir " + q(s / "out") + " --format stl --with-path");
    EXPECT_EQ(r.code, 3) << r.out;  // moebius fails
    EXPECT_TRUE(has(r, "has the same name as " + test_data("tetra.obj"))) << r.out;
    EXPECT_TRUE(has(r, (s / "out/tetra-2.stl"))) << r.out;
    const auto stl = slurp(s / "out/tetra.stl");
    ASSERT_GE(stl.size(), 84u);
    EXPECT_EQ(stl.size(), 84u + 50u * 4u);  // 4 triangles, nothing split
    EXPECT_TRUE(fs::exists(s / "out/tetra.route.csv"));
    const json failed = json::parse(slurp(s / "out/moebius.report.json"));
    EXPECT_FALSE(failed["ok"].get<bool>());
    EXPECT_FALSE(failed.contains("output")) << failed.dump();
    EXPECT_FALSE(fs::exists(s / "out/moebius.stl"));
}

TEST(CliApp, VerifyRefusesInexactResults) {
    Scratch s("verify");
    ASSERT_EQ(cli("strip " + q(test_data("tetra.off")) + " -o " + q(s / "t.stl")).code, 0);
    const Exec v = cli("verify " + q(test_data("tetra.off")) + " " + q(s / "t.stl"));
    EXPECT_EQ(v.code, 4);
    EXPECT_TRUE(has(v, "float32")) << v.out;
}

TEST(CliApp, RenderIsItsOwnProgram) {
    if (!render_built()) GTEST_SKIP() << "render not built (needs libosmesa6-dev and libpng-dev)";
    const Exec help = cli("render --help");
    EXPECT_EQ(help.code, 0);
    EXPECT_TRUE(has(help, "RESULT")) << help.out;
    EXPECT_FALSE(has(help, "INPUT is")) << help.out;
    EXPECT_TRUE(has(help, "--route")) << help.out;
    Scratch s("render");
    const Exec glb = cli("render " + q(s / "spot.glb") + " -o " + q(s / "x.png"));
    EXPECT_EQ(glb.code, 3);
    EXPECT_TRUE(has(glb, "cannot read a glTF result")) << glb.out;
    ASSERT_EQ(cli("strip " + q(kRoom) + " -o " + q(s / "room.ply")).code, 0);
    const Exec pic = cli("render " + q(s / "room.ply") + " -o " + q(s / "room.png") + " --route --bands 3");
    EXPECT_EQ(pic.code, 0) << pic.out;
    EXPECT_GT(fs::file_size(s / "room.png"), 1000u);
}

TEST(CliApp, MessagesNameTheFilePolygon) {
    Scratch s("polygon");
    // Polygon 1 is a triangle with a repeated vertex; it is triangle 2 after fan triangulation.
    spit(s / "quads.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n3 0 0 1\n");
    const Exec r = cli("info " + q(s / "quads.off"));
    EXPECT_EQ(r.code, 3);
    EXPECT_TRUE(has(r, "face 2 (polygon 1 of the file)")) << r.out;
}
