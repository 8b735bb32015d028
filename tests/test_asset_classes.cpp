// Issue 18, "Done when": every class of real-asset problem strips with `--repair` through the
// command line and `verify --repair` accepts the result. One case per class: non-manifold edges
// and vertices, duplicate and degenerate faces, several components, an unwelded soup, most faces
// flipped (the result must face outward), PLY tristrips, OBJ with vt/vn seams, a glTF scene with
// several textured primitives (glTF out, and one mesh out).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fixtures.hpp"
#include "shell.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/repair.hpp"

using namespace singlestrip;
namespace fs = std::filesystem;

using singlestrip::test::test_data;

namespace {

struct Scratch : singlestrip::test::ScratchDir {
    Scratch() : ScratchDir("classes") {}
};

singlestrip::test::ShellRun cli(const std::string& args) {
    return singlestrip::test::run_program(SINGLESTRIP_CLI_PATH, args);
}

/// `strip IN --repair -o OUT` then `verify IN OUT --repair`: both must succeed.
void strips_and_verifies(const std::string& in, const std::string& out) {
    SCOPED_TRACE(in + " -> " + out);
    const auto [code, text] = cli("strip '" + in + "' --repair -o '" + out + "'");
    ASSERT_EQ(code, 0) << text;
    const auto [vcode, vtext] = cli("verify '" + in + "' '" + out + "' --repair");
    EXPECT_EQ(vcode, 0) << vtext;
}

void write_soup_obj(const std::string& path, const TriangleSoup& s) {
    write_strip_mesh(path, s.points, s.triangles, std::vector<uint32_t>(s.triangles.size(), 0));
}

}  // namespace

TEST(AssetClasses, BrokenConnectivityStripsWithRepairAndVerifies) {
    Scratch dir;
    for (const char* f : {"non_manifold_edge.off", "non_manifold_vertex.off", "duplicate_face.off", "repeated_vertex.off",
                          "two_components.off", "moebius.off"})
        strips_and_verifies(test_data(f), dir / (std::string(f) + ".ply"));
}

TEST(AssetClasses, UnweldedSoupBecomesOneStrip) {
    Scratch dir;
    const TriangleSoup sphere = make_icosphere(2);
    TriangleSoup u;
    for (const Triangle& t : sphere.triangles) {
        const auto base = static_cast<uint32_t>(u.points.size());
        for (uint32_t v : t) u.points.push_back(sphere.points[v]);
        u.triangles.push_back({base, base + 1, base + 2});
    }
    write_soup_obj(dir / "soup.obj", u);
    strips_and_verifies(dir / "soup.obj", dir / "soup.ply");
    const auto [code, text] = cli("strip '" + dir / "soup.obj" + "' -o '" + dir / "plain.ply" + "'");
    EXPECT_EQ(code, 0) << text;  // without --repair: one strip per triangle, and a warning naming --weld
    EXPECT_NE(text.find("--weld"), std::string::npos) << text;
}

TEST(AssetClasses, MostFacesFlippedEndsOutward) {
    Scratch dir;
    TriangleSoup s = make_icosphere(2);
    for (size_t f = 0; f < s.triangles.size(); ++f)
        if (f % 7 != 0) std::swap(s.triangles[f][1], s.triangles[f][2]);
    write_soup_obj(dir / "flipped.obj", s);
    strips_and_verifies(dir / "flipped.obj", dir / "out.ply");
    const TriangleSoup out = read_mesh_file(dir / "out.ply");
    EXPECT_GT(signed_volume(out.points, out.triangles), 0.0);
}

TEST(AssetClasses, PlyTristripsStripAndVerify) {
    Scratch dir;
    const TriangleSoup s = make_icosphere(1);
    std::ofstream ply(dir / "strips.ply");
    ply << "ply\nformat ascii 1.0\nelement vertex " << s.points.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
        << "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
    for (const Point3& p : s.points) ply << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    ply << 4 * s.triangles.size();
    for (const Triangle& t : s.triangles) ply << ' ' << t[0] << ' ' << t[1] << ' ' << t[2] << " -1";
    ply << '\n';
    ply.close();
    strips_and_verifies(dir / "strips.ply", dir / "out.ply");
    EXPECT_EQ(read_mesh_file(dir / "strips.ply").triangles.size(), s.triangles.size());
}

TEST(AssetClasses, ObjWithTextureAndNormalSeams) {
    Scratch dir;
    for (const char* ext : {".obj", ".ply", ".glb"}) strips_and_verifies(test_data("sphere_uv.obj"), dir / (std::string("out") + ext));
}

TEST(AssetClasses, GltfSceneWithSeveralTexturedPrimitives) {
    Scratch dir;
    for (const char* out : {"out.glb", "out.gltf", "out.ply", "out.obj"}) strips_and_verifies(test_data("scene.glb"), dir / out);
}
