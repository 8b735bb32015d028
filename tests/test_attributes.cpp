// Vertex attributes (issue 18, item 3): OBJ vt/vn with their own index streams (seams become
// boundaries, so the picture is unchanged), PLY vertex properties, glTF attributes into other
// formats; midpoints blended; every output format writes what it holds; verify accepts them.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "shell.hpp"
#include "singlestrip/attributes.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/gltf.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/repair.hpp"
#include "singlestrip/validate.hpp"
#include "singlestrip/verify.hpp"
#include "tinygltf_read.hpp"

using namespace singlestrip;
namespace fs = std::filesystem;

namespace {

std::string data(const std::string& name) {
    return std::string(SINGLESTRIP_SOURCE_DIR) + "/tests/data/" + name;
}

struct Scratch : singlestrip::test::ScratchDir {
    explicit Scratch(const std::string& tag) : ScratchDir("attrs-" + tag) {}
};

/// Exit code and merged output of the CLI.
singlestrip::test::ShellRun cli(const std::string& args) {
    return singlestrip::test::run_program(SINGLESTRIP_CLI_PATH, args);
}

void write_file(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

/// The attributes of the strip primitive of a glTF OUT (float accessors, tightly packed) as a
/// soup's attributes, under their glTF names.
TriangleSoup read_gltf_output(const std::string& path) {
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    const bool ok = is_gltf_path(path) && path.back() == 'b' ? loader.LoadBinaryFromFile(&m, &err, &warn, path)
                                                             : loader.LoadASCIIFromFile(&m, &err, &warn, path);
    EXPECT_TRUE(ok) << err;
    TriangleSoup s;
    if (!ok) return s;
    s.points = read_gltf_strip(path).positions;
    for (const auto& [name, index] : m.meshes[0].primitives[0].attributes) {
        const tinygltf::Accessor& a = m.accessors[static_cast<size_t>(index)];
        const tinygltf::BufferView& v = m.bufferViews[static_cast<size_t>(a.bufferView)];
        const auto k = static_cast<uint32_t>(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type)));
        EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT) << name;
        const auto* f = reinterpret_cast<const float*>(m.buffers[static_cast<size_t>(v.buffer)].data.data() + v.byteOffset + a.byteOffset);
        s.attributes.push_back({name, k, AttributeBlend::Linear, std::vector<double>(f, f + a.count * k)});
    }
    return s;
}

/// Every output vertex that is not an input vertex lies halfway along an edge of its parent face
/// (a split midpoint): its attributes must be the blend of that edge's ends.
void expect_midpoints_blended(const PipelineResult& r) {
    const size_t n = r.input.points.size();
    size_t checked = 0;
    for (size_t f = 0; f < r.arrays.faces.size(); ++f)
        for (uint32_t m : r.arrays.faces[f]) {
            if (m < n) continue;
            const Triangle& t = r.input.triangles[r.arrays.parent[f]];
            for (int e = 0; e < 3; ++e) {
                const uint32_t a = t[e], b = t[(e + 1) % 3];
                bool halfway = true;
                for (int d = 0; d < 3; ++d)
                    halfway = halfway && std::abs(r.arrays.points[m][d] - (r.input.points[a][d] + r.input.points[b][d]) / 2) < 1e-12;
                if (!halfway) continue;
                ++checked;
                for (size_t i = 0; i < r.input.attributes.size(); ++i) {
                    const VertexAttribute& in = r.input.attributes[i];
                    const VertexAttribute& out = r.arrays.attributes[i];
                    const size_t k = in.components;
                    std::vector<double> want(k);
                    for (size_t c = 0; c < k; ++c) want[c] = (in.values[a * k + c] + in.values[b * k + c]) / 2;
                    if (in.blend == AttributeBlend::Unit) {
                        const double len = std::sqrt(want[0] * want[0] + want[1] * want[1] + want[2] * want[2]);
                        for (size_t c = 0; c < 3; ++c) want[c] /= len;
                    }
                    for (size_t c = 0; c < k; ++c) {
                        if (in.blend == AttributeBlend::Nearest)
                            EXPECT_TRUE(out.values[m * k + c] == in.values[a * k + c] || out.values[m * k + c] == in.values[b * k + c])
                                << in.name;
                        else
                            EXPECT_NEAR(out.values[m * k + c], want[c], 1e-9) << in.name << " of midpoint " << m;
                    }
                }
                break;
            }
        }
    EXPECT_GT(checked, 0u) << "no midpoint to check";
}

}  // namespace

TEST(ObjAttributes, SeamsBecomeVerticesOfTheirOwn) {
    const TriangleSoup s = read_mesh_file(data("sphere_uv.obj"));
    // 42 positions; the u = 0/1 meridian (5 rings) and the two poles (8 texture coordinates each)
    // give 5 + 7 + 7 more vertices.
    ASSERT_EQ(s.points.size(), 61u);
    ASSERT_EQ(s.attributes.size(), 2u);
    EXPECT_EQ(s.attributes[0].name, "TEXCOORD_0");
    EXPECT_EQ(s.attributes[1].name, "NORMAL");
    EXPECT_EQ(s.attributes[1].blend, AttributeBlend::Unit);
    EXPECT_EQ(s.points[0], (Point3{0, 0, 1}));  // file vertex numbers are kept
    for (size_t v = 42; v < s.points.size(); ++v) {
        bool same = false;
        for (size_t u = 0; u < 42; ++u) same = same || s.points[u] == s.points[v];
        EXPECT_TRUE(same) << "vertex " << v << " is a copy of a file vertex";
    }
    // Cut along the seam, the sphere is a disk: one boundary loop, nothing else wrong.
    const MeshInfo m = mesh_info(s);
    EXPECT_TRUE(m.valid());
    EXPECT_EQ(m.components, 1u);
    EXPECT_EQ(m.boundary_loops, 1u);
    EXPECT_EQ(m.unwelded_vertices, 0u);  // seam copies differ in their attributes
}

TEST(ObjAttributes, MidpointsGetBlendedAttributesAndInputVerticesKeepTheirs) {
    const TriangleSoup s = read_mesh_file(data("sphere_uv.obj"));
    const PipelineResult r = stripify(s, PipelineOptions{});
    ASSERT_EQ(r.arrays.attributes.size(), 2u);
    ASSERT_GT(r.strip.stats.splits, 0u);
    for (size_t i = 0; i < 2; ++i) {
        const VertexAttribute& a = r.arrays.attributes[i];
        ASSERT_EQ(a.values.size(), r.arrays.points.size() * a.components);
        for (size_t j = 0; j < s.attributes[i].values.size(); ++j) EXPECT_EQ(a.values[j], s.attributes[i].values[j]);
    }
    expect_midpoints_blended(r);
}

TEST(ObjAttributes, EveryOutputFormatWritesWhatItHoldsAndVerifies) {
    Scratch dir("formats");
    const std::string in = data("sphere_uv.obj");
    const PipelineResult r = stripify(read_mesh_file(in), PipelineOptions{});
    for (const char* name : {"o.obj", "o.ply", "o.glb", "o.gltf", "o.off"}) {
        SCOPED_TRACE(name);
        const std::string out = dir / name;
        const auto [code, text] = cli("strip '" + in + "' -o '" + out + "'");
        ASSERT_EQ(code, 0) << text;
        const auto [vcode, vtext] = cli("verify '" + in + "' '" + out + "'");
        EXPECT_EQ(vcode, 0) << vtext;
        if (std::string(name) == "o.off") {  // OFF output holds positions only, and says so
            EXPECT_NE(text.find("has no place for the vertex attributes TEXCOORD_0 NORMAL"), std::string::npos) << text;
            continue;
        }
        EXPECT_EQ(text.find("has no place"), std::string::npos) << text;
        const TriangleSoup back = is_gltf_path(out) ? read_gltf_output(out) : read_mesh_file(out);
        ASSERT_EQ(back.points.size(), r.arrays.points.size());
        for (const char* attr : {"TEXCOORD_0", "NORMAL"}) {
            const VertexAttribute* got = find_attribute(back.attributes, attr);
            const VertexAttribute* want = find_attribute(r.arrays.attributes, attr);
            ASSERT_TRUE(got && want) << attr;
            ASSERT_EQ(got->values.size(), want->values.size()) << attr;
            const double tol = std::string(name) == "o.obj" ? 0 : 1e-6;  // float32 in PLY and glTF
            for (size_t i = 0; i < want->values.size(); ++i) EXPECT_NEAR(got->values[i], want->values[i], tol) << attr << " " << i;
        }
    }
}

TEST(ObjAttributes, BadTextureOrNormalReferenceNamesFileLineAndProblem) {
    Scratch dir("bad");
    const std::string head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
    const struct {
        const char* face;
        const char* message;
    } cases[] = {
        {"f 1/1 2/2 3/1\n", "line 6: face 0 references texture coordinate 1 but the file has only 1 'vt' records"},
        {"f 1//1 2//1 3//-2\n", "line 6: face 0 references normal -1 but the file has only 1 'vn' records"},
        {"f 1/0 2/1 3/1\n", "line 6: face 0: bad vertex reference '1/0'"},
        {"f 1/x 2/1 3/1\n", "line 6: face 0: bad vertex reference '1/x'"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.face);
        const std::string path = dir / "bad.obj";
        write_file(path, head + c.face);
        try {
            read_mesh_file(path);
            ADD_FAILURE() << "accepted";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(path + ": " + c.message), std::string::npos) << e.what();
        }
        EXPECT_EQ(cli("strip '" + path + "' -o '" + dir / "o.ply'").code, 3);  // bad input (docs)
    }
    write_file(dir / "vt.obj", "v 0 0 0\nvt 0 nan\n");
    EXPECT_THROW(read_mesh_file(dir / "vt.obj"), InputError);
}

TEST(ObjAttributes, AStreamOnlySomeCornersHaveIsNotKept) {
    // tests/data/pyramid_slashes.obj mixes "i", "i/t", "i//n" and "i/t/n" corners.
    const TriangleSoup s = read_mesh_file(data("pyramid_slashes.obj"));
    EXPECT_TRUE(s.attributes.empty());
    EXPECT_EQ(s.points.size(), 6u);
}

TEST(ObjAttributes, VertexColoursAreKeptAndFollowTheSeams) {
    Scratch dir("colours");
    std::ifstream in(data("sphere_uv.obj"));
    std::string obj, line;
    int v = 0;
    while (std::getline(in, line)) {
        if (line.rfind("v ", 0) == 0) line += " " + std::to_string(v++ % 2) + " 0.5 0.25";
        obj += line + "\n";
    }
    write_file(dir / "c.obj", obj);
    const TriangleSoup s = read_mesh_file(dir / "c.obj");
    const VertexAttribute* c = find_attribute(s.attributes, "COLOR_0");
    ASSERT_NE(c, nullptr);
    ASSERT_EQ(c->values.size(), 3 * s.points.size());
    for (size_t u = 0; u < s.points.size(); ++u)
        for (size_t w = 0; w < 42; ++w)
            if (s.points[u] == s.points[w]) {
                EXPECT_EQ(c->values[3 * u], c->values[3 * w]) << u;  // seam copies: their position's colour
            }
    const auto [code, text] = cli("strip '" + dir / "c.obj" + "' -o '" + dir / "o.obj" + "'");
    ASSERT_EQ(code, 0) << text;
    const TriangleSoup out = read_mesh_file(dir / "o.obj");  // kept: `back` points into it
    const VertexAttribute* back = find_attribute(out.attributes, "COLOR_0");
    ASSERT_NE(back, nullptr);
    for (size_t i = 0; i < c->values.size(); ++i) EXPECT_EQ(back->values[i], c->values[i]);
    // One vertex without a colour: no COLOR_0 (a "v x y z w" file is not coloured either).
    write_file(dir / "partial.obj", "v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 0 0 1\nf 1 2 3\n");
    EXPECT_TRUE(read_mesh_file(dir / "partial.obj").attributes.empty());
    write_file(dir / "w.obj", "v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 1 2 3\n");
    EXPECT_TRUE(read_mesh_file(dir / "w.obj").attributes.empty());
}

TEST(PlyAttributes, VertexPropertiesAreReadCarriedAndWrittenBack) {
    Scratch dir("ply");
    const std::string in = data("sphere_attrs.ply");
    const TriangleSoup s = read_mesh_file(in);
    std::vector<std::string> names;
    for (const auto& a : s.attributes) names.push_back(a.name);
    EXPECT_EQ(names, (std::vector<std::string>{"NORMAL", "COLOR_0", "TEXCOORD_0", "quality", "id"}));
    const VertexAttribute& colour = *find_attribute(s.attributes, "COLOR_0");
    EXPECT_EQ(colour.components, 4u);
    EXPECT_DOUBLE_EQ(colour.values[0], 128.0 / 255);                                // uchar 128
    EXPECT_DOUBLE_EQ(colour.values[2], 1.0);                                        // uchar 255
    EXPECT_EQ(find_attribute(s.attributes, "id")->blend, AttributeBlend::Nearest);  // integers may be ids
    EXPECT_EQ(find_attribute(s.attributes, "id")->values[3], 103.0);

    const PipelineResult r = stripify(s, PipelineOptions{});
    ASSERT_GT(r.strip.stats.splits, 0u);
    expect_midpoints_blended(r);

    for (const char* name : {"o.ply", "o.glb"}) {
        SCOPED_TRACE(name);
        const std::string out = dir / name;
        const auto [code, text] = cli("strip '" + in + "' -o '" + out + "'");
        ASSERT_EQ(code, 0) << text;
        const auto [vcode, vtext] = cli("verify '" + in + "' '" + out + "'");
        EXPECT_EQ(vcode, 0) << vtext;
        const TriangleSoup back = is_gltf_path(out) ? read_gltf_output(out) : read_mesh_file(out);
        ASSERT_EQ(back.attributes.size(), s.attributes.size() + (is_gltf_path(out) ? 1 : 0));  // + POSITION
        for (size_t i = 0; i < s.attributes.size(); ++i) {
            const std::string want_name = is_gltf_path(out) && i >= 3 ? "_" + std::string(i == 3 ? "QUALITY" : "ID") : s.attributes[i].name;
            const VertexAttribute* got = find_attribute(back.attributes, want_name);
            ASSERT_NE(got, nullptr) << want_name;
            for (size_t j = 0; j < s.attributes[i].values.size(); ++j)  // input vertices unchanged
                EXPECT_NEAR(got->values[j], s.attributes[i].values[j], 1e-6) << want_name;
        }
    }
}

TEST(PlyAttributes, NonFiniteBinaryPropertyIsRefused) {
    Scratch dir("nan");
    std::string ply =
        "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
        "property float nx\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n";
    const float v[4] = {0, 0, 0, std::nanf("")};
    ply.append(reinterpret_cast<const char*>(v), sizeof v);
    write_file(dir / "nan.ply", ply);
    try {
        read_mesh_file(dir / "nan.ply");
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("vertex 0: property 'nx' is not finite"), std::string::npos) << e.what();
    }
}

TEST(GltfAttributes, SceneIntoPlyAndObjKeepsItsAttributes) {
    Scratch dir("gltf");
    const std::string in = data("scene.glb");
    const TriangleSoup s = read_gltf_soup(in);
    ASSERT_NE(find_attribute(s.attributes, "TEXCOORD_0"), nullptr);
    ASSERT_NE(find_attribute(s.attributes, "NORMAL"), nullptr);
    for (const char* name : {"o.ply", "o.obj"}) {
        SCOPED_TRACE(name);
        const std::string out = dir / name;
        const auto [code, text] = cli("strip '" + in + "' -o '" + out + "'");
        ASSERT_EQ(code, 0) << text;
        const auto [vcode, vtext] = cli("verify '" + in + "' '" + out + "'");
        EXPECT_EQ(vcode, 0) << vtext;
        const TriangleSoup back = read_mesh_file(out);
        const VertexAttribute* uv = find_attribute(back.attributes, "TEXCOORD_0");
        ASSERT_NE(uv, nullptr);
        const VertexAttribute& want = *find_attribute(s.attributes, "TEXCOORD_0");
        std::vector<char> used(back.points.size(), 0);  // OBJ gives vertices without a corner no attributes
        for (const Triangle& t : back.triangles)
            for (uint32_t v : t) used[v] = 1;
        for (size_t j = 0; j < want.values.size(); ++j)
            if (used[j / 2]) {
                EXPECT_NEAR(uv->values[j], want.values[j], 1e-6);
            }
    }
}

TEST(WeldAttributes, WeldMergesOnlyVerticesEqualInEveryAttribute) {
    TriangleSoup s;
    s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    s.triangles = {{0, 1, 2}, {3, 5, 4}};
    s.attributes.push_back({"TEXCOORD_0", 2, AttributeBlend::Linear, {0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 1, 1}});
    TriangleSoup a = s;
    EXPECT_EQ(weld_soup(a), 2u);      // equal positions and texture coordinates
    s.attributes[0].values[6] = 0.5;  // vertex 3: another texture coordinate, a seam
    TriangleSoup b = s;
    EXPECT_EQ(weld_soup(b), 1u);
    EXPECT_EQ(b.triangles[1], (Triangle{3, 5, 2}));
}

TEST(Attributes, RepairCopiesCarryTheAttributesOfTheirVertex) {
    // Two tetrahedra sharing vertex 0 only: repair gives vertex 0 a copy.
    TriangleSoup s;
    s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    s.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}};
    s.attributes.push_back({"quality", 1, AttributeBlend::Linear, {7, 1, 2, 3, 4, 5, 6}});
    PipelineOptions o;
    o.repair = true;
    const PipelineResult r = stripify(s, o);
    ASSERT_EQ(r.repair->copied_from, (std::vector<uint32_t>{0}));
    EXPECT_EQ(r.arrays.attributes[0].values[7], 7.0);
}

TEST(Attributes, InconsistentAttributeArraysAreRefused) {
    TriangleSoup s;
    s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    s.triangles = {{0, 1, 2}};
    s.attributes.push_back({"quality", 1, AttributeBlend::Linear, {1, 2}});
    EXPECT_THROW(stripify(s, PipelineOptions{}), InputError);
}
