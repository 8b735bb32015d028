// glTF export: every file is checked by the Khronos glTF-Validator (npm `gltf-validator`, run
// with node) — zero errors required — and read back (tinygltf) and decoded with our own strip
// decoder: the decoded triangles must be exactly the output faces, in order, with their winding.
//
// The validator is looked up in $SINGLESTRIP_GLTF_VALIDATOR_DIR (a directory with
// node_modules/gltf-validator), else in ~/.cache/singlestrip/gltf-validator, where
// scripts/install-deps installs it (npm), else "gltf-validator/" next to this test executable.
// The tests never download it: without node or the package the validator checks SKIP with the
// reason; the decode tests always run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "fixtures.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/gltf.hpp"
#include "singlestrip/gltf_scene.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/validate.hpp"
#include "singlestrip/verify.hpp"
#include "tinygltf_read.hpp"

using namespace singlestrip;
namespace fs = std::filesystem;

namespace {

fs::path exe_dir() {
    std::error_code ec;
    const fs::path p = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::current_path() : p.parent_path();
}

fs::path scratch_dir() {
    const fs::path d = exe_dir() / "gltf-test-out";
    fs::create_directories(d);
    return d;
}

StripArrays strip_of(const TriangleSoup& soup) {
    const TriangleSoup s = prepare_soup(soup, {}, "test");
    return strip_arrays(build_strip(Mesh::from_soup(s)));
}

std::string run_capture(const std::string& cmd, int& status) {
    std::string out;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) {
        status = -1;
        return out;
    }
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
    status = pclose(p);
    return out;
}

/// Where scripts/install-deps puts the validator (or $SINGLESTRIP_GLTF_VALIDATOR_DIR).
std::vector<fs::path> validator_candidates() {
    if (const char* d = std::getenv("SINGLESTRIP_GLTF_VALIDATOR_DIR")) return {d};
    std::vector<fs::path> c;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) c.push_back(fs::path(x) / "singlestrip" / "gltf-validator");
    if (const char* h = std::getenv("HOME"); h && *h) c.push_back(fs::path(h) / ".cache" / "singlestrip" / "gltf-validator");
    c.push_back(exe_dir() / "gltf-validator");  // where earlier versions of this test installed it
    return c;
}

/// Directory holding node_modules/gltf-validator, or "" and the reason. The test never
/// downloads it (an offline run must not hang or fail): scripts/install-deps installs it.
std::string validator_dir(std::string& why) {
    static std::string dir, reason;
    static bool tried = false;
    if (tried) {
        why = reason;
        return dir;
    }
    tried = true;
    int st = 0;
    run_capture("node --version 2>&1", st);
    if (st != 0) {
        reason = "node is not installed";
        why = reason;
        return {};
    }
    for (const fs::path& d : validator_candidates())
        if (fs::exists(d / "node_modules" / "gltf-validator" / "package.json")) return dir = d.string();
    reason = "the npm package gltf-validator is not installed in " + validator_candidates().front().string() +
             " (scripts/install-deps installs it; set SINGLESTRIP_GLTF_VALIDATOR_DIR for another place)";
    why = reason;
    return {};
}

/// Runs the Khronos validator on `file`; returns its JSON report.
nlohmann::json validate_gltf(const std::string& dir, const std::string& file) {
    // One script per process: ctest runs the validator tests in parallel, and a script rewritten
    // while another node reads it fails at random.
    const fs::path script = fs::path(dir) / ("validate-" + std::to_string(::getpid()) + ".js");
    {
        std::ofstream js(script);
        js << "const v = require('gltf-validator');\n"
              "const fs = require('fs');\n"
              "const path = process.argv[2];\n"
              "v.validateBytes(new Uint8Array(fs.readFileSync(path)), {uri: path, maxIssues: 0})\n"
              "  .then(r => { process.stdout.write(JSON.stringify(r)); })\n"
              "  .catch(e => { process.stdout.write(JSON.stringify({exception: String(e)})); process.exit(1); });\n";
    }
    int st = 0;
    const std::string out = run_capture("cd '" + dir + "' && node '" + script.filename().string() + "' '" + file + "' 2>&1", st);
    std::error_code ec;
    fs::remove(script, ec);
    EXPECT_EQ(st, 0) << out;
    return nlohmann::json::parse(out, nullptr, /*allow_exceptions=*/false);
}

/// Each triangle rotated so its smallest index comes first (same cyclic order = same winding).
std::vector<Triangle> canonical(std::vector<Triangle> t) {
    for (Triangle& f : t) {
        while (f[0] > f[1] || f[0] > f[2]) f = Triangle{f[1], f[2], f[0]};
    }
    return t;
}

void expect_roundtrip(const std::string& file, const StripArrays& a, const std::vector<uint32_t>& idx) {
    const GltfStrip g = read_gltf_strip(file);
    EXPECT_EQ(g.mode, 5) << "primitive mode must be TRIANGLE_STRIP";
    EXPECT_EQ(g.indices, idx);
    // Our own decoder on the file's indices gives back exactly the output faces, in order.
    EXPECT_EQ(canonical(decode_triangle_strip(g.indices)), canonical(a.faces));
    uint32_t max_index = 0;
    for (uint32_t i : g.indices) max_index = std::max(max_index, i);
    EXPECT_EQ(g.index_component_type, max_index < 65535 ? 5123 : 5125);
    ASSERT_EQ(g.positions.size(), a.points.size());
    for (size_t v = 0; v < a.points.size(); ++v)
        for (int d = 0; d < 3; ++d) ASSERT_EQ(g.positions[v][d], static_cast<double>(static_cast<float>(a.points[v][d])));
    ASSERT_EQ(g.normals.size(), a.points.size());
    // Normals are unit (the validator requires it; direction is checked on a sphere below).
    for (const Point3& n : g.normals) EXPECT_NEAR(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1.0, 1e-5);
}

struct Case {
    std::string name;
    TriangleSoup soup;
};

std::vector<Case> cases() {
    return {
        {"tetra", read_mesh_file(std::string(SINGLESTRIP_SOURCE_DIR) + "/tests/data/tetra.off")},
        {"icosphere", make_icosphere(2)},
        {"torus", make_torus(24, 12)},
        {"genus2_with_holes", make_genus_with_holes(2, 2, 6)},
        {"builtin", make_builtin_model()},
        // > 65535 vertices: 32-bit indices.
        {"big_grid", make_grid_disk(260, 260)},
    };
}

}  // namespace

TEST(Gltf, RoundTripDecodesToOutputFaces) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const StripArrays a = strip_of(c.soup);
        const std::vector<uint32_t> idx = encode_triangle_strip(a.faces);
        for (const char* ext : {".glb", ".gltf"}) {
            const std::string file = (scratch_dir() / (c.name + ext)).string();
            write_gltf_strip(file, a, idx);
            expect_roundtrip(file, a, idx);
            // Atomic write: no temporary left next to the file.
            for (const auto& e : fs::directory_iterator(scratch_dir()))
                EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
        }
    }
}

// glTF holds float32 positions and no parents: the verifier finds each face's parent from the
// split structure. Polygons whose ears are thinner than a float32 step (20,000 points on the
// unit circle; 5,000 on a circle of radius 1 at 1e4 from the origin, where a step is 1e-3)
// made geometric inference pick neighbouring ears and report valid strips as broken.
TEST(Gltf, Float32NeedlesVerify) {
    const std::vector<std::pair<std::string, TriangleSoup>> polygons = {
        {"unit", make_circle_polygon(20000)},
        {"far", make_circle_polygon(5000, 1, {1e4, 1e4, 0})},
        {"small", make_circle_polygon(20000, 1e-3, {0, 0, 0}, 11)},
    };
    for (const auto& [name, soup] : polygons)
        for (StripEngine e : {StripEngine::Matching, StripEngine::Growth}) {
            SCOPED_TRACE(name + (e == StripEngine::Matching ? " matching" : " growth"));
            StripOptions o;
            o.engine = e;
            const StripArrays a = strip_arrays(build_strip(Mesh::from_soup(prepare_soup(soup, {}, "test")), o));
            ASSERT_GT(a.faces.size(), soup.triangles.size());  // split: there are parents to find
            const std::string file = (scratch_dir() / ("needles_" + name + ".glb")).string();
            write_gltf_strip(file, a, encode_triangle_strip(a.faces));
            const VerifyReport r = verify_files(soup, file);
            EXPECT_TRUE(r.ok()) << r.to_string();
        }
}

TEST(Gltf, BigMeshUsesUint32AndSmallUint16) {
    const StripArrays big = strip_of(make_grid_disk(260, 260));
    ASSERT_GT(big.points.size(), 65535u);
    const std::string f1 = (scratch_dir() / "big.glb").string();
    write_gltf_strip(f1, big, encode_triangle_strip(big.faces));
    EXPECT_EQ(read_gltf_strip(f1).index_component_type, 5125);
    const StripArrays small = strip_of(make_icosphere(1));
    const std::string f2 = (scratch_dir() / "small.glb").string();
    write_gltf_strip(f2, small, encode_triangle_strip(small.faces));
    EXPECT_EQ(read_gltf_strip(f2).index_component_type, 5123);
}

TEST(Gltf, NormalsPointOutwardOnConvexMesh) {
    const StripArrays a = strip_of(make_icosphere(2));
    const std::vector<Point3> n = vertex_normals(a.points, a.faces);
    // Icosphere is centred at the origin: outward normal ~ position direction.
    for (size_t v = 0; v < a.points.size(); ++v) {
        const Point3& p = a.points[v];
        const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        const double dot = (p[0] * n[v][0] + p[1] * n[v][1] + p[2] * n[v][2]) / len;
        EXPECT_GT(dot, 0.95) << "vertex " << v;
    }
}

TEST(Gltf, Errors) {
    const StripArrays a = strip_of(make_icosphere(0));
    const std::vector<uint32_t> idx = encode_triangle_strip(a.faces);
    EXPECT_THROW(write_gltf_strip((scratch_dir() / "x.obj").string(), a, idx), RequestError);
    EXPECT_THROW(write_gltf_strip((scratch_dir() / "x.glb").string(), a, {}), RequestError);
    std::vector<uint32_t> bad = idx;
    bad[0] = static_cast<uint32_t>(a.points.size());
    EXPECT_THROW(write_gltf_strip((scratch_dir() / "x.glb").string(), a, bad), RequestError);
    EXPECT_THROW(write_gltf_strip((scratch_dir() / "no-such-dir" / "x.glb").string(), a, idx), OutputError);
    EXPECT_FALSE(fs::exists(scratch_dir() / "x.glb"));
    EXPECT_THROW(read_gltf_strip(std::string(SINGLESTRIP_SOURCE_DIR) + "/tests/data/tetra.off"), InputError);
    EXPECT_TRUE(is_gltf_path("a/B.GLB"));
    EXPECT_TRUE(is_gltf_path("x.gltf"));
    EXPECT_FALSE(is_gltf_path("x.glb.ply"));
}

TEST(Gltf, KhronosValidatorReportsNoErrors) {
    std::string why;
    const std::string dir = validator_dir(why);
    if (dir.empty()) GTEST_SKIP() << "Khronos glTF-Validator unavailable: " << why;
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const StripArrays a = strip_of(c.soup);
        const std::vector<uint32_t> idx = encode_triangle_strip(a.faces);
        for (const char* ext : {".glb", ".gltf"}) {
            const std::string file = fs::absolute(scratch_dir() / (c.name + "_v" + ext)).string();
            write_gltf_strip(file, a, idx);
            const nlohmann::json r = validate_gltf(dir, file);
            ASSERT_TRUE(r.is_object() && r.contains("issues")) << r.dump();
            const auto& issues = r["issues"];
            EXPECT_EQ(issues["numErrors"].get<int>(), 0) << file << ": " << issues.dump(1);
            // The validator saw what we wrote: one TRIANGLE_STRIP primitive.
            const auto& info = r["info"];
            EXPECT_EQ(info["drawCallCount"].get<int>(), 1) << info.dump();
            EXPECT_EQ(info["totalVertexCount"].get<size_t>(), a.points.size()) << info.dump();
            if (issues["numWarnings"].get<int>() != 0) std::cerr << file << ": warnings: " << issues["messages"].dump() << '\n';
        }
    }
}

TEST(Gltf, KhronosValidatorCatchesACorruptedFile) {
    // Guards against a validator run that silently checks nothing: a wrong POSITION max and a
    // wrong mode must be reported as errors.
    std::string why;
    const std::string dir = validator_dir(why);
    if (dir.empty()) GTEST_SKIP() << "Khronos glTF-Validator unavailable: " << why;
    const StripArrays a = strip_of(make_icosphere(1));
    const std::string file = fs::absolute(scratch_dir() / "corrupt.gltf").string();
    write_gltf_strip(file, a, encode_triangle_strip(a.faces));
    nlohmann::json doc;
    {
        std::ifstream in(file);
        in >> doc;
    }
    doc["accessors"][0]["max"][0] = doc["accessors"][0]["max"][0].get<double>() + 1.0;
    doc["meshes"][0]["primitives"][0]["mode"] = 9;  // not a glTF primitive mode
    {
        std::ofstream out(file);
        out << doc.dump();
    }
    const nlohmann::json r = validate_gltf(dir, file);
    ASSERT_TRUE(r.is_object() && r.contains("issues")) << r.dump();
    EXPECT_GE(r["issues"]["numErrors"].get<int>(), 2) << r["issues"].dump(1);
}

TEST(Gltf, SeveralComponentsAreJoinedByDegenerateTrianglesAndValidate) {
    // Three separate surfaces; the index file uses restarts, glTF (no restart in core) gets
    // degenerate joins that still decode to exactly the output faces.
    TriangleSoup s = make_icosphere(1);
    for (const TriangleSoup& part : {make_torus(8, 5), make_grid_disk(5, 4)}) {
        const auto base = static_cast<uint32_t>(s.points.size());
        const double shift = 4.0 * static_cast<double>(s.triangles.size());
        for (Point3 p : part.points) s.points.push_back({p[0] + shift, p[1], p[2]});
        for (Triangle t : part.triangles) s.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    PipelineOptions o;
    o.join = JoinMode::Restart;
    const PipelineResult r = stripify(s, o);
    ASSERT_EQ(r.components.size(), 3u);
    const std::vector<uint32_t> idx = degenerate_joined_indices(r);
    EXPECT_EQ(std::count(idx.begin(), idx.end(), 0xffffffffu), 0);
    std::string why;
    const std::string dir = validator_dir(why);
    for (const char* ext : {".glb", ".gltf"}) {
        const std::string file = fs::absolute(scratch_dir() / (std::string("three_parts") + ext)).string();
        write_gltf_strip(file, r.arrays, idx);
        const GltfStrip g = read_gltf_strip(file);
        EXPECT_EQ(g.mode, 5);
        EXPECT_EQ(canonical(decode_triangle_strip(g.indices)), canonical(r.arrays.faces));
        if (dir.empty()) continue;
        const nlohmann::json v = validate_gltf(dir, file);
        ASSERT_TRUE(v.is_object() && v.contains("issues")) << v.dump();
        EXPECT_EQ(v["issues"]["numErrors"].get<int>(), 0) << file << ": " << v["issues"].dump(1);
    }
    if (dir.empty()) GTEST_SKIP() << "decoded; Khronos glTF-Validator unavailable: " << why;
}

namespace {

/// A whole output model, read with tinygltf (images kept as bytes).
tinygltf::Model load_any(const std::string& path) {
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(
        [](tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) { return true; }, nullptr);
    std::string err, warn;
    const bool ok = path.size() > 4 && path.substr(path.size() - 4) == ".glb" ? loader.LoadBinaryFromFile(&m, &err, &warn, path)
                                                                              : loader.LoadASCIIFromFile(&m, &err, &warn, path);
    EXPECT_TRUE(ok) << err;
    return m;
}

/// Accessor `i` as floats (float or unsigned integer components, normalised ones mapped to [0, 1]).
std::vector<double> floats(const tinygltf::Model& m, int i) {
    const auto& a = m.accessors.at(static_cast<size_t>(i));
    const auto& v = m.bufferViews.at(static_cast<size_t>(a.bufferView));
    const auto& b = m.buffers.at(static_cast<size_t>(v.buffer)).data;
    const int k = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
    const int cs = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
    const size_t stride = v.byteStride ? v.byteStride : static_cast<size_t>(k * cs);
    std::vector<double> out;
    for (size_t e = 0; e < a.count; ++e)
        for (int c = 0; c < k; ++c) {
            const unsigned char* p = b.data() + v.byteOffset + a.byteOffset + e * stride + static_cast<size_t>(c * cs);
            if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
                float f;
                std::memcpy(&f, p, 4);
                out.push_back(f);
            } else if (cs == 1) {
                out.push_back(a.normalized ? *p / 255.0 : *p);
            } else if (cs == 2) {
                uint16_t h;
                std::memcpy(&h, p, 2);
                out.push_back(a.normalized ? h / 65535.0 : h);
            } else {
                uint32_t u;
                std::memcpy(&u, p, 4);
                out.push_back(u);
            }
        }
    return out;
}

double area(const std::vector<double>& pos, const Triangle& t) {
    double u[3], w[3];
    for (int d = 0; d < 3; ++d) {
        u[d] = pos[3 * t[1] + d] - pos[3 * t[0] + d];
        w[d] = pos[3 * t[2] + d] - pos[3 * t[0] + d];
    }
    const double c0 = u[1] * w[2] - u[2] * w[1], c1 = u[2] * w[0] - u[0] * w[2], c2 = u[0] * w[1] - u[1] * w[0];
    return 0.5 * std::sqrt(c0 * c0 + c1 * c1 + c2 * c2);
}

}  // namespace

// Outputs that carry the input's attributes (OBJ vt/vn, PLY normals, colours, texture
// coordinates and custom scalars): zero errors and zero warnings, every attribute present.
TEST(Gltf, AttributeCarryingOutputsValidate) {
    std::string why;
    const std::string dir = validator_dir(why);
    for (const char* name : {"sphere_uv.obj", "sphere_attrs.ply"}) {
        SCOPED_TRACE(name);
        const PipelineResult r = stripify(read_mesh_file(std::string(SINGLESTRIP_SOURCE_DIR) + "/tests/data/" + name), PipelineOptions{});
        for (const char* ext : {".glb", ".gltf"}) {
            const std::string file = fs::absolute(scratch_dir() / (std::string("attrs_") + name + ext)).string();
            write_gltf_strip(file, r.arrays, degenerate_joined_indices(r));
            const tinygltf::Model m = load_any(file);
            const auto& attrs = m.meshes[0].primitives[0].attributes;
            EXPECT_EQ(attrs.size(), r.arrays.attributes.size() + 1) << "POSITION and one accessor per attribute";
            EXPECT_EQ(attrs.count("TEXCOORD_0"), 1u);
            EXPECT_EQ(attrs.count("NORMAL"), 1u);
            if (std::string(name) == "sphere_attrs.ply") {
                EXPECT_EQ(attrs.count("COLOR_0"), 1u);
                EXPECT_EQ(attrs.count("_QUALITY"), 1u);
                EXPECT_EQ(attrs.count("_ID"), 1u);
            }
            if (dir.empty()) continue;
            const nlohmann::json v = validate_gltf(dir, file);
            ASSERT_TRUE(v.is_object() && v.contains("issues")) << v.dump();
            EXPECT_EQ(v["issues"]["numErrors"].get<int>(), 0) << file << ": " << v["issues"].dump(1);
            EXPECT_EQ(v["issues"]["numWarnings"].get<int>(), 0) << file << ": " << v["issues"].dump(1);
        }
    }
    if (dir.empty()) GTEST_SKIP() << "checked; Khronos glTF-Validator unavailable: " << why;
}

TEST(GltfInput, ReadsEveryTrianglePrimitive) {
    for (const char* f : {"scene.gltf", "scene.glb"}) {
        const TriangleSoup s = read_gltf_soup(std::string(SINGLESTRIP_SOURCE_DIR) + "/tests/data/" + f);
        EXPECT_EQ(s.triangles.size(), 96u + 12u + 24u) << f;  // tube, cube, non-indexed grid; the LINES are skipped
    }
    EXPECT_THROW(read_gltf_soup(std::string(SINGLESTRIP_SOURCE_DIR) + "/tests/data/tetra.off"), InputError);
}

TEST(GltfInput, SceneWithSeveralTexturedPrimitivesStripsKeepsTheRestAndValidates) {
    std::string why;
    const std::string dir = validator_dir(why);
    for (const char* in_name : {"scene.gltf", "scene.glb"}) {
        const std::string in = std::string(SINGLESTRIP_SOURCE_DIR) + "/tests/data/" + in_name;
        const tinygltf::Model src = load_any(in);
        for (const char* ext : {".glb", ".gltf"}) {
            SCOPED_TRACE(std::string(in_name) + " -> " + ext);
            const std::string out = fs::absolute(scratch_dir() / (std::string("scene_out_") + in_name + ext)).string();
            const auto prims = strip_gltf_file(in, out, PipelineOptions{});
            ASSERT_EQ(prims.size(), 4u);
            EXPECT_TRUE(prims[0].stripped && prims[1].stripped && prims[2].stripped);
            EXPECT_FALSE(prims[3].stripped);  // LINES kept as they were
            EXPECT_EQ(prims[1].strips, 6u);   // the cube's per-face UVs are seams: six pieces
            EXPECT_GT(prims[2].welded, 0u);   // the non-indexed grid's equal corners were merged
            const tinygltf::Model m = load_any(out);
            EXPECT_EQ(m.nodes.size(), src.nodes.size());
            EXPECT_EQ(m.materials.size(), src.materials.size());
            EXPECT_EQ(m.textures.size(), src.textures.size());
            EXPECT_EQ(m.images.size(), src.images.size());
            EXPECT_EQ(m.skins.size(), src.skins.size());
            EXPECT_EQ(m.meshes[0].primitives[0].material, 0);
            EXPECT_EQ(m.meshes[2].primitives[0].mode, TINYGLTF_MODE_LINE);
            for (size_t k = 0; k < 3; ++k) {
                const auto& mp = k < 2 ? m.meshes[0].primitives[k] : m.meshes[1].primitives[0];
                const auto& sp = k < 2 ? src.meshes[0].primitives[k] : src.meshes[1].primitives[0];
                ASSERT_EQ(mp.mode, TINYGLTF_MODE_TRIANGLE_STRIP);
                EXPECT_EQ(mp.attributes.size(), sp.attributes.size());
                std::vector<uint32_t> idx;
                for (double x : floats(m, mp.indices)) idx.push_back(static_cast<uint32_t>(x));
                const auto faces = decode_triangle_strip(idx);
                EXPECT_EQ(faces.size(), prims[k].output_triangles);
                // Same surface: the strip's area is the input's.
                const auto pos = floats(m, mp.attributes.at("POSITION")), spos = floats(src, sp.attributes.at("POSITION"));
                double a_out = 0, a_in = 0;
                for (const Triangle& t : faces) a_out += area(pos, t);
                if (k == 0) {  // the tube's triangles come first in read_gltf_soup(), on its own vertices
                    for (const Triangle& t : read_gltf_soup(in).triangles)
                        if (t[0] < spos.size() / 3) a_in += area(spos, t);
                    EXPECT_NEAR(a_out, a_in, 1e-5 * a_in);
                }
                // Input vertices keep every attribute; the tube's midpoints get interpolated ones.
                for (const auto& [name, acc] : sp.attributes) {
                    const auto before = floats(src, acc), after = floats(m, mp.attributes.at(name));
                    ASSERT_GE(after.size(), before.size()) << name;
                    for (size_t i = 0; i < before.size(); ++i) EXPECT_NEAR(after[i], before[i], 1e-6) << name;
                }
                if (k == 0) {
                    const auto nrm = floats(m, mp.attributes.at("NORMAL")), uv = floats(m, mp.attributes.at("TEXCOORD_0"));
                    for (size_t v = 0; v < pos.size() / 3; ++v) {
                        // Normals radial (the midpoint of a chord points the same way), v = y / 2.
                        const double r = std::hypot(pos[3 * v], pos[3 * v + 2]);
                        EXPECT_NEAR(nrm[3 * v], pos[3 * v] / r, 1e-5);
                        EXPECT_NEAR(nrm[3 * v + 2], pos[3 * v + 2] / r, 1e-5);
                        EXPECT_NEAR(uv[2 * v + 1], pos[3 * v + 1] / 2, 1e-5);
                    }
                }
            }
            // The independent verifier, primitive by primitive, with float32 tolerances.
            const VerifyReport rep = verify_files(in, out);
            EXPECT_TRUE(rep.ok()) << rep.to_string();
            EXPECT_EQ(rep.strips, 8u);  // tube 1, cube 6, grid 1
            if (dir.empty()) continue;
            const nlohmann::json v = validate_gltf(dir, out);
            ASSERT_TRUE(v.is_object() && v.contains("issues")) << v.dump();
            EXPECT_EQ(v["issues"]["numErrors"].get<int>(), 0) << out << ": " << v["issues"].dump(1);
            EXPECT_EQ(v["issues"]["numWarnings"].get<int>(), 0) << out << ": " << v["issues"].dump(1);
        }
    }
    if (dir.empty()) GTEST_SKIP() << "checked; Khronos glTF-Validator unavailable: " << why;
}

TEST(GltfInput, QuantizedPrimitiveIsStrippedWithFloatAttributes) {
    // KHR_mesh_quantization: uint16 positions, normalised int8 normals, uint16 UVs. The strip keeps
    // the values (new accessors are float, which the extension allows) and the node's dequantizing scale.
    const std::string in = std::string(SINGLESTRIP_SOURCE_DIR) + "/tests/data/quantized.glb";
    const std::string out = fs::absolute(scratch_dir() / "quantized_out.glb").string();
    const auto prims = strip_gltf_file(in, out, PipelineOptions{});
    ASSERT_EQ(prims.size(), 1u);
    EXPECT_TRUE(prims[0].stripped);
    const tinygltf::Model src = load_any(in), m = load_any(out);
    EXPECT_EQ(m.nodes[0].scale, src.nodes[0].scale);
    const auto& sp = src.meshes[0].primitives[0];
    const auto& mp = m.meshes[0].primitives[0];
    EXPECT_EQ(mp.mode, TINYGLTF_MODE_TRIANGLE_STRIP);
    const auto before = floats(src, sp.attributes.at("POSITION")), after = floats(m, mp.attributes.at("POSITION"));
    for (size_t i = 0; i < before.size(); ++i) EXPECT_EQ(after[i], before[i]);
    const auto nrm = floats(m, mp.attributes.at("NORMAL"));
    for (size_t v = 0; v < nrm.size() / 3; ++v) EXPECT_NEAR(std::hypot(nrm[3 * v], nrm[3 * v + 1], nrm[3 * v + 2]), 1.0, 1e-5);
    std::string why;
    const std::string dir = validator_dir(why);
    if (dir.empty()) GTEST_SKIP() << "checked; Khronos glTF-Validator unavailable: " << why;
    const nlohmann::json v = validate_gltf(dir, out);
    ASSERT_TRUE(v.is_object() && v.contains("issues")) << v.dump();
    EXPECT_EQ(v["issues"]["numErrors"].get<int>(), 0) << v["issues"].dump(1);
}
