// Resource limits of read_mesh_file (issue 7, point 4): files whose declared counts are absurd for
// their size must be refused with InputError (naming the file) before anything is allocated for
// them or looped over. Many cases come from CGAL's readers (used until 2026-12); the strict
// readers must still refuse them. Each case runs in a forked child whose address space is capped at 512 MiB
// (RLIMIT_AS), so an attempted huge allocation shows up as a failure (bad_alloc or a kill), not as
// a pass; alarm() there is a hang guard only, not a timing assertion. Valid variants of the same
// formats (binary OFF, big-endian PLY, 32-bit list counts, colours, comments) must still be read.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "shell.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SINGLESTRIP_TEST_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define SINGLESTRIP_TEST_ASAN 1
#endif

using namespace singlestrip;
namespace fs = std::filesystem;

namespace {

// Removed at exit (the forked readers leave by _exit, which runs no destructor).
const fs::path& scratch() {
    static const singlestrip::test::ScratchDir dir("read-limits");
    return dir.dir;
}

std::string write_file(const std::string& bytes, const std::string& ext) {
    static int counter = 0;
    const fs::path p = scratch() / ("case" + std::to_string(counter++) + ext);
    std::ofstream(p, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return p.string();
}

/// Reads `bytes` (as a file with extension `ext`) in a forked child limited to 512 MiB of address
/// space. Returns "" when read_mesh_file threw InputError whose message starts with the path and
/// contains every needle; otherwise what happened.
std::string refused_path(const std::string& path, const std::vector<std::string>& needles = {}) {
    const fs::path msg_file = path + ".msg";
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
#ifndef SINGLESTRIP_TEST_ASAN
        const rlimit lim{rlim_t{512} << 20, rlim_t{512} << 20};
        setrlimit(RLIMIT_AS, &lim);
#endif
        alarm(120);  // hang guard only
        int code = 0;
        try {
            (void)read_mesh_file(path);
            code = 10;
        } catch (const InputError& e) {
            std::ofstream(msg_file) << e.what();
            code = 0;
        } catch (const std::bad_alloc&) {
            code = 11;
        } catch (...) {
            code = 12;
        }
        _exit(code);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    if (WIFSIGNALED(st)) return WTERMSIG(st) == SIGALRM ? "hang (killed after 120 s)" : "killed by signal " + std::to_string(WTERMSIG(st));
    switch (WEXITSTATUS(st)) {
        case 0:
            break;
        case 10:
            return "accepted";
        case 11:
            return "bad_alloc (tried to allocate beyond 512 MiB)";
        case 12:
            return "threw something other than InputError";
        default:
            return "child exit " + std::to_string(WEXITSTATUS(st));
    }
    std::ifstream in(msg_file);
    const std::string msg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (msg.rfind(path + ": ", 0) != 0) return "message does not start with the path: " + msg;
    for (const auto& n : needles)
        if (msg.find(n) == std::string::npos) return "message lacks '" + n + "': " + msg;
    return {};
}

std::string refused(const std::string& bytes, const std::string& ext, const std::vector<std::string>& needles = {}) {
    return refused_path(write_file(bytes, ext), needles);
}

/// A named pipe `name` in the scratch directory with a thread writing `bytes` into it once.
struct Pipe {
    std::string path;
    std::thread writer;
    Pipe(const std::string& name, std::string bytes) : path((scratch() / name).string()) {
        fs::remove(path);
        EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0);
        writer = std::thread([p = path, b = std::move(bytes)] {
            std::ofstream(p, std::ios::binary).write(b.data(), static_cast<std::streamsize>(b.size()));
        });
    }
    ~Pipe() {
        writer.join();
        fs::remove(path);
    }
};

/// Reads `bytes` in-process (they are small and valid) and returns the number of triangles.
size_t triangles_of(const std::string& bytes, const std::string& ext) {
    return read_mesh_file(write_file(bytes, ext)).triangles.size();
}

std::string ply_header(const std::string& format, const std::string& nv, const std::string& nf, const std::string& list = "uchar int") {
    return "ply\nformat " + format + " 1.0\nelement vertex " + nv +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " + nf + "\nproperty list " + list +
           " vertex_indices\nend_header\n";
}

template <class T>
void append(std::string& s, T v) {
    s.append(reinterpret_cast<const char*>(&v), sizeof v);  // little-endian host (x86-64, aarch64)
}

void append_be32(std::string& s, uint32_t v) {
    for (int k = 3; k >= 0; --k) s.push_back(static_cast<char>(v >> (8 * k) & 0xff));
}

std::string binary_stl(uint32_t declared, size_t real) {
    std::string s(80, '\0');
    append(s, declared);
    s.append(50 * real, '\0');
    return s;
}

const std::string kTriangleOff = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";

}  // namespace

// ---- OFF ---------------------------------------------------------------------------------------

TEST(ReadLimits, OffHeaderCountsAreBoundedByTheFileSize) {
    EXPECT_EQ(refused("OFF\n100000000 100000000 0\n", ".off", {"100000000"}), "");
    EXPECT_EQ(refused("OFF\n3 100000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", ".off", {"truncated OFF", "100000000 faces"}), "");
    EXPECT_EQ(refused("OFF\n2000000000 1 0\n", ".off"), "");
    EXPECT_EQ(refused("OFF\n1000000000000 1 0\n", ".off"), "");  // overflows CGAL's int
    EXPECT_EQ(refused("# comment\nOFF # more\n# and more\n100000000 1 0\n", ".off"), "");
}

TEST(ReadLimits, OffFaceCornerCountIsBoundedByItsLine) {
    EXPECT_EQ(refused(kTriangleOff + "300000000 0 1 2\n", ".off", {"face 0", "300000000"}), "");
    EXPECT_EQ(refused(kTriangleOff + "2147483647 0 1 2\n", ".off", {"face 0"}), "");
    EXPECT_EQ(refused(kTriangleOff + "1e14 0 1 2\n", ".off", {"face 0"}), "");
    EXPECT_EQ(refused(kTriangleOff + "-3 0 1 2\n", ".off", {"face 0", "-3"}), "");
    EXPECT_EQ(refused(kTriangleOff + "nan 0 1 2\n", ".off", {"face 0"}), "");
    EXPECT_EQ(refused(kTriangleOff + "3 0 1 # 2 hidden by a comment\n", ".off", {"face 0", "declares 3 vertices but lists 2"}), "");
    // Negative and non-integral indices (CGAL casts a negative double to size_t: undefined).
    EXPECT_EQ(refused(kTriangleOff + "3 0 -1 2\n", ".off", {"face 0", "-1"}), "");
    EXPECT_EQ(refused(kTriangleOff + "3 0 1e300 2\n", ".off", {"face 0"}), "");
}

TEST(ReadLimits, BinaryOffCountsAreBounded) {
    auto header = [](uint32_t nv, uint32_t nf) {
        std::string s = "OFF BINARY\n";
        append_be32(s, nv);
        append_be32(s, nf);
        append_be32(s, 0);
        return s;
    };
    EXPECT_EQ(refused(header(100000000, 100000000), ".off", {"binary OFF"}), "");
    std::string s = header(3, 1);
    for (float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) {
        uint32_t u;
        std::memcpy(&u, &c, 4);
        append_be32(s, u);
    }
    std::string ok = s;
    for (uint32_t v : {3u, 0u, 1u, 2u}) append_be32(ok, v);
    EXPECT_EQ(triangles_of(ok, ".off"), 1u);  // the valid binary file still reads
    std::string huge = s;
    for (uint32_t v : {0x7fffffffu, 0u, 1u, 2u}) append_be32(huge, v);
    EXPECT_EQ(refused(huge, ".off", {"face 0", "2147483647"}), "");
    std::string negative = s;
    for (uint32_t v : {0xffffffffu, 0u, 1u, 2u}) append_be32(negative, v);
    EXPECT_EQ(refused(negative, ".off", {"face 0"}), "");
}

TEST(ReadLimits, ValidOffVariantsStillRead) {
    EXPECT_EQ(triangles_of("# c\nOFF\n# c\n4 2 0\n\n0 0 0\n1 0 0 # c\n1 1 0\n0 1 0\n# c\n3 0 1 2\n\n4 0 2 3 1 # quad\n", ".off"), 3u);
    EXPECT_EQ(triangles_of("COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2 128 128 128 255\n", ".off"), 1u);
    EXPECT_EQ(triangles_of("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2", ".off"), 1u);  // no final newline
    EXPECT_EQ(triangles_of("OFF\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n", ".off"), 1u);
}

// CGAL converts COFF colours to unsigned char (or a colour-map index) unchecked and, after one
// coloured face, reads a colour for every later face without looking at the line (F16).
TEST(ReadLimits, OffColoursCgalCannotConvertAreRefused) {
    const std::string v = "COFF\n4 2 0\n";
    const std::string rest = "1 0 0 0 255 0\n0 1 0 0 0 255\n1 1 0 9 9 9\n";
    const std::string faces = "3 0 1 2\n3 1 3 2\n";
    EXPECT_EQ(triangles_of(v + "0 0 0 255 0 0\n" + rest + faces, ".off"), 2u);
    EXPECT_EQ(triangles_of(v + "0 0 0 0.5 1 0\n" + rest + faces, ".off"), 2u);  // fractions
    EXPECT_EQ(refused(v + "0 0 0 256 0 0\n" + rest + faces, ".off", {"vertex 0", "256"}), "");
    EXPECT_EQ(refused(v + "0 0 0 -1 0 0\n" + rest + faces, ".off", {"vertex 0", "-1"}), "");
    EXPECT_EQ(refused(v + "0 0 0 200 0.5 0\n" + rest + faces, ".off", {"vertex 0", "200"}), "");  // read as fractions
    EXPECT_EQ(refused(v + "0 0 0 1 0 5.5e23\n" + rest + faces, ".off", {"vertex 0", "5.5e+23"}), "");
    EXPECT_EQ(refused(v + "0 0 0 nan 0 0\n" + rest + faces, ".off", {"vertex 0", "nan"}), "");
    const std::string vs = v + "0 0 0 1 2 3\n" + rest;
    EXPECT_EQ(triangles_of(vs + "3 0 1 2 7\n3 1 3 2 0.5 0.5 0.5 1\n", ".off"), 2u);  // index, then rgba
    EXPECT_EQ(triangles_of(vs + "3 0 1 2\n3 1 3 2 10 20 30\n", ".off"), 2u);         // colour only later
    EXPECT_EQ(refused(vs + "3 0 1 2 -5\n3 1 3 2 1\n", ".off", {"face 0", "colour-map index -5"}), "");
    EXPECT_EQ(refused(vs + "3 0 1 2 1e12\n3 1 3 2 1\n", ".off", {"face 0", "colour-map index"}), "");
    EXPECT_EQ(refused(vs + "3 0 1 2 5 5\n3 1 3 2\n", ".off", {"face 0", "2 colour numbers"}), "");
    EXPECT_EQ(refused(vs + "3 0 1 2 300 0 0\n3 1 3 2 1 1 1\n", ".off", {"face 0", "300"}), "");
    // A face without a colour after a coloured one is valid OFF (CGAL's sticky colour flag refused it).
    EXPECT_EQ(triangles_of(vs + "3 0 1 2 1 1 1\n3 1 3 2\n", ".off"), 2u);
    EXPECT_EQ(refused(vs + "3 0 1 2 1 x 1\n3 1 3 2\n", ".off", {"face 0", "bad colour number 'x'"}), "");
    // Plain OFF: CGAL ignores numbers after a face's indices, and so do we.
    EXPECT_EQ(triangles_of("OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2 -5 1e30\n3 1 3 2\n", ".off"), 2u);
}

// CGAL's stream reads a line's numbers until the first it cannot parse ("nan", "inf", "+-0"),
// then indexes colours as if all were there (F17: vertex colours, F18: face colours; found by
// code audit after F16). Only plain decimal numbers pass the pre-scan.
TEST(ReadLimits, OffNumbersCgalCannotParseAreRefused) {
    const std::string v = "COFF\n4 2 0\n";
    const std::string rest = "1 0 0 0 255 0\n0 1 0 0 0 255\n1 1 0 9 9 9\n";
    const std::string faces = "3 0 1 2\n3 1 3 2\n";
    EXPECT_EQ(refused(v + "nan 0 0 255 0 0\n" + rest + faces, ".off", {"vertex 0", "'nan'"}), "");
    EXPECT_EQ(refused(v + "0 0 inf 255 0 0\n" + rest + faces, ".off", {"vertex 0", "'inf'"}), "");
    EXPECT_EQ(refused(v + "0 +-0 0 255 0 0\n" + rest + faces, ".off", {"vertex 0", "'+-0'"}), "");
    EXPECT_EQ(refused(v + "0 0 0 255 0 0 infinity\n" + rest + faces, ".off", {"vertex 0", "'infinity'"}), "");
    EXPECT_EQ(
        refused("CNOFF\n3 1 0\n0 0 0 nan 0 1 255 0 0\n1 0 0 0 0 1 0 255 0\n0 1 0 0 0 1 0 0 255\n3 0 1 2\n", ".off", {"vertex 0", "'nan'"}),
        "");
    const std::string vs = v + "0 0 0 1 2 3 1e30\n" + rest;
    EXPECT_EQ(refused(vs + "3 0 1 2 1 1 +-0\n3 1 3 2\n", ".off", {"face 0", "'+-0'"}), "");
    EXPECT_EQ(refused(vs + "3 0 1 2 5\n3 1 3 2 +-0\n", ".off", {"face 1", "'+-0'"}), "");
    EXPECT_EQ(refused(vs + "3 0 1 2 NaN 1 1\n3 1 3 2\n", ".off", {"face 0", "'NaN'"}), "");
    EXPECT_EQ(refused(vs + "3 0 1 2 0x1 1 1\n3 1 3 2\n", ".off", {"face 0", "'0x1'"}), "");
    // Every decimal spelling the stream reads still passes: signs, leading dot, trailing dot, exponents.
    EXPECT_EQ(triangles_of(v + "+0 -0. .0 1. +.5 5E-1\n" + rest + "3 0 1 2 1e0 2E+0 0003\n3 1 3 2 -0 0 0.\n", ".off"), 2u);
    // An underflow the stream reads as 0 passes too; an overflow it fails on does not.
    EXPECT_EQ(triangles_of(v + "1e-400 0 -2e-324 0 0 0\n" + rest + faces, ".off"), 2u);
    EXPECT_EQ(refused(v + "1e400 0 0 0 0 0\n" + rest + faces, ".off", {"vertex 0", "'1e400'"}), "");
}

// Binary NOFF and CNOFF faces are walked like binary OFF's (F19, code audit): the pre-scan used
// to stop at the vertices, so CGAL resized a face to a corner count of 2^31-1.
TEST(ReadLimits, BinaryOffWithNormalsFaceCountsAreBounded) {
    for (const std::string kw : {"NOFF", "CNOFF"}) {
        SCOPED_TRACE(kw);
        std::string s = kw + " BINARY\n";
        for (uint32_t c : {3u, 1u, 0u}) append_be32(s, c);
        for (float c : {0.f, 0.f, 0.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 0.f, 0.f, 1.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f}) {
            uint32_t u;
            std::memcpy(&u, &c, 4);
            append_be32(s, u);
        }
        std::string ok = s;
        for (uint32_t v : {3u, 0u, 1u, 2u}) append_be32(ok, v);
        EXPECT_EQ(triangles_of(ok, ".off"), 1u);
        for (uint32_t k : {0x7fffffffu, 300000000u, 0xffffffffu}) {
            std::string bad = s;
            for (uint32_t v : {k, 0u, 1u, 2u}) append_be32(bad, v);
            EXPECT_EQ(refused(bad, ".off", {"face 0"}), "");
        }
    }
}

// ---- PLY ---------------------------------------------------------------------------------------

TEST(ReadLimits, PlyAbsurdElementCountsAreRefused) {
    EXPECT_EQ(refused(ply_header("ascii", "1000000000000", "1"), ".ply"), "");
    EXPECT_EQ(refused(ply_header("binary_little_endian", "1000000000000", "1"), ".ply"), "");
    EXPECT_EQ(refused(ply_header("binary_little_endian", "100000000", "100000000") + std::string(64, '\0'), ".ply"), "");
    EXPECT_EQ(refused(ply_header("binary_big_endian", "3", "100000000") + std::string(36 + 64, '\0'), ".ply"), "");
    EXPECT_EQ(refused(ply_header("ascii", "-1", "1"), ".ply", {"bad count", "vertex"}), "");
}

TEST(ReadLimits, PlyElementWithoutPropertiesIsRefusedNotLoopedOver) {
    EXPECT_EQ(refused("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                      "element face 1\nproperty list uchar int vertex_indices\nelement foo 1000000000000\nend_header\n"
                      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                      ".ply", {"element 'foo'", "no properties"}),
              "");
    // A property of an unknown type: its size is unknown, so the element cannot be walked.
    EXPECT_EQ(refused("ply\nformat binary_little_endian 1.0\nelement junk 1000000000000\nproperty quaternion q\nend_header\n", ".ply",
                      {"element 'junk'", "unknown type 'quaternion'"}),
              "");
}

TEST(ReadLimits, PlyPropertyBeforeElementIsRefusedNotCrashed) {
    EXPECT_EQ(refused("ply\nformat binary_little_endian 1.0\nproperty float x\nelement vertex 0\nend_header\n", ".ply",
                      {"'property' before any 'element'"}),
              "");
    EXPECT_EQ(
        refused("ply\nformat ascii 1.0\nproperty list uchar int vertex_indices\nend_header\n", ".ply", {"'property' before any 'element'"}),
        "");
}

TEST(ReadLimits, PlyPropertyTypesCgalCannotConvertAreRefusedNotCrashed) {
    // CGAL looks coordinates up as float/double and halfedge ends as uint, through a null pointer
    // when the file's type differs.
    EXPECT_EQ(refused("ply\nformat ascii 1.0\nelement vertex 3\nproperty int x\nproperty float y\nproperty float z\nelement face 1\n"
                      "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                      ".ply", {"'x'", "int"}),
              "");
    EXPECT_EQ(
        refused("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty list uchar float z\nelement face 1\n"
                "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 1 0\n3 0 1 2\n",
                ".ply", {"'z'"}),
        "");
    // Elements other than vertices and faces are skipped whatever their types (CGAL needed uint halfedge ends).
    EXPECT_EQ(
        triangles_of("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
                     "property list uchar int vertex_indices\nelement halfedge 1\nproperty int source\nproperty int target\nend_header\n"
                     "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n0 1\n",
                     ".ply"),
        1u);
}

// CGAL turns colours on when red|r, green|g and blue|b each exist as uchar, then fetches one
// spelling as uchar whatever its type: a null dereference (F20, code audit).
TEST(ReadLimits, PlyColourPropertiesOfMixedTypesAreRefused) {
    auto ply = [](const std::string& element, const std::string& props, const std::string& vertex_extra, const std::string& face_extra) {
        const bool v = element == "vertex";
        return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n" +
               (v ? props : std::string()) + "element face 1\nproperty list uchar int vertex_indices\n" + (v ? std::string() : props) +
               "end_header\n0 0 0" + vertex_extra + "\n1 0 0" + vertex_extra + "\n0 1 0" + vertex_extra + "\n3 0 1 2" + face_extra + "\n";
    };
    const std::string mixed = "property uchar red\nproperty float green\nproperty uchar g\nproperty uchar blue\n";
    // Colours are not read, so colour properties of mixed types are valid PLY and read (CGAL crashed on them).
    EXPECT_EQ(triangles_of(ply("vertex", mixed, " 1 0.5 2 3", ""), ".ply"), 1u);
    EXPECT_EQ(
        triangles_of(ply("face", "property uchar red\nproperty uchar green\nproperty float blue\nproperty uchar b\n", "", " 1 2 0.5 3"),
                     ".ply"),
        1u);
    EXPECT_EQ(triangles_of(ply("vertex", "property uchar r\nproperty uchar green\nproperty float g\nproperty uchar b\n", " 1 2 0.5 3", ""),
                           ".ply"),
              1u);
    // Colours CGAL reads, and float colours it ignores, still read.
    EXPECT_EQ(triangles_of(ply("vertex", "property uchar red\nproperty uchar green\nproperty uchar blue\n", " 1 2 3", ""), ".ply"), 1u);
    EXPECT_EQ(triangles_of(ply("face", "property uchar r\nproperty uchar g\nproperty uchar b\n", "", " 1 2 3"), ".ply"), 1u);
    EXPECT_EQ(triangles_of(ply("vertex", "property float red\nproperty float green\nproperty float blue\n", " 0.1 0.2 0.3", ""), ".ply"),
              1u);
    EXPECT_EQ(
        triangles_of(ply("vertex", "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty float r\n", " 1 2 3 0.5", ""),
                     ".ply"),
        1u);
}

TEST(ReadLimits, BinaryPlyListCountsAreBoundedByTheRemainingBytes) {
    const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    for (const std::string list : {"uint int", "int int", "uint uint"}) {
        SCOPED_TRACE(list);
        std::string s = ply_header("binary_little_endian", "3", "1", list);
        s.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
        append(s, uint32_t{0x7fffffffu});
        s.append(12, '\0');
        EXPECT_EQ(refused(s, ".ply", {"element 'face'", "list 'vertex_indices'", "2147483647"}), "");
    }
    // A negative signed count (CGAL would cast it to size_t).
    std::string s = ply_header("binary_little_endian", "3", "1", "int int");
    s.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
    append(s, int32_t{-1});
    s.append(12, '\0');
    EXPECT_EQ(refused(s, ".ply", {"negative"}), "");
    // Big endian: the count 2^31-1 written most significant byte first.
    std::string be = ply_header("binary_big_endian", "3", "1", "uint int");
    be.append(36, '\0');
    append_be32(be, 0x7fffffffu);
    be.append(12, '\0');
    EXPECT_EQ(refused(be, ".ply", {"2147483647"}), "");
}

TEST(ReadLimits, AsciiPlyWideListCountsAreBounded) {
    const std::string body = "0 0 0\n1 0 0\n0 1 0\n";
    EXPECT_EQ(
        refused(ply_header("ascii", "3", "1", "int int") + body + "2000000000 0 1 2\n", ".ply", {"list 'vertex_indices'", "2000000000"}),
        "");
    EXPECT_EQ(refused(ply_header("ascii", "3", "1", "uint int") + body + "4294967295 0 1 2\n", ".ply", {"list 'vertex_indices'"}), "");
    EXPECT_EQ(refused(ply_header("ascii", "3", "1", "int int") + body + "-5 0 1 2\n", ".ply", {"list 'vertex_indices'"}), "");
}

// Every ASCII body is walked, whatever its count types: CGAL leaves a count or number it reads
// past the end uninitialised and uses it, and wraps a narrow count (a uchar 259 reads 3 entries).
TEST(ReadLimits, AsciiPlyNarrowListCountsAndTruncationAreRefused) {
    const std::string body = "0 0 0\n1 0 0\n0 1 0\n";
    EXPECT_EQ(refused(ply_header("ascii", "3", "1", "uchar int") + body, ".ply", {"truncated PLY"}), "");
    EXPECT_EQ(refused(ply_header("ascii", "3", "1", "ushort int") + body + "3 0 1", ".ply", {"truncated PLY", "element 'face'"}), "");
    EXPECT_EQ(refused(ply_header("ascii", "3", "1", "ushort int") + "0 0 0\n1 0 0\n0 1\n", ".ply", {"truncated PLY"}), "");
    EXPECT_EQ(refused(ply_header("ascii", "3", "1", "uchar int") + body + "259 0 1 2\n", ".ply", {"out of range", "'259'"}), "");
    EXPECT_EQ(refused(ply_header("ascii", "3", "1", "char int") + body + "200 0 1 2\n", ".ply", {"out of range", "'200'"}), "");
    EXPECT_EQ(refused(ply_header("ascii", "3", "1", "short int") + body + "-1 0 1 2\n", ".ply", {"bad count"}), "");
    EXPECT_EQ(refused(ply_header("ascii", "3", "1", "uchar int") + body + "3 0 1 2.5\n", ".ply", {"cannot parse"}), "");
    EXPECT_EQ(refused(ply_header("ascii", "3", "1", "uchar int") + "0 0 nan\n1 0 0\n0 1 0\n3 0 1 2\n", ".ply", {"cannot parse", "'nan'"}),
              "");
    // Counts at the top of their range, trailing data after the last element, CRLF: still read.
    EXPECT_EQ(triangles_of(ply_header("ascii", "3", "1", "ushort int") + body + "3 0 1 2\nextra bytes\n", ".ply"), 1u);
    EXPECT_EQ(triangles_of(ply_header("ascii", "3", "1", "char int") + "0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n", ".ply"), 1u);
}

TEST(ReadLimits, ValidPlyVariantsStillRead) {
    const std::string body = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n4 0 2 3 1\n";
    for (const std::string list : {"uchar int", "int int", "uint uint", "ushort int", "char int"}) {
        SCOPED_TRACE(list);
        EXPECT_EQ(triangles_of(ply_header("ascii", "4", "2", list) + body, ".ply"), 3u);
    }
    // Binary big endian with an extra per-face property after the list, and an extra element.
    std::string s =
        "ply\nformat binary_big_endian 1.0\ncomment x\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uint int vertex_indices\nproperty uchar flags\nelement extra 2\nproperty short a\nend_header\n";
    s.append(36, '\0');
    for (uint32_t v : {3u, 0u, 1u, 2u}) append_be32(s, v);
    s.push_back('\x07');
    s.append(4, '\0');
    // Coordinates are all zero here: the soup is degenerate but readable.
    EXPECT_EQ(triangles_of(s, ".ply"), 1u);
}

// ---- STL and OBJ -------------------------------------------------------------------------------

TEST(ReadLimits, BinaryStlTriangleCountIsBoundedByTheFileSize) {
    EXPECT_EQ(refused(binary_stl(1000000000u, 1), ".stl", {"truncated binary STL", "1000000000 triangles"}), "");
    EXPECT_EQ(refused(binary_stl(0xffffffffu, 0), ".stl", {"truncated binary STL"}), "");
}

TEST(ReadLimits, ObjHugeFaceLinesAreHarmless) {
    // CGAL's OBJ reader grows a face as it reads its indices: a long or absurd face line costs
    // memory proportional to the line only.
    EXPECT_EQ(refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 1000000000000\n", ".obj", {"face 0"}), "");
    // An unreadable token is refused, not taken as the end of the face.
    EXPECT_EQ(refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3 x 4\n", ".obj", {"face 0", "'x'"}), "");
    // A tab separates references like a space (CGAL swallowed the reference after it).
    EXPECT_EQ(triangles_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\t4\n", ".obj"), 2u);
    // (vt and vn references must name records that exist: tests/test_attributes.cpp.)
    EXPECT_EQ(
        triangles_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvn 0 0 1\nvn 0 0 1\nf 1/1/1  2//2 3 # c\t\nf -1 -2 -3\t\r\n", ".obj"),
        2u);
    std::string longline = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf";
    for (int i = 0; i < 200000; ++i) longline += " 1 2 3";
    longline += "\n";
    EXPECT_EQ(triangles_of(longline, ".obj"), 599998u);
}

// ---- the fuzz reproducers (fuzz/repro, written by the fuzz work) ---------------------------------

TEST(ReadLimits, FuzzReproducersAreCleanInputErrors) {
    const fs::path dir = fs::path(SINGLESTRIP_SOURCE_DIR) / "fuzz" / "repro";
    if (!fs::exists(dir)) GTEST_SKIP() << "no fuzz/repro";
    for (const char* name :
         {"off_huge_counts.off", "off_huge_face_corner_count.off", "off_negative_index_ub.off", "ply_element_without_properties_hang.ply",
          "ply_huge_list_count.ply", "ply_property_before_element.ply", "ply_int_coordinate.ply"}) {
        SCOPED_TRACE(name);
        const fs::path p = dir / name;
        if (!fs::exists(p)) continue;
        std::ifstream in(p, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_EQ(refused(bytes, p.extension().string()), "");
    }
}

// ---- Every format: the bytes are read once (F22) ------------------------------------------------

// CGAL used to reopen the path: a pipe looked empty to the pre-scan (which could not seek it) and
// then gave CGAL its real bytes unchecked (F1's crash again); a device never ended.
TEST(ReadLimits, PipesAreReadOnceAndDevicesAreRefused) {
    {
        Pipe pipe("f1.ply", "ply\nformat ascii 1.0\nproperty float x\nelement vertex 3\nend_header\n");
        EXPECT_EQ(refused_path(pipe.path, {"'property' before any 'element'"}), "");
    }
    {
        Pipe pipe("ok.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
        EXPECT_EQ(read_mesh_file(pipe.path).triangles.size(), 1u);
    }
    const fs::path device = scratch() / "random.stl";
    fs::create_symlink("/dev/urandom", device);
    EXPECT_EQ(refused_path(device.string(), {"not a regular file"}), "");
}

ReadOptions limited_to(std::uint64_t max_input_bytes) {
    ReadOptions o;
    o.max_input_bytes = max_input_bytes;
    return o;
}

// The whole input is held in memory once: a file or a pipe longer than the limit is refused, a
// pipe as soon as the limit is passed (a writer that never stops must not fill the memory).
TEST(ReadLimits, InputsLargerThanTheLimitAreRefused) {
    const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    const std::string path = write_file(off, ".off");
    EXPECT_EQ(read_mesh_file(path, limited_to(off.size())).triangles.size(), 1u);
    try {
        (void)read_mesh_file(path, limited_to(off.size() - 1));
        ADD_FAILURE() << "a file one byte over the limit was read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("larger than the input limit of " + std::to_string(off.size() - 1) + " bytes"),
                  std::string::npos)
            << e.what();
    }
    std::signal(SIGPIPE, SIG_IGN);  // the writer is left with a closed pipe: EPIPE, not a signal
    std::string endless = off + "# ";
    endless.append(std::size_t{8} << 20, 'x');
    Pipe pipe("long.off", endless);
    try {
        (void)read_mesh_file(pipe.path, limited_to(std::uint64_t{1} << 20));
        ADD_FAILURE() << "a pipe over the limit was read";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(pipe.path, 0), 0u) << e.what();
        EXPECT_NE(std::string(e.what()).find("larger than the input limit"), std::string::npos) << e.what();
    }
}

// ReadOptions::format reads a file whatever its name: a pipe, /dev/stdin, no extension.
TEST(ReadLimits, FormatCanBeNamedInsteadOfTheExtension) {
    const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    ReadOptions as_off;
    as_off.format = "OFF";
    EXPECT_EQ(read_mesh_file(write_file(off, ".txt"), as_off).triangles.size(), 1u);
    {
        Pipe pipe("stdin_like", off);
        EXPECT_EQ(read_mesh_file(pipe.path, as_off).triangles.size(), 1u);
    }
    EXPECT_EQ(refused(off, ".txt", {"unknown input format '.txt'"}), "");
    ReadOptions as_obj;
    as_obj.format = "obj";  // an OFF file read as OBJ has no 'v' or 'f' records
    EXPECT_THROW((void)read_mesh_file(write_file(off, ".off"), as_obj), InputError);
    ReadOptions bogus;
    bogus.format = "3ds";
    try {
        (void)read_mesh_file(write_file(off, ".off"), bogus);
        ADD_FAILURE() << "an unknown format name was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown input format '3ds'"), std::string::npos) << e.what();
    }
}

// ---- STL: CGAL's own ASCII/binary fallback, made clean ------------------------------------------

namespace {
std::string binary_stl_of(const std::string& header80, const std::vector<std::array<float, 9>>& triangles) {
    std::string s = header80;
    s.resize(80, ' ');
    append(s, static_cast<uint32_t>(triangles.size()));
    for (const auto& t : triangles) {
        for (int k = 0; k < 3; ++k) append(s, 0.f);
        for (float c : t) append(s, c);
        s.append(2, '\0');
    }
    return s;
}
const std::vector<std::array<float, 9>> kTetra = {
    {0, 0, 0, 0, 1, 0, 1, 0, 0}, {0, 0, 0, 1, 0, 0, 0, 0, 1}, {0, 0, 0, 0, 0, 1, 0, 1, 0}, {1, 0, 0, 0, 1, 0, 0, 0, 1}};
}  // namespace

// CGAL's binary parser merges vertices in a std::map, where NaN equals everything (F23).
TEST(ReadLimits, StlBinaryNonFiniteVerticesAreRefused) {
    EXPECT_EQ(triangles_of(binary_stl_of("tetra", kTetra), ".stl"), 4u);
    auto bad = kTetra;
    bad[2][6] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(refused(binary_stl_of("tetra", bad), ".stl", {"triangle 2", "vertex 2", "non-finite"}), "");
    bad = kTetra;
    bad[0][0] = std::numeric_limits<float>::infinity();
    EXPECT_EQ(refused(binary_stl_of("solid but binary", bad), ".stl", {"triangle 0", "non-finite"}), "");
}

// CGAL kept the points of a failed ASCII attempt when it then read the file as binary (F24):
// a binary file whose header starts with "solid" and holds "vertex" words got their points.
TEST(ReadLimits, StlFailedAsciiAttemptLeavesNothingBehind) {
    const std::string header = "solid t\nfacet\nvertex 7 7 7\nvertex 8 8 8\nvertex 9 9 9\nvertex 6 6 6\n";
    const TriangleSoup soup = read_mesh_file(write_file(binary_stl_of(header, kTetra), ".stl"));
    ASSERT_EQ(soup.triangles.size(), 4u);
    ASSERT_EQ(soup.points.size(), 4u);
    for (const auto& p : soup.points)
        for (double c : p) EXPECT_TRUE(c == 0 || c == 1) << "a point from the header text was kept";
    // A truncated binary file is not read as text; ASCII files CGAL misses as ASCII still are.
    std::string truncated = binary_stl_of("x", kTetra);
    truncated.resize(84 + 50);  // one of the four triangles, then text: still short of 284 bytes
    truncated += "facet normal 0 0 1 outer loop vertex 0 0 0 vertex 1 0 0 vertex 0 1 0 endloop endfacet endsolid";
    EXPECT_EQ(refused(truncated, ".stl", {"truncated binary STL"}), "");
    const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n";
    EXPECT_EQ(triangles_of("solid\tname\n" + facet, ".stl"), 1u);
    EXPECT_EQ(triangles_of("\xEF\xBB\xBFsolid name\n" + facet, ".stl"), 1u);
}

// ---- OBJ and PLY: files CGAL reads as something else -------------------------------------------

// CGAL reads an index, then skips to the next space: "3#x 4" is read as corners 3 and 4 (F25).
TEST(ReadLimits, ObjCommentGluedToAnIndexIsRefused) {
    const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
    EXPECT_EQ(refused(v + "f 1 2 3#x 4\n", ".obj", {"line 5", "face 0", "'#'"}), "");
    EXPECT_EQ(refused(v + "f 1 2/#/ 3\n", ".obj", {"'#'"}), "");
    EXPECT_EQ(triangles_of(v + "f 1 2 3#comment\n", ".obj"), 1u);  // nothing after it: same face either way
    EXPECT_EQ(triangles_of(v + "f 1 2 3 # a 4\n", ".obj"), 1u);    // a separate '#' ends CGAL's face too
}

// diagnose_ply summed header counts in a long long (F26, UBSan: signed overflow).
TEST(ReadLimits, PlyHeaderCountsThatOverflowASumAreRefused) {
    const std::string mesh =
        "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\n";
    std::string h = "ply\nformat ascii 1.0\n" + mesh;
    for (int i = 0; i < 10; ++i) h += "element e" + std::to_string(i) + " 999999999999999999\nproperty float a\n";
    EXPECT_EQ(refused(h + "end_header\n1 2 3 4\n", ".ply", {"truncated PLY"}), "");
    std::string b = "ply\nformat binary_little_endian 1.0\n" + mesh;
    for (int i = 0; i < 10; ++i) b += "element e" + std::to_string(i) + " 999999999999999999\nproperty double a\n";
    EXPECT_EQ(refused(b + "end_header\n12345678", ".ply", {"truncated PLY"}), "");
}

// A few bytes per item on disk became a point or a polygon each in CGAL's arrays (F27); those
// items are refused first. CGAL uses only the first property of a name, so later namesakes of
// another type are not refused (they were, wrongly).
TEST(ReadLimits, PlyItemsCgalWouldStoreUselesslyAreRefused) {
    std::string v =
        "ply\nformat binary_little_endian 1.0\nelement vertex 1000\nproperty uchar q\nelement face 0\nproperty list uchar int "
        "vertex_indices\nend_header\n";
    EXPECT_EQ(refused(v + std::string(1000, '\0'), ".ply", {"element 'vertex'", "no property 'x'"}), "");
    std::string f = ply_header("binary_little_endian", "3", "1000");
    f.append(36, '\0');
    EXPECT_EQ(refused(f + std::string(1000, '\0'), ".ply", {"face 0", "0 vertices"}), "");
    const std::string body = "0 0 0\n1 0 0\n0 1 0\n";
    EXPECT_EQ(refused(ply_header("ascii", "3", "2") + body + "3 0 1 2\n2 0 1\n", ".ply", {"face 1", "2 vertices"}), "");
    EXPECT_EQ(refused(ply_header("ascii", "3", "1", "uchar float") + body + "3 0 1 2\n", ".ply", {"no 'vertex_indices'", "int or uint"}),
              "");
    // vertex_index is read when vertex_indices is not an int list; later namesakes are ignored.
    EXPECT_EQ(
        triangles_of(
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nproperty list uchar float x\n"
            "element face 1\nproperty list uchar int vertex_index\nend_header\n0 0 0 1 5\n1 0 0 0\n0 1 0 0\n3 0 1 2\n",
            ".ply"),
        1u);
    EXPECT_EQ(
        triangles_of(
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
            "property list uchar int vertex_indices\nelement halfedge 1\nproperty uint source\nproperty uint target\nproperty int source\n"
            "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n0 1 -1\n",
            ".ply"),
        1u);
}
