// Vertex attributes (issue 18, item 3): OBJ vt/vn with their own index streams (seams become
// boundaries, so the picture is unchanged), PLY vertex properties, glTF attributes into other
// formats; midpoints blended; every output format writes what it holds; verify accepts them.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
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

using singlestrip::test::test_data;

namespace {

/// Reading `path` must throw InputError whose message contains `fragment`.
void expect_refused(const std::string& path, const std::string& fragment) {
    try {
        read_mesh_file(path);
        ADD_FAILURE() << path << " accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

struct Scratch : singlestrip::test::ScratchDir {
    explicit Scratch(const std::string& tag) : ScratchDir("attrs-" + tag) {}
};

/// Exit code and merged output of the CLI.
singlestrip::test::ShellRun cli(const std::string& args) {
    return singlestrip::test::run_program(SINGLESTRIP_CLI_PATH, args);
}

/// `strip IN -o OUT`, then `verify IN OUT`, through the CLI; both must succeed. Returns the strip
/// command's output (its notes).
std::string strip_and_verify_cli(const std::string& in, const std::string& out) {
    const auto [code, text] = cli("strip '" + in + "' -o '" + out + "'");
    EXPECT_EQ(code, 0) << text;
    const auto [vcode, vtext] = cli("verify '" + in + "' '" + out + "'");
    EXPECT_EQ(vcode, 0) << vtext;
    return text;
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
    const TriangleSoup s = read_mesh_file(test_data("sphere_uv.obj"));
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
    const TriangleSoup s = read_mesh_file(test_data("sphere_uv.obj"));
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
    const std::string in = test_data("sphere_uv.obj");
    const PipelineResult r = stripify(read_mesh_file(in), PipelineOptions{});
    for (const char* name : {"o.obj", "o.ply", "o.glb", "o.gltf", "o.off"}) {
        SCOPED_TRACE(name);
        const std::string out = dir / name;
        const std::string text = strip_and_verify_cli(in, out);
        EXPECT_EQ(text.find("has no place"), std::string::npos) << text;
        const TriangleSoup back = is_gltf_path(out) ? read_gltf_output(out) : read_mesh_file(out);
        ASSERT_EQ(back.points.size(), r.arrays.points.size());
        for (const char* attr : {"TEXCOORD_0", "NORMAL"}) {
            const VertexAttribute* got = find_attribute(back.attributes, attr);
            const VertexAttribute* want = find_attribute(r.arrays.attributes, attr);
            ASSERT_TRUE(got && want) << attr;
            ASSERT_EQ(got->values.size(), want->values.size()) << attr;
            const bool text_file = std::string(name) == "o.obj" || std::string(name) == "o.off";
            const double tol = text_file ? 0 : 1e-6;  // float32 in PLY and glTF
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
        expect_refused(path, path + ": " + c.message);
        EXPECT_EQ(cli("strip '" + path + "' -o '" + dir / "o.ply'").code, 3);  // bad input (docs)
    }
    write_file(dir / "vt.obj", "v 0 0 0\nvt 0 nan\n");
    EXPECT_THROW(read_mesh_file(dir / "vt.obj"), InputError);
}

TEST(ObjAttributes, AStreamOnlySomeCornersHaveIsNotKept) {
    // tests/data/pyramid_slashes.obj mixes "i", "i/t", "i//n" and "i/t/n" corners.
    const TriangleSoup s = read_mesh_file(test_data("pyramid_slashes.obj"));
    EXPECT_TRUE(s.attributes.empty());
    EXPECT_EQ(s.points.size(), 6u);
}

TEST(ObjAttributes, VertexColoursAreKeptAndFollowTheSeams) {
    Scratch dir("colours");
    std::ifstream in(test_data("sphere_uv.obj"));
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
    const std::string in = test_data("sphere_attrs.ply");
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
        strip_and_verify_cli(in, out);
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
    expect_refused(dir / "nan.ply", "vertex 0: property 'nx' is not finite");
}

TEST(GltfAttributes, SceneIntoPlyAndObjKeepsItsAttributes) {
    Scratch dir("gltf");
    const std::string in = test_data("scene.glb");
    const TriangleSoup s = read_gltf_soup(in);
    ASSERT_NE(find_attribute(s.attributes, "TEXCOORD_0"), nullptr);
    ASSERT_NE(find_attribute(s.attributes, "NORMAL"), nullptr);
    for (const char* name : {"o.ply", "o.obj"}) {
        SCOPED_TRACE(name);
        const std::string out = dir / name;
        strip_and_verify_cli(in, out);
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

namespace {

/// A 5 x 5 grid as [ST][C][N]OFF: unit normals leaning outwards, byte colours (alpha on every
/// other vertex), texture coordinates x / 5, y / 5. The grid needs midpoint splits.
std::string grid_off(bool normals, bool colours, bool textures) {
    std::string s = std::string(textures ? "ST" : "") + (colours ? "C" : "") + (normals ? "N" : "") + "OFF\n36 50 0\n";
    for (int y = 0; y <= 5; ++y)
        for (int x = 0; x <= 5; ++x) {
            const double nx = x - 2.5, ny = y - 2.5, len = std::sqrt(nx * nx + ny * ny + 9);
            s += std::to_string(x) + " " + std::to_string(y) + " 0";
            if (normals) s += " " + std::to_string(nx / len) + " " + std::to_string(ny / len) + " " + std::to_string(3 / len);
            if (colours) s += " " + std::to_string(40 * x) + " " + std::to_string(40 * y) + " 7" + ((x + y) % 2 ? " 128" : "");
            if (textures) s += " " + std::to_string(x / 5.0) + " " + std::to_string(y / 5.0);
            s += "\n";
        }
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 5; ++x) {
            const int a = y * 6 + x;
            s += "3 " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + 7) + "\n";
            s += "3 " + std::to_string(a) + " " + std::to_string(a + 7) + " " + std::to_string(a + 6) + "\n";
        }
    return s;
}

}  // namespace

TEST(OffAttributes, NormalsColoursAndTextureCoordinatesAreKept) {
    Scratch dir("off");
    write_file(dir / "g.off", grid_off(true, true, true));
    const TriangleSoup s = read_mesh_file(dir / "g.off");
    std::vector<std::string> names;
    for (const auto& a : s.attributes) names.push_back(a.name);
    ASSERT_EQ(names, (std::vector<std::string>{"NORMAL", "COLOR_0", "TEXCOORD_0"}));  // the PLY reader's names and order
    const VertexAttribute &n = s.attributes[0], &c = s.attributes[1], &t = s.attributes[2];
    EXPECT_EQ(n.blend, AttributeBlend::Unit);
    EXPECT_NEAR(n.values[2], 3 / std::sqrt(2.5 * 2.5 * 2 + 9), 1e-6);
    ASSERT_EQ(c.components, 4u);                        // some vertices have alpha
    EXPECT_DOUBLE_EQ(c.values[4 * 7 + 0], 40.0 / 255);  // vertex 7 = (1, 1): bytes scaled to [0, 1]
    EXPECT_DOUBLE_EQ(c.values[4 * 7 + 2], 7.0 / 255);
    EXPECT_DOUBLE_EQ(c.values[4 * 7 + 3], 1.0);          // no alpha: opaque
    EXPECT_DOUBLE_EQ(c.values[4 * 1 + 3], 128.0 / 255);  // vertex 1 has alpha 128
    EXPECT_DOUBLE_EQ(t.values[2 * 7 + 0], 0.2);

    const PipelineResult r = stripify(s, PipelineOptions{});
    ASSERT_GT(r.strip.stats.splits, 0u);
    expect_midpoints_blended(r);
}

TEST(OffAttributes, EachVariantKeepsWhatItHoldsAndRefusesAWrongCount) {
    Scratch dir("offvariants");
    for (int mask = 0; mask < 8; ++mask) {
        const bool nrm = mask & 1, col = mask & 2, tex = mask & 4;
        SCOPED_TRACE(mask);
        write_file(dir / "g.off", grid_off(nrm, col, tex));
        const TriangleSoup s = read_mesh_file(dir / "g.off");
        EXPECT_EQ(s.attributes.size(), size_t{nrm} + col + tex);
        EXPECT_EQ(find_attribute(s.attributes, "NORMAL") != nullptr, nrm);
        EXPECT_EQ(find_attribute(s.attributes, "COLOR_0") != nullptr, col);
        EXPECT_EQ(find_attribute(s.attributes, "TEXCOORD_0") != nullptr, tex);
    }
    // Fractions stay as they are; in a file with an integer colour above 1, the all-integer
    // colours are bytes ("0 0 1" is 1/255 there, 1.0 in a file of fractions).
    write_file(dir / "f.off", "COFF\n3 1 0\n0 0 0 0.5 0.25 1\n1 0 0 0 0 1\n0 1 0 1 1 1\n3 0 1 2\n");
    EXPECT_EQ(read_mesh_file(dir / "f.off").attributes[0].values, (std::vector<double>{0.5, 0.25, 1, 0, 0, 1, 1, 1, 1}));
    write_file(dir / "b.off", "COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0 0 0 1\n0 1 0 0.5 0.5 0.5\n3 0 1 2\n");
    const std::vector<double> b = read_mesh_file(dir / "b.off").attributes[0].values;
    EXPECT_EQ(b, (std::vector<double>{1, 0, 0, 0, 0, 1.0 / 255, 0.5, 0.5, 0.5}));
    write_file(dir / "short.off", "STOFF\n3 1 0\n0 0 0 0.5\n1 0 0 0 0\n0 1 0 1 1\n3 0 1 2\n");
    expect_refused(dir / "short.off", "line 3: vertex 0 has 4 numbers; a STOFF vertex needs 3 plus 2 texture coordinates");
    write_file(dir / "4.off", "4OFF\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n");
    EXPECT_THROW(read_mesh_file(dir / "4.off"), InputError);
}

TEST(OffAttributes, BinaryNoffKeepsItsNormalsAndBinaryStoffIsRefusedByName) {
    Scratch dir("offbinary");
    auto be32 = [](std::string& s, uint32_t u) {
        for (int k = 3; k >= 0; --k) s += static_cast<char>((u >> (8 * k)) & 0xff);
    };
    auto body = [&](std::string s) {
        for (uint32_t c : {3u, 1u, 0u}) be32(s, c);
        for (float x : {0.f, 0.f, 0.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 0.6f, 0.f, 0.8f, 0.f, 1.f, 0.f, 0.f, 0.6f, 0.8f}) {
            uint32_t u;
            std::memcpy(&u, &x, 4);
            be32(s, u);
        }
        for (uint32_t v : {3u, 0u, 1u, 2u}) be32(s, v);
        return s;
    };
    write_file(dir / "n.off", body("NOFF BINARY\n"));
    const TriangleSoup s = read_mesh_file(dir / "n.off");
    ASSERT_EQ(s.attributes.size(), 1u);
    EXPECT_EQ(s.attributes[0].name, "NORMAL");
    EXPECT_EQ(s.attributes[0].values, (std::vector<double>{0, 0, 1, 0.6f, 0, 0.8f, 0, 0.6f, 0.8f}));
    EXPECT_EQ(s.points[1], (Point3{1, 0, 0}));
    write_file(dir / "st.off", body("STNOFF BINARY\n"));
    expect_refused(dir / "st.off", "texture coordinates in a binary OFF");
}

TEST(OffAttributes, OffOutputWritesThemBackAndVerifies) {
    Scratch dir("offout");
    const std::string in = dir / "g.off";
    write_file(in, grid_off(true, true, true));
    const PipelineResult r = stripify(read_mesh_file(in), PipelineOptions{});
    const std::string out = dir / "o.off";
    const auto [code, text] = cli("strip '" + in + "' -o '" + out + "'");
    ASSERT_EQ(code, 0) << text;
    EXPECT_EQ(text.find("has no place"), std::string::npos) << text;
    const TriangleSoup back = read_mesh_file(out);
    ASSERT_EQ(back.attributes.size(), 3u);
    for (size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(back.attributes[i].name, r.arrays.attributes[i].name);
        EXPECT_EQ(back.attributes[i].values, r.arrays.attributes[i].values) << back.attributes[i].name;  // shortest round-trip text
    }
    const auto [vcode, vtext] = cli("verify '" + in + "' '" + out + "'");
    EXPECT_EQ(vcode, 0) << vtext;
}

namespace {

/// The output's attributes as verify() reads them from a float64 file.
std::vector<OutputAttribute> as_output(const std::vector<VertexAttribute>& attrs) {
    std::vector<OutputAttribute> out;
    for (const VertexAttribute& a : attrs) out.push_back({a.name, a.components, a.values});
    return out;
}

bool has_line(const std::vector<std::string>& lines, const std::vector<std::string>& parts) {
    for (const std::string& l : lines) {
        bool all = true;
        for (const std::string& p : parts) all = all && l.find(p) != std::string::npos;
        if (all) return true;
    }
    return false;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
}

}  // namespace

TEST(VerifyAttributes, RealOutputsPassAndSayWhatWasChecked) {
    Scratch dir("verifyreal");
    const std::string in = test_data("sphere_attrs.ply");
    const struct {
        const char* name;
        const char* checked;
    } cases[] = {{"o.ply", "NORMAL (float32), COLOR_0 (8-bit), TEXCOORD_0 (float32), quality (double), id (integer)"},
                 {"o.obj", "NORMAL (decimal text), COLOR_0 (decimal text), TEXCOORD_0 (decimal text)"},
                 {"o.off", "NORMAL (decimal text), COLOR_0 (decimal text), TEXCOORD_0 (decimal text)"},
                 {"o.glb",
                  "NORMAL (glTF, float32 tolerance), COLOR_0 (glTF, float32 tolerance), TEXCOORD_0 (glTF, float32 tolerance), "
                  "quality (glTF, float32 tolerance), id (glTF, float32 tolerance)"}};
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        const auto [code, text] = cli("strip '" + in + "' -o '" + (dir / c.name) + "'");
        ASSERT_EQ(code, 0) << text;
        const VerifyReport rep = verify_files(in, dir / c.name);
        EXPECT_TRUE(rep.ok()) << rep.to_string();
        EXPECT_TRUE(has_line(rep.notes, {"attributes checked at every output vertex: ", c.checked})) << joined(rep.notes);
    }
    // OBJ cannot hold the custom ones: noted, not failed.
    EXPECT_TRUE(has_line(verify_files(in, dir / "o.obj").notes, {"the input's quality is not in the output"}));
}

TEST(VerifyAttributes, AMutatedOutputFailsNamingVertexAttributeAndValues) {
    Scratch dir("verifymut");
    const std::string in = dir / "g.off";
    write_file(in, grid_off(true, true, true));
    const TriangleSoup s = read_mesh_file(in);
    const PipelineResult r = stripify(s, PipelineOptions{});
    const size_t n = s.points.size();
    ASSERT_GT(r.arrays.points.size(), n);
    auto verify_with = [&](const std::function<void(StripArrays&)>& mutate) {
        StripArrays a = r.arrays;
        mutate(a);
        const std::string out = dir / "o.off";
        write_strip_mesh(out, a.points, a.faces, a.parent, a.attributes);
        return verify_files(in, out);
    };
    const VerifyReport good = verify_with([](StripArrays&) {});
    EXPECT_TRUE(good.ok()) << good.to_string();
    // A midpoint's texture coordinate moved a little: the failure names the vertex, the
    // attribute, both values, the parent's corners and the tolerance.
    const VerifyReport mid = verify_with([&](StripArrays& a) { a.attributes[2].values[2 * n] += 1e-6; });
    EXPECT_FALSE(mid.ok());
    EXPECT_TRUE(
        has_line(mid.failures, {"attributes: vertex " + std::to_string(n) + " TEXCOORD_0 = (", "expected (", "the blend of parent face ",
                                "weights (0.5, 0.5, 0)", "within 1e-09 + 1e-09 * |expected| (decimal text in the output)"}))
        << joined(mid.failures);
    // An input vertex's normal turned: it must keep the input's.
    const VerifyReport orig =
        verify_with([&](StripArrays& a) { std::swap(a.attributes[0].values[3 * 4], a.attributes[0].values[3 * 4 + 1]); });
    EXPECT_TRUE(has_line(orig.failures, {"attributes: vertex 4 NORMAL = (", "input vertex 4's"})) << joined(orig.failures);
    // A midpoint's normal not renormalised (the plain average of two unit vectors is shorter).
    const VerifyReport unit = verify_with([&](StripArrays& a) {
        double* m = &a.attributes[0].values[3 * n];
        for (int c = 0; c < 3; ++c) m[c] *= 0.99;
    });
    EXPECT_TRUE(has_line(unit.failures, {"vertex " + std::to_string(n) + " NORMAL", "renormalised"})) << joined(unit.failures);
    // A colour out by more than the text tolerance.
    const VerifyReport colour = verify_with([&](StripArrays& a) { a.attributes[1].values[4 * (n + 1)] += 0.01; });
    EXPECT_TRUE(has_line(colour.failures, {"vertex " + std::to_string(n + 1) + " COLOR_0"})) << joined(colour.failures);
}

TEST(VerifyAttributes, NearestAttributesTakeOneEndpointsValues) {
    const TriangleSoup s = read_mesh_file(test_data("sphere_attrs.ply"));
    const PipelineResult r = stripify(s, PipelineOptions{});
    VerifyInput vi = verify_input(r.input, r.arrays, r.indices);
    vi.in_attributes = r.input.attributes;
    vi.out_attributes = as_output(r.arrays.attributes);
    const VerifyReport good = verify(vi);
    EXPECT_TRUE(good.ok()) << good.to_string();
    const size_t n = s.points.size(), id = 4;  // "id": integers, copied from a corner
    ASSERT_EQ(vi.out_attributes[id].name, "id");
    ASSERT_GT(r.arrays.points.size(), n);
    vi.out_attributes[id].values[n] = 0.5 * (vi.out_attributes[id].values[n] + 1e6);  // no corner has it
    const VerifyReport bad = verify(vi);
    EXPECT_TRUE(has_line(bad.failures, {"attributes: vertex " + std::to_string(n) + " id = (", "one of the largest-weight corners'"}))
        << bad.to_string();
    // Every midpoint copied from its edge's other end passes too: both ends weigh 0.5.
    vi.out_attributes = as_output(r.arrays.attributes);
    size_t swapped = 0;
    std::vector<char> done(r.arrays.points.size(), 0);
    for (size_t f = 0; f < r.arrays.faces.size(); ++f)
        for (uint32_t m : r.arrays.faces[f]) {
            if (m < n || done[m]) continue;
            done[m] = 1;
            const Triangle& t = r.input.triangles[r.arrays.parent[f]];
            for (int e = 0; e < 3; ++e) {
                const uint32_t a = t[e], b = t[(e + 1) % 3];
                bool halfway = true;
                for (int d = 0; d < 3; ++d) halfway = halfway && r.arrays.points[m][d] == (r.input.points[a][d] + r.input.points[b][d]) / 2;
                const double va = s.attributes[id].values[a], vb = s.attributes[id].values[b];
                if (!halfway || va == vb) continue;
                double& got = vi.out_attributes[id].values[m];
                got = got == va ? vb : va;
                ++swapped;
            }
        }
    EXPECT_GT(swapped, 0u);
    const VerifyReport other = verify(vi);
    EXPECT_TRUE(other.ok()) << other.to_string();
}
