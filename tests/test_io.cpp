// Readers (every format, ASCII and binary), precise read errors, writers, constraint files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "cgal_data.hpp"
#include "shell.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/validate.hpp"

namespace fs = std::filesystem;
using namespace singlestrip;

using singlestrip::test::test_data;

namespace {

// One directory per tag under a process-wide scratch directory, removed at exit.
fs::path scratch_dir(const std::string& tag) {
    static const singlestrip::test::ScratchDir root("io");
    fs::path d = root.dir / tag;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

// The tetrahedron of tests/data (see make_data.py), outward oriented.
const std::vector<Point3> kTetraPoints = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::vector<Triangle> kTetraFaces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

/// A triangle as its three corner positions, rotated so the smallest corner is first: equal for
/// the same oriented face whatever the vertex numbering.
std::array<Point3, 3> geometric(const TriangleSoup& s, const Triangle& t) {
    std::array<Point3, 3> c = {s.points[t[0]], s.points[t[1]], s.points[t[2]]};
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    return c;
}

std::string error_of(const std::string& path) {
    try {
        read_mesh_file(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST(ReadMesh, TetraInEveryFormatKeepsOrderAndOrientation) {
    TriangleSoup expected{kTetraPoints, kTetraFaces, {}};
    std::vector<std::array<Point3, 3>> want;
    for (const auto& t : kTetraFaces) want.push_back(geometric(expected, t));
    for (const char* name : {"tetra.off", "tetra.obj", "tetra_ascii.ply", "tetra_binary.ply", "tetra_ascii.stl", "tetra_binary.stl"}) {
        SCOPED_TRACE(name);
        TriangleSoup s = read_mesh_file(test_data(name));
        ASSERT_EQ(s.points.size(), 4u);
        ASSERT_EQ(s.triangles.size(), 4u);
        ASSERT_EQ(s.source_polygon.size(), 4u);
        for (uint32_t f = 0; f < 4; ++f) {
            EXPECT_EQ(geometric(s, s.triangles[f]), want[f]) << "face " << f;  // same faces, same order, same winding
            EXPECT_EQ(s.source_polygon[f], f);
        }
        const bool stl = std::string(name).find(".stl") != std::string::npos;
        if (!stl) {
            // Indexed formats keep the file's vertex numbering exactly.
            EXPECT_EQ(s.points, kTetraPoints);
            EXPECT_EQ(s.triangles, kTetraFaces);
        } else {
            // STL welding: numbered by first appearance: corners of face 0 (0,2,1) come first.
            const std::vector<Point3> first_appearance = {kTetraPoints[0], kTetraPoints[2], kTetraPoints[1], kTetraPoints[3]};
            EXPECT_EQ(s.points, first_appearance);
        }
        EXPECT_TRUE(diagnose_soup(s).empty());
    }
}

TEST(ReadMesh, BinaryPlyWrittenInTestRoundTrips) {
    // A binary PLY with float coordinates and an int list, written here byte by byte.
    fs::path dir = scratch_dir("ply");
    const std::string path = (dir / "square.ply").string();
    {
        std::ofstream o(path, std::ios::binary);
        o << "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
             "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
        const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5f}, {0, 1, 0}};
        o.write(reinterpret_cast<const char*>(v), sizeof v);
        const unsigned char n = 4;
        const int32_t idx[4] = {0, 1, 2, 3};
        o.write(reinterpret_cast<const char*>(&n), 1);
        o.write(reinterpret_cast<const char*>(idx), sizeof idx);
    }
    TriangleSoup s = read_mesh_file(path);
    ASSERT_EQ(s.points.size(), 4u);
    EXPECT_EQ(s.points[2], (Point3{1, 1, 0.5}));
    // The quad is fan-triangulated (v0, vi, vi+1).
    ASSERT_EQ(s.triangles.size(), 2u);
    EXPECT_EQ(s.triangles[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(s.triangles[1], (Triangle{0, 2, 3}));
    EXPECT_EQ(s.source_polygon, (std::vector<uint32_t>{0, 0}));
    fs::remove_all(dir);
}

TEST(ReadMesh, BinaryStlWrittenInTestWeldsExactlyEqualCorners) {
    fs::path dir = scratch_dir("stl");
    const std::string path = (dir / "two.stl").string();
    {
        std::ofstream o(path, std::ios::binary);
        char header[80] = {};
        std::memcpy(header, "binary test", 11);
        o.write(header, 80);
        const uint32_t n = 2;
        o.write(reinterpret_cast<const char*>(&n), 4);
        // Two triangles sharing the edge (1,0,0)-(0,1,0); a third corner differs only slightly.
        const float tris[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 0}};
        for (const auto& t : tris) {
            o.write(reinterpret_cast<const char*>(t), sizeof t);
            o.write("\0\0", 2);
        }
    }
    TriangleSoup s = read_mesh_file(path);
    ASSERT_EQ(s.points.size(), 4u);  // 6 corners, 2 pairs welded
    EXPECT_EQ(s.points[0], (Point3{0, 0, 0}));
    EXPECT_EQ(s.points[3], (Point3{1, 1, 0}));
    EXPECT_EQ(s.triangles[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(s.triangles[1], (Triangle{1, 3, 2}));
    EXPECT_TRUE(diagnose_soup(s).empty());
    fs::remove_all(dir);
}

TEST(ReadMesh, PolygonsAreFanTriangulatedAndUnreferencedVerticesKept) {
    for (const char* name : {"pyramid_quad.off", "pyramid_slashes.obj"}) {
        SCOPED_TRACE(name);
        TriangleSoup s = read_mesh_file(test_data(name));
        EXPECT_EQ(s.points.size(), 6u);  // vertex 5 is unused but kept
        ASSERT_EQ(s.triangles.size(), 6u);
        EXPECT_EQ(s.triangles[0], (Triangle{0, 3, 2}));
        EXPECT_EQ(s.triangles[1], (Triangle{0, 2, 1}));
        EXPECT_EQ(s.triangles[2], (Triangle{0, 1, 4}));
        EXPECT_EQ(s.triangles[4], (Triangle{2, 3, 4}));  // from negative indices in the OBJ
        EXPECT_EQ(s.source_polygon, (std::vector<uint32_t>{0, 0, 1, 2, 3, 4}));
        MeshInfo m = mesh_info(s);
        EXPECT_EQ(m.referenced_vertices, 5u);
        EXPECT_EQ(m.polygons, 5u);
        EXPECT_EQ(m.euler_characteristic, 2);
        EXPECT_TRUE(m.valid());
    }
}

struct BadCase {
    const char* file;
    std::vector<std::string> needles;  // substrings the message must contain (besides the path)
};

TEST(ReadMesh, BadInputsGivePreciseErrors) {
    const std::vector<BadCase> cases = {
        {"empty.off", {"empty file"}},
        {"blank.obj", {"empty file"}},
        {"truncated_faces.off", {"truncated OFF", "4 faces", "only 3"}},
        {"truncated_vertices.off", {"truncated OFF", "4 vertices", "only 2"}},
        {"index_out_of_range.off", {"face 2", "vertex 7", "only 4 vertices"}},
        {"index_out_of_range.obj", {"face 3", "vertex 4", "only 4 vertices"}},
        {"nan.off", {"vertex 2", "non-finite", "nan"}},
        {"inf.obj", {"vertex 3", "non-finite"}},
        {"no_faces.off", {"no faces"}},
        {"no_faces.obj", {"no faces"}},
        {"two_corner_face.off", {"face 1", "only 2 vertices"}},
        {"garbage.ply", {"not a PLY file"}},
        {"truncated_binary.ply", {"truncated PLY"}},
        {"truncated_binary.stl", {"truncated binary STL", "4 triangles"}},
        {"unknown.xyz", {"unknown input format", ".xyz"}},
        {"does_not_exist.off", {"no such file"}},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.file);
        const std::string path = test_data(c.file);
        const std::string msg = error_of(path);
        EXPECT_NE(msg.find(path), std::string::npos) << msg;
        for (const auto& n : c.needles) EXPECT_NE(msg.find(n), std::string::npos) << "missing '" << n << "' in: " << msg;
    }
}

TEST(ReadMesh, DirectoryAndUnreadableFile) {
    fs::path dir = scratch_dir("perm");
    fs::create_directories(dir / "mesh.off");
    EXPECT_NE(error_of((dir / "mesh.off").string()).find("is a directory"), std::string::npos);
    const fs::path locked = dir / "locked.off";
    fs::copy_file(test_data("tetra.off"), locked);
    fs::permissions(locked, fs::perms::none);
    if (::geteuid() != 0) {  // root can read anything
        const std::string msg = error_of(locked.string());
        EXPECT_NE(msg.find("cannot open"), std::string::npos) << msg;
        EXPECT_NE(msg.find(locked.string()), std::string::npos) << msg;
    }
    fs::permissions(locked, fs::perms::owner_all);
    fs::remove_all(dir);
}

TEST(WriteMesh, EveryFormatRoundTripsExactly) {
    fs::path dir = scratch_dir("write");
    // Coordinates that need all 17 digits, and a face order that is not sorted.
    const std::vector<Point3> pts = {{0.1, 1.0 / 3.0, -2.5e-7}, {1e10, 3.141592653589793, 0}, {-0.0, 2.0, 1.0 / 7.0}, {5, 6, 7}};
    const std::vector<Triangle> faces = {{1, 2, 3}, {0, 1, 2}, {3, 2, 0}};
    const std::vector<uint32_t> parent = {7, 0, 3};
    for (const char* ext : {".ply", ".obj", ".off", ".PLY"}) {
        SCOPED_TRACE(ext);
        const std::string path = (dir / (std::string("out") + ext)).string();
        write_strip_mesh(path, pts, faces, parent);
        TriangleSoup s = read_mesh_file(path);
        EXPECT_EQ(s.points, pts);
        EXPECT_EQ(s.triangles, faces);
    }
    // Only the outputs exist: no temporary files left behind.
    size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        EXPECT_EQ(e.path().string().find(".tmp-"), std::string::npos) << e.path();
        ++n;
    }
    EXPECT_EQ(n, 4u);
    fs::remove_all(dir);
}

TEST(WriteMesh, PlyHasBinaryLayoutWithParent) {
    fs::path dir = scratch_dir("plylayout");
    const std::string path = (dir / "o.ply").string();
    const std::vector<Point3> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    write_strip_mesh(path, pts, {{0, 1, 2}, {2, 1, 3}}, {4, 9});
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string end = "end_header\n";
    const size_t body = bytes.find(end) + end.size();
    const std::string header = bytes.substr(0, body);
    EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
    EXPECT_NE(header.find("element vertex 4"), std::string::npos);
    EXPECT_NE(header.find("property double x"), std::string::npos);
    EXPECT_NE(header.find("element face 2"), std::string::npos);
    EXPECT_NE(header.find("property list uchar uint vertex_indices"), std::string::npos);
    EXPECT_NE(header.find("property uint parent"), std::string::npos);
    ASSERT_EQ(bytes.size(), body + 4 * 24 + 2 * (1 + 12 + 4));
    const char* face1 = bytes.data() + body + 4 * 24 + 17;
    uint32_t v[3], parent;
    EXPECT_EQ(static_cast<unsigned char>(face1[0]), 3u);
    std::memcpy(v, face1 + 1, 12);
    std::memcpy(&parent, face1 + 13, 4);
    EXPECT_EQ(v[0], 2u);
    EXPECT_EQ(v[1], 1u);
    EXPECT_EQ(v[2], 3u);
    EXPECT_EQ(parent, 9u);
    fs::remove_all(dir);
}

TEST(WriteMesh, UnknownExtensionIsRequestErrorAndWritesNothing) {
    fs::path dir = scratch_dir("ext");
    const std::string path = (dir / "out.xyz").string();
    EXPECT_THROW(write_strip_mesh(path, kTetraPoints, kTetraFaces, {0, 1, 2, 3}), RequestError);
    EXPECT_THROW(output_format_for("noext"), RequestError);
    EXPECT_FALSE(fs::exists(path));
    fs::remove_all(dir);
}

TEST(WriteMesh, BinaryStlReadsBackWelded) {
    fs::path dir = scratch_dir("stl");
    const std::string path = (dir / "out.stl").string();
    write_strip_mesh(path, kTetraPoints, kTetraFaces, {0, 1, 2, 3});
    EXPECT_EQ(fs::file_size(path), 84u + 50u * kTetraFaces.size());
    const TriangleSoup back = read_mesh_file(path);
    EXPECT_EQ(back.points.size(), 4u);
    EXPECT_EQ(back.triangles.size(), kTetraFaces.size());
    fs::remove_all(dir);
}

TEST(WriteMesh, FailureLeavesNoFile) {
    fs::path dir = scratch_dir("fail");
    const std::string path = (dir / "missing_dir" / "out.ply").string();
    EXPECT_THROW(write_strip_mesh(path, kTetraPoints, kTetraFaces, {0, 1, 2, 3}), OutputError);
    EXPECT_THROW(write_indices(path + ".txt", {1, 2, 3}), OutputError);
    EXPECT_FALSE(fs::exists(dir / "missing_dir"));
    // An existing output is replaced only by a complete file.
    const std::string existing = (dir / "keep.off").string();
    write_text_atomic(existing, "old");
    EXPECT_THROW(write_strip_mesh((dir / "keep.off" / "x.off").string(), kTetraPoints, kTetraFaces, {0, 1, 2, 3}), OutputError);
    std::ifstream in(existing);
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(content, "old");
    fs::remove_all(dir);
}

TEST(WriteMesh, IndicesAreSixteenPerLine) {
    fs::path dir = scratch_dir("idx");
    const std::string path = (dir / "i.txt").string();
    std::vector<uint32_t> idx(35);
    for (uint32_t i = 0; i < idx.size(); ++i) idx[i] = 1000 - i;
    write_indices(path, idx);
    std::ifstream in(path);
    std::vector<uint32_t> back;
    std::vector<size_t> per_line;
    for (std::string line; std::getline(in, line);) {
        std::istringstream ss(line);
        size_t n = 0;
        for (uint32_t v; ss >> v; ++n) back.push_back(v);
        per_line.push_back(n);
    }
    EXPECT_EQ(back, idx);
    EXPECT_EQ(per_line, (std::vector<size_t>{16, 16, 3}));
    fs::remove_all(dir);
}

TEST(Constraints, PolylinesBecomeConsecutivePairs) {
    const auto edges = read_constraints(test_data("constraints_ok.txt"), 4);
    const std::vector<ConstraintEdge> want = {{0, 1, 2}, {1, 2, 2}, {3, 0, 4}};
    EXPECT_EQ(edges, want);
    const std::vector<std::pair<uint32_t, uint32_t>> want_pairs = {{0, 1}, {1, 2}, {3, 0}};
    EXPECT_EQ(vertex_pairs(edges), want_pairs);
}

TEST(Constraints, ErrorsNameFileAndLine) {
    auto message = [](const std::string& f, uint32_t nv) {
        try {
            read_constraints(f, nv);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    std::string m = message(test_data("constraints_bad_token.txt"), 4);
    EXPECT_NE(m.find("constraints_bad_token.txt: line 2"), std::string::npos) << m;
    EXPECT_NE(m.find("'x'"), std::string::npos) << m;
    m = message(test_data("constraints_out_of_range.txt"), 4);
    EXPECT_NE(m.find("line 3"), std::string::npos) << m;
    EXPECT_NE(m.find("vertex 4"), std::string::npos) << m;
    m = message(test_data("nope.txt"), 4);
    EXPECT_NE(m.find("nope.txt"), std::string::npos) << m;
}

TEST(ReadMeshReal, FandiskAndFormatsFromCgalDemo) {
    const std::string fandisk = test::cgal_mesh_path("fandisk.off");
    if (fandisk.empty()) GTEST_SKIP() << "libcgal-demo data not available";
    TriangleSoup s = read_mesh_file(fandisk);
    EXPECT_EQ(s.triangles.size(), 12946u);
    MeshInfo m = mesh_info(s);
    EXPECT_TRUE(m.valid());
    EXPECT_EQ(m.genus, 0);
    // The same sphere shipped as OFF, PLY and STL: the same oriented faces.
    const std::string off = test::cgal_mesh_path("sphere.off"), ply = test::cgal_mesh_path("sphere.ply"),
                      stl = test::cgal_mesh_path("sphere.stl");
    if (off.empty() || ply.empty() || stl.empty()) GTEST_SKIP();
    auto faces_of = [](const TriangleSoup& t) {
        std::multiset<std::array<Point3, 3>> f;
        for (const auto& tri : t.triangles) f.insert(geometric(t, tri));
        return f;
    };
    const TriangleSoup a = read_mesh_file(off), b = read_mesh_file(ply), c = read_mesh_file(stl);
    EXPECT_EQ(a.points.size(), b.points.size());
    EXPECT_EQ(a.triangles.size(), c.triangles.size());
    EXPECT_EQ(mesh_info(c).euler_characteristic, 2);
    EXPECT_EQ(faces_of(a), faces_of(b));
}

namespace {
std::string write_scratch(const std::string& tag, const std::string& name, const std::string& bytes) {
    const fs::path p = scratch_dir(tag) / name;
    std::ofstream(p, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return p.string();
}
const std::string kSquareVertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n";
}  // namespace

// PLY `element tristrips` (issue 18): strips separated by -1, odd triangles wound the other way
// round, triangles with a repeated vertex (the usual way to join strips) skipped.
TEST(ReadMesh, PlyTristripsAreDecodedWithAlternatingWinding) {
    const std::string header =
        "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
        "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
    // Strip 0 1 3 2 (two triangles), restart, strip 4 4 1 2: (4,4,1) is skipped, (1,4,2) is odd.
    const TriangleSoup s = read_mesh_file(write_scratch("strips", "s.ply", header + kSquareVertices + "9 0 1 3 2 -1 4 4 1 2\n"));
    const std::vector<Triangle> want = {{0, 1, 3}, {3, 1, 2}, {1, 4, 2}};
    EXPECT_EQ(s.triangles, want);
    EXPECT_EQ(s.source_polygon, (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_TRUE(diagnose_soup(s).empty());
    // Binary, uint entries: the restart is 2^32-1.
    std::string b =
        "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "element tristrips 1\nproperty list uint uint vertex_indices\nend_header\n";
    const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    b.append(reinterpret_cast<const char*>(v), sizeof v);
    const uint32_t list[6] = {5, 0, 1, 3, 0xffffffffu, 2};
    b.append(reinterpret_cast<const char*>(list), sizeof list);
    const TriangleSoup t = read_mesh_file(write_scratch("strips", "b.ply", b));
    EXPECT_EQ(t.triangles, (std::vector<Triangle>{{0, 1, 3}}));
    const std::string bad = error_of(write_scratch("strips", "bad.ply", header + kSquareVertices + "3 0 1 7\n"));
    EXPECT_NE(bad.find("tristrips item 0 entry 2 references vertex 7 but the file has only 5 vertices"), std::string::npos) << bad;
}

// Every reader names what it did not understand when it finds no faces (issue 18).
TEST(ReadMesh, NoFacesNamesTheElementsAndRecordsNotUnderstood) {
    const std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
        "element xyz 1\nproperty list int int vertex_indices\nend_header\n" +
        kSquareVertices + "3 0 1 2\n";
    std::string m = error_of(write_scratch("noface", "u.ply", ply));
    EXPECT_NE(m.find("no faces"), std::string::npos) << m;
    EXPECT_NE(m.find("element 'xyz' is not understood; faces are read from 'face' or 'tristrips'"), std::string::npos) << m;
    m = error_of(write_scratch("noface", "u.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\nfo 1 2 3\n"));
    EXPECT_NE(m.find("no faces"), std::string::npos) << m;
    EXPECT_NE(m.find("'fo' (1 line) 'l' (2 lines)"), std::string::npos) << m;
}

// Reader errors name the file's polygon, not the triangle number after fan triangulation (issue 19).
TEST(ReadMesh, ErrorsNameTheFilePolygon) {
    const std::string quads = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf 1 2 3 4\nf 1 2 9\n";
    std::string m = error_of(write_scratch("poly", "q.obj", quads));
    EXPECT_NE(m.find("line 7: face 2 references vertex 8"), std::string::npos) << m;
    m = error_of(write_scratch("poly", "q.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n4 0 1 2 3\n3 0 1 9\n"));
    EXPECT_NE(m.find("line 9: face 2 references vertex 9"), std::string::npos) << m;
}
