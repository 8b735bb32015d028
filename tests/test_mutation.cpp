// Hostile input (issue 7): every prefix and a deterministic set of single-byte mutations of every
// sample mesh in tests/data must give a clean InputError or a soup that the whole pipeline turns
// into a strip that passes verify() (fuzz/check_pipeline.hpp) — never a crash or another
// exception. Headers that declare absurd counts must be refused without allocating for them
// (checked with a global operator new that records the largest request) and without hanging
// (each case runs in a forked child with an alarm as a hang guard).
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "../fuzz/check_pipeline.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"

// ---- allocation probe: the largest single request since reset; huge requests fail at once -----
namespace {
std::atomic<size_t> g_largest_request{0};
constexpr size_t kRefuseAbove = size_t{1} << 30;  // never really allocate more than 1 GiB
void* probe_alloc(size_t n) {
    size_t prev = g_largest_request.load(std::memory_order_relaxed);
    while (n > prev && !g_largest_request.compare_exchange_weak(prev, n, std::memory_order_relaxed)) {
    }
    if (n > kRefuseAbove) throw std::bad_alloc();
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
}  // namespace
void* operator new(size_t n) {
    return probe_alloc(n);
}
void* operator new[](size_t n) {
    return probe_alloc(n);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, size_t) noexcept {
    std::free(p);
}
// The nothrow forms too (std::stable_sort's buffer): else the sanitizer's operator new pairs with
// the free() above (alloc-dealloc mismatch).
void* operator new(size_t n, const std::nothrow_t&) noexcept {
    try {
        return probe_alloc(n);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](size_t n, const std::nothrow_t&) noexcept {
    try {
        return probe_alloc(n);
    } catch (...) {
        return nullptr;
    }
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}

using namespace singlestrip;
namespace fs = std::filesystem;

namespace {

fs::path data_dir() {
    return fs::path(SINGLESTRIP_SOURCE_DIR) / "tests" / "data";
}

fs::path scratch_dir() {
    static const fs::path dir = [] {
        fs::path base = fs::exists("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
        fs::path d = base / ("singlestrip_mutation_" + std::to_string(getpid()));
        fs::create_directories(d);
        return d;
    }();
    return dir;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string write_case(const std::string& bytes, const std::string& ext) {
    const fs::path p = scratch_dir() / ("case" + ext);
    std::ofstream(p, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return p.string();
}

std::vector<fs::path> sample_meshes() {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(data_dir())) {
        std::string ext = e.path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl") out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

struct Tally {
    size_t cases = 0, refused = 0, stripped = 0;
    std::vector<std::string> failures;
    void fail(const std::string& what) {
        if (failures.size() < 20)
            failures.push_back(what);
        else if (failures.size() == 20)
            failures.push_back("(more failures not shown)");
    }
};

/// With SINGLESTRIP_MUTATION_LOG=<file> every case's outcome is written there, one line each
/// ("label<TAB>refused<TAB>message" or "label<TAB>stripped"), to compare the readers of two builds.
std::FILE* outcome_log() {
    static std::FILE* log = [] {
        const char* path = std::getenv("SINGLESTRIP_MUTATION_LOG");
        return path ? std::fopen(path, "a") : nullptr;
    }();
    return log;
}

/// Reads `path` as a mesh; "" when read_mesh_file threw InputError naming the file or the soup
/// passed the checked pipeline (refused or stripped and verified), else what went wrong.
std::string check_file(const std::string& path, const std::string& label, Tally& t) {
    TriangleSoup soup;
    try {
        soup = read_mesh_file(path);
    } catch (const InputError& e) {
        ++t.refused;
        if (std::FILE* log = outcome_log())
            std::fprintf(log, "%s\trefused\t%s\n", label.c_str(), e.what() + std::min(path.size(), std::strlen(e.what())));
        if (std::string(e.what()).rfind(path, 0) != 0) return label + ": InputError does not name the file: " + e.what();
        return {};
    } catch (const std::exception& e) {
        return label + ": read_mesh_file threw a non-InputError: " + e.what();
    }
    if (auto p = fuzzcheck::check_soup(soup); !p.empty()) return label + ": " + p;
    fuzzcheck::Outcome outcome;
    // --repair must turn every readable soup into verified strips (or refuse it for no faces).
    fuzzcheck::Request repaired;
    repaired.repair = true;
    repaired.cycles = false;
    if (auto p = fuzzcheck::check_pipeline(soup, repaired, &outcome); !p.empty()) return label + " (--repair): " + p;
    if (auto p = fuzzcheck::check_pipeline(std::move(soup), {}, &outcome); !p.empty()) return label + ": " + p;
    ++(outcome == fuzzcheck::Outcome::Stripped ? t.stripped : t.refused);
    if (std::FILE* log = outcome_log())
        std::fprintf(log, "%s\t%s\n", label.c_str(), outcome == fuzzcheck::Outcome::Stripped ? "stripped" : "refused\t(pipeline)");
    return {};
}

/// One case: the bytes as a file with extension `ext`.
void run_case(const std::string& bytes, const std::string& ext, const std::string& label, Tally& t) {
    ++t.cases;
    if (auto p = check_file(write_case(bytes, ext), label, t); !p.empty()) t.fail(p);
}

void report(const Tally& t) {
    std::printf("  %zu cases: %zu refused with InputError/RequestError, %zu stripped and verified\n", t.cases, t.refused, t.stripped);
    for (const auto& f : t.failures) ADD_FAILURE() << f;
}

}  // namespace

TEST(Mutation, EveryPrefixOfEverySampleIsRefusedOrVerified) {
    const auto files = sample_meshes();
    ASSERT_GE(files.size(), 6u) << "tests/data should hold a sample file per format";
    Tally t;
    for (const auto& f : files) {
        const std::string bytes = slurp(f);
        for (size_t n = 0; n <= bytes.size(); ++n)
            run_case(bytes.substr(0, n), f.extension().string(), f.filename().string() + " prefix " + std::to_string(n), t);
    }
    report(t);
    EXPECT_GT(t.stripped, 0u);  // full files (the last prefix) of the valid samples strip
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
constexpr bool kSanitized = __has_feature(address_sanitizer);
#else
constexpr bool kSanitized = false;
#endif

TEST(Mutation, SingleByteMutationsAreRefusedOrVerified) {
    // Replacement bytes chosen to hit number syntax, separators, keywords and binary counts; the
    // last one flips the low bit (a neighbouring digit or count).
    const int values[] = {0x00, 0xff, '0', '9', '-', '.', ' ', '\n', 'e', 0x7f, -1};
    constexpr size_t kAll = std::size(values);
    // Under the sanitizers (ten times slower: 12 of the default run's minutes) each position
    // gets 4 of the 11 mutations, in turn, so every position and every mutation is still met.
    const size_t per_byte = kSanitized ? 4 : kAll;
    Tally t;
    for (const auto& f : sample_meshes()) {
        const std::string bytes = slurp(f);
        for (size_t i = 0; i < bytes.size(); ++i) {
            std::string m = bytes;
            for (size_t j = 0; j < per_byte; ++j) {
                const int v = values[(i + j) % kAll];
                const auto b = static_cast<unsigned char>(v < 0 ? bytes[i] ^ 0x01 : v);
                if (static_cast<unsigned char>(bytes[i]) == b) continue;
                m[i] = static_cast<char>(b);
                const std::string what = v < 0 ? " ^ 1" : " = " + std::to_string(v);
                run_case(m, f.extension().string(), f.filename().string() + " byte " + std::to_string(i) + what, t);
            }
        }
    }
    report(t);
    EXPECT_GT(t.stripped, 0u);
}

// ---- resource limits -------------------------------------------------------------------------

namespace {

/// Reads `bytes` as a file in a forked child (so a crash or hang cannot take the suite down).
/// Returns "" when read_mesh_file threw InputError and no single allocation exceeded
/// `max_alloc`; else what happened.
std::string refused_cheaply(const std::string& bytes, const std::string& ext, size_t max_alloc = size_t{64} << 20) {
    const std::string path = write_case(bytes, ext);
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        alarm(60);  // hang guard only (the reads take milliseconds): SIGALRM ends the child
        g_largest_request = 0;
        int code = 0;
        try {
            (void)read_mesh_file(path);
            code = 10;
        } catch (const InputError&) {
            code = 0;
        } catch (...) {
            code = 11;
        }
        if (code == 0 && g_largest_request.load() > max_alloc) {
            std::fprintf(stderr, "largest allocation: %zu bytes\n", g_largest_request.load());
            code = 12;
        }
        _exit(code);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    if (WIFSIGNALED(st)) return WTERMSIG(st) == SIGALRM ? "hang (killed after 60 s)" : "killed by signal " + std::to_string(WTERMSIG(st));
    switch (WEXITSTATUS(st)) {
        case 0:
            return {};
        case 10:
            return "accepted";
        case 11:
            return "threw something other than InputError";
        case 12:
            return "refused, but only after allocating more than " + std::to_string(max_alloc >> 20) + " MiB at once";
        default:
            return "child exit " + std::to_string(WEXITSTATUS(st));
    }
}

std::string ply_header(const std::string& format, const std::string& nv, const std::string& nf, const std::string& list = "uchar int") {
    return "ply\nformat " + format + " 1.0\nelement vertex " + nv +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " + nf + "\nproperty list " + list +
           " vertex_indices\nend_header\n";
}

std::string binary_stl(uint32_t declared, size_t real) {
    std::string s(80, '\0');
    s.append(reinterpret_cast<const char*>(&declared), 4);  // little-endian host (x86-64, aarch64)
    s.append(50 * real, '\0');
    return s;
}

}  // namespace

TEST(ResourceLimits, AbsurdVertexCountsAreRefused) {
    EXPECT_EQ(refused_cheaply("OFF\n1000000000000 1 0\n", ".off"), "");
    EXPECT_EQ(refused_cheaply(ply_header("ascii", "1000000000000", "1"), ".ply"), "");
    EXPECT_EQ(refused_cheaply(ply_header("binary_little_endian", "1000000000000", "1"), ".ply"), "");
    EXPECT_EQ(refused_cheaply(ply_header("binary_little_endian", "100000000", "100000000") + std::string(64, '\0'), ".ply"), "");
}

TEST(ResourceLimits, AbsurdTriangleCountInTinyBinaryStlIsRefused) {
    EXPECT_EQ(refused_cheaply(binary_stl(1000000000u, 1), ".stl"), "");
    EXPECT_EQ(refused_cheaply(binary_stl(0xffffffffu, 0), ".stl"), "");
}

// Finding F7 (fixed): CGAL's binary PLY reader allocates count * size for a face list before
// reading it (8 GB for the count 2^31-1 in this 130-byte file).
TEST(ResourceLimits, HugeListCountInBinaryPlyIsRefused) {
    std::string s = ply_header("binary_little_endian", "3", "1", "uint int");
    const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    s.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
    const uint32_t count = 0x7fffffffu;
    s.append(reinterpret_cast<const char*>(&count), 4);
    s.append(12, '\0');
    EXPECT_EQ(refused_cheaply(s, ".ply"), "");
}

// Finding F4 (fixed): OFF header counts are checked against the file size before CGAL allocates.
TEST(ResourceLimits, OffCountsAreCheckedBeforeAllocating) {
    EXPECT_EQ(refused_cheaply("OFF\n100000000 100000000 0\n", ".off"), "");
    EXPECT_EQ(refused_cheaply("OFF\n3 100000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", ".off"), "");
}

// Finding F8 (fixed): CGAL resizes an OFF polygon to its declared corner count before reading it.
TEST(ResourceLimits, OffFaceCornerCountIsCheckedBeforeAllocating) {
    EXPECT_EQ(refused_cheaply("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n300000000 0 1 2\n", ".off"), "");
}

// Findings F2 (hang) and F1 (crash) in CGAL's PLY header handling (fixed).
TEST(ResourceLimits, PlyElementWithoutPropertiesDoesNotHang) {
    EXPECT_EQ(refused_cheaply("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                              "element face 1\nproperty list uchar int vertex_indices\nelement foo 1000000000000\nend_header\n"
                              "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                              ".ply"),
              "");
}

TEST(ResourceLimits, PlyPropertyBeforeElementDoesNotCrash) {
    EXPECT_EQ(refused_cheaply("ply\nformat binary_little_endian 1.0\nproperty float x\nelement vertex 0\nend_header\n", ".ply"), "");
}

// ---- every fuzz reproducer -------------------------------------------------------------------

// Each file in fuzz/repro/ once crashed, hung, exhausted memory or gave a strip that verify()
// rejected (docs/reliability.md, F1-F10). Mesh files must now give a clean InputError or a
// verified strip, each in a forked child (a regressed crash must not take the suite down) with
// the allocation probe; companion files (.constraints.txt, .fuzz_pipeline) are used by
// PipelineReproducers below.
namespace {

std::vector<fs::path> repro_files() {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(fs::path(SINGLESTRIP_SOURCE_DIR) / "fuzz" / "repro")) out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

bool is_mesh(const fs::path& p) {
    const std::string ext = p.extension().string();
    return ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl";
}

/// check_file() in a forked child: "" when it passed with no allocation above 1 GiB.
std::string check_file_isolated(const fs::path& path) {
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        alarm(60);
        g_largest_request = 0;
        Tally t;
        const std::string p = check_file(path.string(), path.filename().string(), t);
        if (!p.empty()) std::fprintf(stderr, "%s\n", p.c_str());
        if (p.empty() && g_largest_request.load() > (size_t{64} << 20))
            std::fprintf(stderr, "largest allocation: %zu bytes\n", g_largest_request.load());
        std::fflush(stderr);
        _exit(!p.empty() ? 1 : g_largest_request.load() > (size_t{64} << 20) ? 2 : t.stripped ? 3 : 4);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    if (WIFSIGNALED(st)) return WTERMSIG(st) == SIGALRM ? "hang (killed after 60 s)" : "killed by signal " + std::to_string(WTERMSIG(st));
    switch (WEXITSTATUS(st)) {
        case 1:
            return "finding (see stderr)";
        case 2:
            return "allocated more than 64 MiB at once";
        case 3:
            return "";  // stripped and verified
        case 4:
            return "";  // refused cleanly
        default:
            return "child exit " + std::to_string(WEXITSTATUS(st));
    }
}

}  // namespace

TEST(Reproducers, EveryReproducerMeshIsRefusedOrVerified) {
    size_t meshes = 0;
    for (const auto& f : repro_files()) {
        if (!is_mesh(f)) continue;
        ++meshes;
        EXPECT_EQ(check_file_isolated(f), "") << f.filename().string();
    }
    EXPECT_GE(meshes, 15u) << "fuzz/repro/ should hold the reproducers of F1-F13";
}

TEST(Reproducers, PipelineReproducersVerify) {
    // F9: seed face 0 with the constraint polyline of strip_grow_three_candidates.constraints.txt;
    // F6: the annulus with default options and the 2-hole sphere with seed face 5 (on the
    // boundary), where the cycle count is guaranteed and checked by verify().
    const fs::path dir = fs::path(SINGLESTRIP_SOURCE_DIR) / "fuzz" / "repro";
    struct Case {
        std::string mesh, constraints;
        std::optional<uint32_t> seed;
        bool orient;
    };
    const Case cases[] = {{"strip_grow_three_candidates.off", "strip_grow_three_candidates.constraints.txt", 0u, false},
                          {"cycles_annulus_missing_cycle.off", "", std::nullopt, false},
                          {"cycles_seed_face_on_boundary.off", "", 5u, true}};
    for (const auto& c : cases) {
        const std::string path = (dir / c.mesh).string();
        TriangleSoup soup = read_mesh_file(path);
        fuzzcheck::Request req;
        req.orient = c.orient;
        if (c.seed) req.strip.seed_face = FaceId(*c.seed);
        if (!c.constraints.empty())
            req.strip.constraint_edges = read_constraints((dir / c.constraints).string(), static_cast<uint32_t>(soup.points.size()));
        fuzzcheck::Outcome outcome;
        EXPECT_EQ(fuzzcheck::check_pipeline(std::move(soup), req, &outcome), "") << c.mesh;
        EXPECT_EQ(outcome, fuzzcheck::Outcome::Stripped) << c.mesh;
    }
}

// F29: --polish with source = target on a wavy grid, where the repair leaves a pinned face short
// (pipeline_polish_pinned_face_short.fuzz_pipeline decoded; the fuzzer's options: no greedy).
TEST(Reproducers, PolishWithAPinnedFaceShort) {
    const fs::path dir = fs::path(SINGLESTRIP_SOURCE_DIR) / "fuzz" / "repro";
    TriangleSoup soup = read_mesh_file((dir / "pipeline_polish_pinned_face_short.off").string());
    fuzzcheck::Request req;
    req.strip.greedy = false;
    req.strip.polish = true;
    req.strip.source = req.strip.target = VertexId(42);
    fuzzcheck::Outcome outcome;
    EXPECT_EQ(fuzzcheck::check_pipeline(std::move(soup), req, &outcome), "");
    EXPECT_EQ(outcome, fuzzcheck::Outcome::Stripped);
}

// ---- F5: the verifier and degenerate input faces --------------------------------------------

namespace {

/// A needle of height 1e-7 (|n| = 1e-7 size^2: barycentrics ill-conditioned) split at the
/// midpoint of its long edge, all coordinates times `s`.
VerifyInput split_needle(double s) {
    VerifyInput v;
    v.in_points = {{0, 0, 0}, {s, 0, 0}, {0.5 * s, 1e-7 * s, 0}};
    v.in_faces = {{0, 1, 2}};
    v.out_points = v.in_points;
    v.out_points.push_back({0.5 * s, 0, 0});
    v.out_faces = {{0, 3, 2}, {3, 1, 2}};
    v.out_parent = {0, 0};
    return v;
}

bool has_check(const VerifyReport& r, const std::string& check) {
    for (const auto& f : r.failures)
        if (f.rfind(check + ":", 0) == 0) return true;
    return false;
}

}  // namespace

TEST(Reproducers, VerifierAcceptsAndStillChecksDegenerateParents) {
    for (double s : {1.0, 1e-300, 1e300, 1e-310}) {
        SCOPED_TRACE("scale " + std::to_string(s));
        VerifyInput v = split_needle(s);
        EXPECT_TRUE(verify(v).ok()) << verify(v).to_string();
        v.out_parent.clear();  // parents inferred (OBJ/OFF outputs)
        EXPECT_TRUE(verify(v).ok()) << verify(v).to_string();

        v = split_needle(s);
        v.out_points[3] = {0.5 * s, 1e-3 * s, 0};  // the split vertex leaves the needle
        EXPECT_TRUE(has_check(verify(v), "geometry")) << verify(v).to_string();

        v = split_needle(s);
        v.out_faces.pop_back();  // a child dropped: area and boundary give it away
        v.out_parent.pop_back();
        const VerifyReport r = verify(v);
        EXPECT_TRUE(has_check(r, "coverage")) << r.to_string();
        EXPECT_TRUE(has_check(r, "conformity")) << r.to_string();

        v = split_needle(s);
        v.out_points[3] = {0.25 * s, 0, 0};  // off the midpoint but inside: areas 1/4 + 3/4, fine
        EXPECT_TRUE(verify(v).ok()) << verify(v).to_string();
    }
    // Coincident corners: a point-sized face, output identical to the input.
    VerifyInput p;
    p.in_points = {{1, 2, 3}, {1, 2, 3}, {1, 2, 3}};
    p.in_faces = {{0, 1, 2}};
    p.out_points = p.in_points;
    p.out_faces = p.in_faces;
    EXPECT_TRUE(verify(p).ok()) << verify(p).to_string();
    p.out_points.push_back({1, 2, 4});  // a child reaching outside the point
    p.out_faces = {{0, 1, 3}};
    p.out_parent = {0};
    EXPECT_FALSE(verify(p).ok());
}

TEST(Reproducers, ConstraintPairThatIsNotAnEdgeIsARefusalNotAFinding) {
    // The fuzz targets pass random pairs; stripify() refuses one that is not an edge while it
    // checks the constraints, and the harness must count that as a refusal.
    TriangleSoup soup = read_mesh_file(std::string(SINGLESTRIP_SOURCE_DIR) + "/tests/data/tetra.off");
    fuzzcheck::Request req;
    req.strip.constraint_edges = {{0, 1}, {2, 2}};
    fuzzcheck::Outcome outcome = fuzzcheck::Outcome::Stripped;
    EXPECT_EQ(fuzzcheck::check_pipeline(soup, req, &outcome), "");
    EXPECT_EQ(outcome, fuzzcheck::Outcome::Refused);
    req.strip.constraint_edges = {{0, 1}};
    EXPECT_EQ(fuzzcheck::check_pipeline(std::move(soup), req, &outcome), "");
    EXPECT_EQ(outcome, fuzzcheck::Outcome::Stripped);
}
