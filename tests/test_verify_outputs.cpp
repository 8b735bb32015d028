// Tests of the independent verifier on output files and real meshes: its own output readers
// round-trip; strips the library builds pass, and mutations of them are caught.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cgal_data.hpp"
#include "singlestrip/cycles.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/tree_cotree.hpp"
#include "singlestrip/verify.hpp"
#include "verify_cases.hpp"

namespace ss = singlestrip;
using ss::Point3;
using ss::Triangle;
using namespace ss::testing;  // verify_cases.hpp: the report helpers, quad(), split_quad()

namespace {

// The first face from index `start` on (cyclically) with no vertex on a boundary edge.
size_t interior_face_from(const std::vector<Triangle>& faces, size_t start) {
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    for (const Triangle& t : faces)
        for (int k = 0; k < 3; ++k) edges.emplace_back(std::minmax(t[k], t[(k + 1) % 3]));
    std::sort(edges.begin(), edges.end());
    std::vector<uint8_t> on_boundary;
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        if (j - i == 1)
            for (uint32_t w : {edges[i].first, edges[i].second}) {
                if (w >= on_boundary.size()) on_boundary.resize(w + 1, 0);
                on_boundary[w] = 1;
            }
        i = j;
    }
    auto inner = [&](uint32_t w) { return w >= on_boundary.size() || !on_boundary[w]; };
    for (size_t n = 0; n < faces.size(); ++n) {
        const size_t f = (start + n) % faces.size();
        if (inner(faces[f][0]) && inner(faces[f][1]) && inner(faces[f][2])) return f;
    }
    return start;
}

// --- output readers ---------------------------------------------------------------------------

class VerifyFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() / ("ss_verify_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                                         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    static void write(const std::string& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }
    std::filesystem::path dir_;
};

template <class T>
void put_le(std::string& s, T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + sizeof(T));
    s.append(b, sizeof(T));
}

std::string binary_ply(const std::vector<Point3>& pts, const std::vector<Triangle>& faces, const std::vector<uint32_t>& parent) {
    std::string s = "ply\nformat binary_little_endian 1.0\ncomment test\nelement vertex " + std::to_string(pts.size()) +
                    "\nproperty double x\nproperty double y\nproperty double z\nelement face " + std::to_string(faces.size()) +
                    "\nproperty list uchar uint vertex_indices\nproperty uint parent\nend_header\n";
    for (const auto& p : pts)
        for (double c : p) put_le(s, c);
    for (size_t f = 0; f < faces.size(); ++f) {
        put_le<uint8_t>(s, 3);
        for (uint32_t v : faces[f]) put_le(s, v);
        put_le(s, parent[f]);
    }
    return s;
}

TEST_F(VerifyFiles, BinaryPlyRoundTrip) {
    const auto in = split_quad();
    write(path("o.ply"), binary_ply(in.out_points, in.out_faces, in.out_parent));
    const auto m = ss::read_output_mesh(path("o.ply"));
    EXPECT_EQ(m.points, in.out_points);
    EXPECT_EQ(m.faces, in.out_faces);
    EXPECT_EQ(m.parent, in.out_parent);
}

TEST_F(VerifyFiles, AsciiPlyObjOffRoundTrip) {
    const auto in = split_quad();
    write(path("a.ply"),
          "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
          "property uchar red\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
          "0 0 0 1\n1 0 0 1\n1 1 0 1\n0 1 0 1\n0.5 0.5 0 1\n3 0 1 4\n3 4 1 2\n3 4 2 3\n3 0 4 3\n");
    auto m = ss::read_output_mesh(path("a.ply"));
    EXPECT_EQ(m.points, in.out_points);
    EXPECT_EQ(m.faces, in.out_faces);
    EXPECT_TRUE(m.parent.empty());

    write(path("o.obj"),
          "# test\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 0\nvn 0 0 1\n"
          "f 1 2 5\nf 5/1/1 2//1 3\nf -1 -3 -2\ng x\nf 1 5 4\n");
    m = ss::read_output_mesh(path("o.obj"));
    EXPECT_EQ(m.points, in.out_points);
    EXPECT_EQ(m.faces, in.out_faces);

    write(path("o.off"), "OFF\n# c\n5 4 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0\n3 0 1 4\n3 4 1 2\n3 4 2 3\n3 0 4 3\n");
    m = ss::read_output_mesh(path("o.off"));
    EXPECT_EQ(m.points, in.out_points);
    EXPECT_EQ(m.faces, in.out_faces);
}

TEST_F(VerifyFiles, MalformedOutputsGiveInputError) {
    const auto in = split_quad();
    std::string ply = binary_ply(in.out_points, in.out_faces, in.out_parent);
    write(path("t.ply"), ply.substr(0, ply.size() - 7));
    EXPECT_THROW(ss::read_output_mesh(path("t.ply")), ss::InputError);
    write(path("q.off"), "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
    EXPECT_THROW(ss::read_output_mesh(path("q.off")), ss::InputError);
    write(path("r.obj"), "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 4\n");
    EXPECT_THROW(ss::read_output_mesh(path("r.obj")), ss::InputError);
    write(path("n.off"), "OFF\n3 1 0\n0 0 nan\n1 0 0\n1 1 0\n3 0 1 2\n");
    EXPECT_THROW(ss::read_output_mesh(path("n.off")), ss::InputError);
    EXPECT_THROW(ss::read_output_mesh(path("missing.ply")), ss::InputError);
    write(path("x.stl"), "solid x\n");
    EXPECT_THROW(ss::read_output_mesh(path("x.stl")), ss::InputError);
    try {
        ss::read_output_mesh(path("r.obj"));
    } catch (const ss::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("r.obj"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("face 0"), std::string::npos);
    }
}

TEST_F(VerifyFiles, VerifyFilesEndToEnd) {
    const auto in = split_quad();
    write(path("in.off"), "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
    write(path("out.ply"), binary_ply(in.out_points, in.out_faces, in.out_parent));
    write(path("idx.txt"), "0 1 4 2\n4 3 0\n");
    write(path("cyc.json"), "{\"cycles\": []}");
    write(path("con.txt"), "# boundary walls\n0 1 2\n");
    ss::VerifyFileOptions opt;
    opt.indices_path = path("idx.txt");
    opt.cycles_path = path("cyc.json");
    opt.constraints_path = path("con.txt");
    opt.source = 1;
    opt.target = 0;
    auto r = ss::verify_files(path("in.off"), path("out.ply"), opt);
    EXPECT_TRUE(r.ok()) << joined(r);

    // The same output as OBJ: parents inferred.
    write(path("out.obj"), "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 0\nf 1 2 5\nf 5 2 3\nf 5 3 4\nf 1 5 4\n");
    r = ss::verify_files(path("in.off"), path("out.obj"), opt);
    EXPECT_TRUE(r.ok()) << joined(r);

    write(path("idx.txt"), "0 1 4 2 3 0\n");
    r = ss::verify_files(path("in.off"), path("out.obj"), opt);
    EXPECT_TRUE(has_failure(r, "indices")) << joined(r);

    write(path("bad.json"), "{\"cycles\": [[1, -2]]}");
    opt.cycles_path = path("bad.json");
    EXPECT_THROW(ss::verify_files(path("in.off"), path("out.obj"), opt), ss::InputError);
}
// --- real meshes: strips built by the library pass; mutations of them are caught -----------

struct RealCase {
    const char* file;
    long long genus;
    size_t loops;
};

class VerifyReal : public ::testing::TestWithParam<RealCase> {};

TEST_P(VerifyReal, BuiltStripPassesAndMutationsAreCaught) {
    const RealCase rc = GetParam();
    const std::string path = ss::test::cgal_mesh_path(rc.file);
    if (path.empty()) GTEST_SKIP() << "libcgal-demo data not available";
    const ss::TriangleSoup soup = ss::read_mesh_file(path);
    const ss::StripResult res = ss::build_strip(ss::Mesh::from_soup(soup));
    const ss::StripArrays arr = ss::strip_arrays(res);

    ss::VerifyInput in;
    in.in_points = soup.points;
    in.in_faces = soup.triangles;
    in.out_points = arr.points;
    in.out_faces = arr.faces;
    in.out_parent = arr.parent;
    in.cycles = ss::tree_cotree_cycles(res).cycles;  // a basis built by other code
    const auto r = ss::verify(in);
    ASSERT_TRUE(r.ok()) << rc.file << "\n" << joined(r);
    EXPECT_EQ(r.genus, rc.genus);
    EXPECT_EQ(r.boundary_loops, rc.loops);
    const size_t dim = static_cast<size_t>(2 * rc.genus + (rc.loops ? static_cast<long long>(rc.loops) - 1 : 0));
    EXPECT_EQ(r.cycle_rank, dim);

    // Parents inferred geometrically give the same verdict.
    {
        auto v = in;
        v.out_parent.clear();
        const auto rv = ss::verify(v);
        EXPECT_TRUE(rv.ok()) << joined(rv);
    }
    const size_t F = in.out_faces.size();
    const size_t mid = F / 2;
    {  // two consecutive faces swapped
        auto v = in;
        std::swap(v.out_faces[mid], v.out_faces[mid + 1]);
        std::swap(v.out_parent[mid], v.out_parent[mid + 1]);
        v.cycles.reset();
        EXPECT_TRUE(has_failure_prefix(ss::verify(v), "strip")) << rc.file;
    }
    {  // a face dropped: one away from the boundary (dropping a face with one boundary edge keeps
       // the topology)
        auto v = in;
        const auto drop = static_cast<long>(interior_face_from(in.out_faces, mid));
        v.out_faces.erase(v.out_faces.begin() + drop);
        v.out_parent.erase(v.out_parent.begin() + drop);
        v.cycles.reset();
        const auto rv = ss::verify(v);
        EXPECT_TRUE(has_failure_prefix(rv, "coverage")) << rc.file << joined(rv);
        EXPECT_TRUE(has_failure_prefix(rv, "topology")) << rc.file << joined(rv);
    }
    if (in.out_points.size() > in.in_points.size()) {  // an inserted midpoint moved along the surface normal
        auto v = in;
        v.cycles.reset();
        Point3& p = v.out_points.back();
        p[0] += 1e-3;
        p[1] += 2e-3;
        p[2] -= 1e-3;
        EXPECT_TRUE(has_failure_prefix(ss::verify(v), "geometry")) << rc.file;
    }
    {  // a face flipped
        auto v = in;
        v.cycles.reset();
        std::swap(v.out_faces[mid][0], v.out_faces[mid][1]);
        const auto rv = ss::verify(v);
        EXPECT_TRUE(has_failure(rv, "orientation", "face " + std::to_string(mid))) << rc.file << joined(rv);
    }
    if (dim >= 2) {  // one cycle replaced by a copy of another: rank deficit
        auto v = in;
        (*v.cycles)[1] = (*v.cycles)[0];
        const auto rv = ss::verify(v);
        EXPECT_TRUE(has_failure(rv, "cycles", "not linearly independent")) << rc.file << joined(rv);
        EXPECT_EQ(rv.cycle_rank, dim - 1);
    }
    if (dim >= 1) {  // one cycle missing
        auto v = in;
        v.cycles->pop_back();
        EXPECT_TRUE(has_failure(ss::verify(v), "cycles", "expected 2g+h-1")) << rc.file;
    }
}

INSTANTIATE_TEST_SUITE_P(Real, VerifyReal,
                         ::testing::Values(RealCase{"head.off", 0, 3}, RealCase{"eight.off", 2, 0},
                                           RealCase{"elephant-with-holes.off", 3, 106}, RealCase{"cheese.off", 133, 0}),
                         [](const auto& param_info) {
                             std::string n = param_info.param.file;
                             n = n.substr(0, n.find('.'));
                             std::replace(n.begin(), n.end(), '-', '_');
                             return n;
                         });

}  // namespace
