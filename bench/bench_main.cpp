// singlestrip_bench — both strip engines next to meshoptimizer on real and generated meshes.
//
// Per mesh, each part in its own forked child process (peak memory is per engine, and an
// engine that is slow or dies cannot take the other's numbers with it):
//   reference   read + prepare the mesh once (untimed); the swap floor (interior vertices whose
//               valence is not a multiple of 3); the time to read the file's bytes; and
//               meshoptimizer on the same triangles: optimizeVertexCacheStrip, then stripify
//               with restart index 0xffffffff and with 0 (degenerate joins, meshoptimizer.h
//               0.18); median of several runs each.
//   one child per engine: `reps` times read_mesh_file -> prepare_soup(orient) ->
//               Mesh::from_soup -> build_strip(engine) -> strip_arrays + encode_triangle_strip
//               -> write_strip_mesh (binary PLY); each stage's time is the median over the
//               repetitions, which stop early when they would overrun the child's time budget.
//               Peak memory = ru_maxrss right after the FIRST repetition, in a child forked from a
//               parent that holds no mesh. The last result is decoded and, up to --verify-max
//               triangles, checked by the independent verifier (untimed).
//   constraints (libcgal-demo meshes of >= 1000 triangles): a few cases of random constraint
//               polylines with a random source and target, both engines on the same cases, each
//               result verified.
// Generated meshes are first written as binary PLY files by another child (so the generator's
// memory never counts), then read like any file.
//
// Output: <out>/bench.csv (one line per mesh and engine), <out>/constraints.csv, <out>/bench.md
// (tables and targets), <out>/readme.md (README's quality table), <out>/scaling.dat and
// <out>/awkward.dat (gnuplot). Progress goes to stderr only when it is a terminal.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <meshoptimizer.h>

#include "families.hpp"
#include "fixtures.hpp"
#include "read_bench.hpp"
#include "scaling.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/validate.hpp"
#include "singlestrip/verify.hpp"

namespace fs = std::filesystem;
namespace ss = singlestrip;

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}
double median(std::vector<double> v) {
    std::erase_if(v, [](double x) { return std::isnan(x); });
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

bool g_progress = false;
void progress(const std::string& s) {
    if (g_progress) std::cerr << s << std::flush;
}

// The engines, default first: every "default engine" number in the report is engines[0].
constexpr int kEngines = 2;
const ss::StripEngine kEngine[kEngines] = {ss::StripEngine::Matching, ss::StripEngine::Growth};

enum class Kind { Cgal, Scaling, Awkward };

struct Spec {
    Kind kind = Kind::Cgal;
    std::string family;  ///< "cgal" or a generated family's name
    std::string name;
    std::string path;                                         ///< input file (cgal) or where the generated PLY goes
    std::string walls_path;                                   ///< constraint edges of a walled family, one "a b" pair per line
    std::function<singlestrip::bench::Generated()> generate;  ///< empty for files
    uint64_t nominal = 0;                                     ///< size class (10K, ...), 0 for cgal
    int reps = 5;
};

struct Settings {
    bool quick = false;
    double budget = 40;  ///< seconds of repetitions per engine child (at least one runs)
    uint64_t verify_max = 2000000;
    int constraint_cases = 4;
    double timeout = 240;
    uint64_t mem_limit = 0;
};

// Everything a child reports is POD so it can go through a pipe as bytes.

struct EngineRun {
    int status = -1;  ///< -1 not run, 0 ok, 1 skipped (input rejected), 2 failed (our error), 3 crashed / timed out
    char message[384] = {};
    int reps = 0;
    uint64_t in_vertices = 0, in_tris = 0, out_tris = 0, splits = 0, swaps = 0, indices = 0, loops = 0;
    uint64_t fundamental = 0, deferred = 0, detours = 0, boundary_loops = 0;
    long long genus = 0;
    bool decode_ok = false;
    int verified = -1;  ///< -1 not checked (over --verify-max), 0 failed, 1 passed
    char verify_message[256] = {};
    double t_read = NAN, t_check = NAN, t_adj = NAN, t_build = NAN, t_encode = NAN, t_write = NAN;
    double t_total = NAN;  ///< read -> write, median of the per-repetition sums
    uint64_t peak_kb = 0;
    double wall = NAN;  ///< filled by the parent
};

struct Reference {
    int status = -1;
    char message[384] = {};
    uint64_t file_bytes = 0, in_vertices = 0, in_tris = 0, interior = 0, interior_off3 = 0;
    double t_bytes = NAN;  ///< reading the file's bytes into memory (page cache warm)
    double m_vcache = NAN, m_restart = NAN, m_degen = NAN;
    uint64_t m_restart_indices = 0, m_restart_strips = 0, m_degen_indices = 0, m_degen_strips = 0;
    uint64_t max_valence = 0;
    bool meshopt_skipped = false;  ///< max_valence over kMeshoptMaxValence
};

constexpr uint64_t kMeshoptMaxValence = 200000;
constexpr int kMaxCases = 8;
struct ConstraintRun {
    int status = -1;
    char message[384] = {};
    uint64_t in_tris = 0;
    int cases = 0;
    int redrawn = 0;  ///< constraint sets drawn again because they cut the surface apart
    struct Case {
        uint32_t constraint_edges = 0;
        int ok[kEngines] = {};
        double extra[kEngines] = {NAN, NAN};
        double idx_per_tri[kEngines] = {NAN, NAN};
        int verified[kEngines] = {-1, -1};
        char error[kEngines][160] = {};
    } c[kMaxCases];
};

template <class T>
void set_message(T& r, const std::string& s) {
    std::snprintf(r.message, sizeof r.message, "%s", s.c_str());
}

/// Reads and prepares (orients) `path` into `soup`; an InputError is recorded in `r` (status 1)
/// and gives false.
template <class T>
bool read_prepared(const std::string& path, ss::TriangleSoup& soup, T& r) {
    try {
        soup = ss::prepare_soup(ss::read_mesh_file(path), ss::PrepareOptions{true}, path);
        return true;
    } catch (const ss::InputError& e) {
        r.status = 1;
        set_message(r, e.what());
        return false;
    }
}

/// Strips joined by degenerate triangles in a GL strip. A swap inside a strip (a b a) makes ONE
/// degenerate triangle; a join (... a b b c c d ...) makes a run of two or more, so only runs of
/// length >= 2 count as joins.
uint64_t count_degenerate_strips(const std::vector<unsigned>& s) {
    if (s.size() < 3) return s.empty() ? 0 : 1;
    uint64_t joins = 0, run = 0;
    for (size_t i = 0; i + 2 < s.size(); ++i) {
        const bool deg = s[i] == s[i + 1] || s[i + 1] == s[i + 2] || s[i] == s[i + 2];
        if (deg) {
            ++run;
        } else {
            joins += run >= 2;
            run = 0;
        }
    }
    return joins + 1;
}

/// Same triangle with the same winding (any rotation of its corners).
bool same_oriented(const ss::Triangle& a, const ss::Triangle& b) {
    for (int k = 0; k < 3; ++k)
        if (a[0] == b[k] && a[1] == b[(k + 1) % 3] && a[2] == b[(k + 2) % 3]) return true;
    return false;
}

/// Interior vertices and those whose valence is not a multiple of 3. Each such vertex forces
/// half a swap in any strip (issue 15), so 1 + off3 / (2F) indices per triangle is a floor.
void count_interior_valence(const ss::TriangleSoup& s, uint64_t& interior, uint64_t& off3, uint64_t& max_valence) {
    std::vector<uint64_t> e;
    e.reserve(s.triangles.size() * 3);
    std::vector<uint32_t> deg(s.points.size(), 0);
    for (const ss::Triangle& t : s.triangles)
        for (int k = 0; k < 3; ++k) {
            e.push_back(uint64_t{t[k]} << 32 | t[(k + 1) % 3]);
            ++deg[t[k]];  // one outgoing edge per incident face
        }
    std::sort(e.begin(), e.end());
    std::vector<char> boundary(s.points.size(), 0);
    for (const uint64_t x : e) {
        const uint64_t twin = (x & 0xffffffffu) << 32 | x >> 32;
        if (!std::binary_search(e.begin(), e.end(), twin)) boundary[x >> 32] = boundary[x & 0xffffffffu] = 1;
    }
    interior = off3 = 0;
    max_valence = deg.empty() ? 0 : *std::max_element(deg.begin(), deg.end());
    for (size_t v = 0; v < deg.size(); ++v) {
        if (deg[v] == 0 || boundary[v]) continue;
        ++interior;
        off3 += deg[v] % 3 != 0;
    }
}

std::string first_line(const std::string& s) {
    return s.substr(0, s.find('\n'));
}

/// Runs the independent verifier; returns 1/0 and the first failure in `msg`.
int verify_result(const ss::TriangleSoup& in, const ss::StripArrays& out, const std::vector<uint32_t>& indices, const ss::StripOptions& o,
                  char* msg, size_t msg_size) {
    ss::VerifyInput vi = ss::verify_input(in, out, indices);
    vi.constraints = ss::vertex_pairs(o.constraint_edges);
    vi.source = ss::index_of(o.source);
    vi.target = ss::index_of(o.target);
    const ss::VerifyReport rep = ss::verify(vi);
    if (!rep.ok()) std::snprintf(msg, msg_size, "%s", first_line(rep.failures.front()).c_str());
    return rep.ok() ? 1 : 0;
}

using EdgeList = singlestrip::bench::EdgeList;

EdgeList read_walls(const std::string& path) {
    EdgeList e;
    std::ifstream in(path);
    uint32_t a = 0, b = 0;
    while (in >> a >> b) e.push_back({a, b});
    return e;
}

void write_generated(const Spec& spec) {
    const singlestrip::bench::Generated g = spec.generate();
    singlestrip::bench::write_binary_ply(spec.path, g.soup);
    if (!spec.walls_path.empty()) {
        std::ofstream o(spec.walls_path);
        for (const auto& [a, b] : g.walls) o << a << ' ' << b << '\n';
        if (!o) throw ss::OutputError(spec.walls_path + ": write failed");
    }
}

EngineRun measure_engine(const Spec& spec, ss::StripEngine engine, const std::string& out_path, const Settings& cfg) {
    EngineRun r;
    std::vector<double> tr, tc, ta, tb, te, tw, tt;
    ss::StripArrays last;
    std::vector<uint32_t> last_indices;
    ss::StripOptions options;
    options.engine = engine;
    const auto start = Clock::now();
    try {
        for (int rep = 0; rep < spec.reps; ++rep) {
            auto t = Clock::now();
            ss::TriangleSoup soup;
            try {
                soup = ss::read_mesh_file(spec.path);
            } catch (const ss::InputError& e) {
                r.status = 1;  // a file the reader rejects (e.g. a point cloud) is skipped, not failed
                set_message(r, e.what());
                return r;
            }
            // Walls are read with the mesh, as `strip --constraints` would.
            if (!spec.walls_path.empty()) options.constraint_edges = ss::as_constraints(read_walls(spec.walls_path));
            tr.push_back(seconds_since(t));
            t = Clock::now();
            try {
                soup = ss::prepare_soup(std::move(soup), ss::PrepareOptions{true}, spec.path);
            } catch (const ss::InputError& e) {
                r.status = 1;
                set_message(r, e.what());
                return r;
            }
            tc.push_back(seconds_since(t));
            r.in_vertices = soup.points.size();
            r.in_tris = soup.triangles.size();
            t = Clock::now();
            ss::Mesh mesh = ss::Mesh::from_soup(soup);
            ta.push_back(seconds_since(t));
            if (const uint32_t parts = mesh.num_components(); parts > 1) {  // timed here as one strip
                r.status = 1;
                set_message(r, std::to_string(parts) + " edge-connected components (the bench times one strip; stripify() strips each)");
                return r;
            }
            // The mesh holds its own copy of everything: drop the soup, as a memory-aware caller would.
            soup = ss::TriangleSoup{};
            t = Clock::now();
            ss::StripResult res = ss::build_strip(std::move(mesh), options);
            tb.push_back(seconds_since(t));
            t = Clock::now();
            ss::StripArrays arr = ss::strip_arrays(res);
            std::vector<uint32_t> indices = ss::encode_triangle_strip(arr.faces);
            te.push_back(seconds_since(t));
            if (rep == 0) {
                const ss::StripStats& st = res.stats;
                r.out_tris = st.output_triangles;
                r.splits = st.splits;
                r.swaps = st.swaps;
                r.loops = st.loops;
                r.fundamental = st.fundamental_triangles;
                r.deferred = st.deferred_regions;
                r.detours = st.detours;
                r.genus = st.genus;
                r.boundary_loops = st.boundary_loops;
                r.indices = indices.size();
                const std::vector<ss::Triangle> dec = ss::decode_triangle_strip(indices);
                r.decode_ok = dec.size() == arr.faces.size() && arr.faces.size() == r.out_tris &&
                              std::equal(dec.begin(), dec.end(), arr.faces.begin(), same_oriented);
            }
            res = ss::StripResult{};
            t = Clock::now();
            ss::write_strip_mesh(out_path, arr.points, arr.faces, arr.parent);
            tw.push_back(seconds_since(t));
            tt.push_back(tr.back() + tc.back() + ta.back() + tb.back() + te.back() + tw.back());
            if (rep == 0) {
                rusage ru{};
                getrusage(RUSAGE_SELF, &ru);
                r.peak_kb = static_cast<uint64_t>(ru.ru_maxrss);
            }
            last = std::move(arr);
            last_indices = std::move(indices);
            ++r.reps;
            progress(".");
            // A median of five minute-long runs tells little more than one, and the full run has
            // to fit its time: stop when one more repetition would overrun the budget.
            const double spent = seconds_since(start);
            if (spent + spent / (rep + 1) > cfg.budget) break;
        }
    } catch (const std::exception& e) {
        r.status = 2;
        set_message(r, e.what());
        return r;
    }
    r.t_read = median(tr);
    r.t_check = median(tc);
    r.t_adj = median(ta);
    r.t_build = median(tb);
    r.t_encode = median(te);
    r.t_write = median(tw);
    r.t_total = median(tt);
    r.status = 0;
    if (r.in_tris <= cfg.verify_max) {
        try {
            const ss::TriangleSoup soup = ss::prepare_soup(ss::read_mesh_file(spec.path), ss::PrepareOptions{true}, spec.path);
            r.verified = verify_result(soup, last, last_indices, options, r.verify_message, sizeof r.verify_message);
        } catch (const std::exception& e) {
            r.verified = 0;
            std::snprintf(r.verify_message, sizeof r.verify_message, "verifier: %s", e.what());
        }
    }
    return r;
}

Reference measure_reference(const Spec& spec, int mreps, double budget) {
    Reference r;
    try {
        std::error_code ec;
        r.file_bytes = fs::file_size(spec.path, ec);
        // Reading the bytes alone: the floor any reader of this file has (issue 17).
        std::vector<double> tb;
        std::vector<char> buf(r.file_bytes + 1);
        for (int rep = 0; rep < 3; ++rep) {
            const auto t = Clock::now();
            std::FILE* f = std::fopen(spec.path.c_str(), "rb");
            if (!f) break;
            const size_t n = std::fread(buf.data(), 1, buf.size(), f);
            std::fclose(f);
            if (n != r.file_bytes) break;
            tb.push_back(seconds_since(t));
        }
        buf = {};
        r.t_bytes = median(tb);
        ss::TriangleSoup soup;
        if (!read_prepared(spec.path, soup, r)) return r;
        r.in_vertices = soup.points.size();
        r.in_tris = soup.triangles.size();
        count_interior_valence(soup, r.interior, r.interior_off3, r.max_valence);
        // optimizeVertexCacheStrip is quadratic in a vertex's valence (a 100K-triangle cone: 16 s,
        // so about 25 minutes at 1M): past this valence meshoptimizer is left out, and said so.
        if (r.max_valence > kMeshoptMaxValence) {
            r.status = 0;
            r.meshopt_skipped = true;
            return r;
        }
        const size_t nidx = soup.triangles.size() * 3, nv = soup.points.size();
        std::vector<unsigned> ib(nidx);
        for (size_t f = 0; f < soup.triangles.size(); ++f)
            for (int k = 0; k < 3; ++k) ib[3 * f + k] = soup.triangles[f][k];
        soup = ss::TriangleSoup{};
        std::vector<unsigned> opt(nidx), dst(meshopt_stripifyBound(nidx));
        std::vector<double> tv, t1, t0;
        size_t n1 = 0, n0 = 0;
        const auto start = Clock::now();
        for (int rep = 0; rep < mreps; ++rep) {
            const auto t = Clock::now();
            meshopt_optimizeVertexCacheStrip(opt.data(), ib.data(), nidx, nv);
            tv.push_back(seconds_since(t));
            if (seconds_since(start) > budget) break;  // slow (high valence): one or two runs say enough
        }
        for (int rep = 0; rep < mreps; ++rep) {
            const auto t = Clock::now();
            n1 = meshopt_stripify(dst.data(), opt.data(), nidx, nv, ~0u);
            t1.push_back(seconds_since(t));
        }
        r.m_restart_indices = n1;
        r.m_restart_strips = 1 + static_cast<uint64_t>(std::count(dst.begin(), dst.begin() + n1, ~0u));
        for (int rep = 0; rep < mreps; ++rep) {
            const auto t = Clock::now();
            n0 = meshopt_stripify(dst.data(), opt.data(), nidx, nv, 0u);
            t0.push_back(seconds_since(t));
        }
        dst.resize(n0);
        r.m_degen_indices = n0;
        r.m_degen_strips = count_degenerate_strips(dst);
        r.m_vcache = median(tv);
        r.m_restart = median(t1);
        r.m_degen = median(t0);
        r.status = 0;
    } catch (const std::exception& e) {
        r.status = 2;
        set_message(r, std::string("reference: ") + e.what());
    }
    return r;
}

uint64_t edge_key(uint32_t a, uint32_t b) {
    return uint64_t{std::min(a, b)} << 32 | std::max(a, b);
}

/// Pieces the faces fall into when `cuts` are removed from the dual graph: a set with more than
/// one is refused by both engines (as it must be) and tells nothing about quality.
size_t pieces_after_cutting(const ss::TriangleSoup& soup, const EdgeList& cuts) {
    std::vector<uint64_t> cut;
    for (auto [u, v] : cuts) cut.push_back(edge_key(u, v));
    std::sort(cut.begin(), cut.end());
    std::vector<std::pair<uint64_t, uint32_t>> e;
    for (uint32_t f = 0; f < soup.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) e.push_back({edge_key(soup.triangles[f][k], soup.triangles[f][(k + 1) % 3]), f});
    std::sort(e.begin(), e.end());
    std::vector<uint32_t> parent(soup.triangles.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    size_t pieces = soup.triangles.size();
    for (size_t i = 0; i + 1 < e.size(); ++i) {
        if (e[i].first != e[i + 1].first || std::binary_search(cut.begin(), cut.end(), e[i].first)) continue;
        const uint32_t a = find(e[i].second), b = find(e[i + 1].second);
        if (a != b) {
            parent[a] = b;
            --pieces;
        }
    }
    return pieces;
}

/// Self-avoiding random walks along mesh edges: the recipe of tests/test_constraints.cpp
/// (RandomConstraintsAndEndpointsOnRealMeshes): 1-6 polylines of up to 40 edges.
EdgeList random_polylines(const ss::TriangleSoup& soup, std::mt19937_64& rng, int count, int max_len) {
    std::vector<std::vector<uint32_t>> adj(soup.points.size());
    for (const auto& t : soup.triangles)
        for (int k = 0; k < 3; ++k) adj[t[k]].push_back(t[(k + 1) % 3]);
    EdgeList edges;
    for (int p = 0; p < count; ++p) {
        uint32_t v = soup.triangles[rng() % soup.triangles.size()][0];
        std::vector<uint32_t> seen{v};
        const int len = 1 + static_cast<int>(rng() % max_len);
        for (int s = 0; s < len && !adj[v].empty(); ++s) {
            const uint32_t w = adj[v][rng() % adj[v].size()];
            if (std::find(seen.begin(), seen.end(), w) != seen.end()) break;
            seen.push_back(w);
            edges.push_back({v, w});
            v = w;
        }
    }
    return edges;
}

ConstraintRun measure_constraints(const Spec& spec, const Settings& cfg) {
    ConstraintRun r;
    try {
        ss::TriangleSoup soup;
        if (!read_prepared(spec.path, soup, r)) return r;
        r.in_tris = soup.triangles.size();
        // As the engine children: build_strip() refuses several components (stripify() strips
        // each), so these cases are skipped, not counted as failed builds.
        if (const uint32_t parts = ss::Mesh::from_soup(soup).num_components(); parts > 1) {
            r.status = 1;
            set_message(r, std::to_string(parts) + " edge-connected components (build_strip() strips one)");
            return r;
        }
        // Seeded by the name: the same cases on every run and for both engines.
        uint64_t seed = 1469598103934665603ull;
        for (const char ch : spec.name) seed = (seed ^ static_cast<unsigned char>(ch)) * 1099511628211ull;
        std::mt19937_64 rng(seed);
        r.cases = std::min(cfg.constraint_cases, kMaxCases);
        for (int i = 0; i < r.cases; ++i) {
            ss::StripOptions o;
            for (int attempt = 0;; ++attempt) {
                const EdgeList walls = random_polylines(soup, rng, 1 + static_cast<int>(rng() % 6), 40);
                o.constraint_edges = ss::as_constraints(walls);
                if (pieces_after_cutting(soup, walls) == 1 || attempt == 50) break;
                ++r.redrawn;
            }
            o.source = ss::VertexId(soup.triangles[rng() % soup.triangles.size()][rng() % 3]);
            o.target = ss::VertexId(soup.triangles[rng() % soup.triangles.size()][rng() % 3]);
            ConstraintRun::Case& c = r.c[i];
            c.constraint_edges = static_cast<uint32_t>(o.constraint_edges.size());
            for (int e = 0; e < kEngines; ++e) {
                o.engine = kEngine[e];
                try {
                    const ss::StripResult res = ss::build_strip(ss::Mesh::from_soup(soup), o);
                    const ss::StripArrays arr = ss::strip_arrays(res);
                    const std::vector<uint32_t> idx = ss::encode_triangle_strip(arr.faces);
                    const double tri = double(r.in_tris);
                    c.ok[e] = 1;
                    c.extra[e] = 100.0 * (double(res.stats.output_triangles) - tri) / tri;
                    c.idx_per_tri[e] = double(idx.size()) / tri;
                    c.verified[e] = verify_result(soup, arr, idx, o, c.error[e], sizeof c.error[e]);
                } catch (const std::exception& ex) {
                    std::snprintf(c.error[e], sizeof c.error[e], "%s", first_line(ex.what()).c_str());
                }
            }
            progress(".");
        }
        r.status = 0;
    } catch (const std::exception& e) {
        r.status = 2;
        set_message(r, e.what());
    }
    return r;
}

/// Runs fn in a forked child with a memory cap; returns its exit status (or -signal / -999 on
/// timeout) and what it wrote to the pipe.
int run_child(const std::function<void(int)>& fn, double timeout_s, uint64_t mem_limit_bytes, std::string* payload) {
    int fds[2];
    if (pipe(fds) != 0) return -998;
    std::cout.flush();
    std::cerr.flush();
    const pid_t pid = fork();
    if (pid < 0) return -997;
    if (pid == 0) {
        close(fds[0]);
        if (mem_limit_bytes) {
            rlimit rl{mem_limit_bytes, mem_limit_bytes};
            setrlimit(RLIMIT_AS, &rl);
        }
        try {
            fn(fds[1]);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "child: %s\n", e.what());
            _exit(3);
        }
        close(fds[1]);
        _exit(0);
    }
    close(fds[1]);
    const auto start = Clock::now();
    bool timed_out = false;
    for (;;) {
        pollfd p{fds[0], POLLIN, 0};
        const int rc = poll(&p, 1, 500);
        if (rc > 0) {
            char buf[4096];
            const ssize_t n = read(fds[0], buf, sizeof buf);
            if (n > 0) {
                if (payload) payload->append(buf, static_cast<size_t>(n));
                continue;
            }
            break;  // EOF: the child closed the pipe (exited)
        }
        if (seconds_since(start) > timeout_s) {
            kill(pid, SIGKILL);
            timed_out = true;
            break;
        }
    }
    close(fds[0]);
    int st = 0;
    rusage ru{};
    wait4(pid, &st, 0, &ru);
    if (timed_out) return -999;
    if (WIFSIGNALED(st)) return -WTERMSIG(st);
    return WEXITSTATUS(st);
}

std::string fmt(const char* f, double v) {
    if (std::isnan(v)) return "–";
    char b[64];
    std::snprintf(b, sizeof b, f, v);
    return b;
}

/// Runs `f` in a child and returns its POD result; a child that dies or times out gives a
/// result with status 3 and the reason.
template <class T>
T run_pod(const std::function<T()>& f, const Settings& cfg) {
    std::string payload;
    const int st = run_child(
        [&](int fd) {
            const T r = f();
            const char* p = reinterpret_cast<const char*>(&r);
            size_t left = sizeof r;
            while (left) {
                const ssize_t n = write(fd, p, left);
                if (n <= 0) break;
                p += n;
                left -= static_cast<size_t>(n);
            }
        },
        cfg.timeout, cfg.mem_limit, &payload);
    T r;
    if (st == 0 && payload.size() == sizeof(T)) {
        std::memcpy(static_cast<void*>(&r), payload.data(), sizeof(T));
    } else {
        r.status = 3;
        set_message(r, st == -999 ? "timeout after " + fmt("%.0f", cfg.timeout) + " s" : "child died (status " + std::to_string(st) + ")");
    }
    return r;
}

std::string ms(double s) {
    return fmt(s < 0.01 ? "%.2f" : (s < 1 ? "%.1f" : "%.0f"), s * 1e3);
}
std::string count_k(uint64_t n) {
    char b[32];
    if (n >= 1000000)
        std::snprintf(b, sizeof b, "%.2gM", n / 1e6);
    else if (n >= 1000)
        std::snprintf(b, sizeof b, "%.3gK", n / 1e3);
    else
        std::snprintf(b, sizeof b, "%llu", static_cast<unsigned long long>(n));
    return b;
}
std::string pct(double v) {
    return fmt("%.1f%%", v);
}
/// Target lines compare against limits like 1.5%: one more digit so a value shown never rounds
/// onto the limit it missed.
std::string pct2(double v) {
    return fmt("%.2f%%", v);
}
std::string pass_miss(bool pass, const std::string& by = "") {
    return pass ? "**met**" : "**missed**" + (by.empty() ? std::string() : " (" + by + ")");
}

struct Row {
    Spec spec;
    Reference ref;
    EngineRun eng[kEngines];
    ConstraintRun con;
    bool has_constraints = false;
};

const char* ename(int e) {
    return ss::engine_name(kEngine[e]);
}
double tris(const Row& row) {
    if (row.ref.status == 0) return double(row.ref.in_tris);
    for (const EngineRun& e : row.eng)
        if (e.status == 0) return double(e.in_tris);
    return NAN;
}
double extra(const EngineRun& e) {
    return e.status == 0 ? 100.0 * (double(e.out_tris) - double(e.in_tris)) / double(e.in_tris) : NAN;
}
double idx_per_tri(const EngineRun& e) {
    return e.status == 0 ? double(e.indices) / double(e.in_tris) : NAN;
}
double floor_idx(const Reference& r) {
    return r.status == 0 ? 1.0 + 0.5 * double(r.interior_off3) / double(r.in_tris) : NAN;
}
double meshopt_idx(const Reference& r) {
    return r.status == 0 && !r.meshopt_skipped ? double(r.m_restart_indices) / double(r.in_tris) : NAN;
}
/// Adjacency + strip + encode: the stages that depend on the engine and on the mesh's shape.
double core_time(const EngineRun& e) {
    return e.status == 0 ? e.t_adj + e.t_build + e.t_encode : NAN;
}
bool ok(const Row& row) {
    if (row.ref.status > 0) return false;
    for (const EngineRun& e : row.eng)
        if (e.status > 0) return false;
    return true;
}

std::string engine_cell(const EngineRun& e, const std::string& v) {
    if (e.status == -1) return "";
    if (e.status != 0) return e.status == 3 ? "crashed" : "failed";
    return v;
}

std::string verified_cell(const Row& row) {
    std::string s;
    for (int e = 0; e < kEngines; ++e) {
        const EngineRun& r = row.eng[e];
        if (r.status != 0) continue;
        if (!s.empty()) s += ", ";
        s += r.verified == 1 ? "ok" : r.verified == 0 ? std::string("**FAILED**: ") + r.verify_message : "–";
        if (!r.decode_ok) s += " (decode MISMATCH)";
    }
    return s;
}

void write_csv(const std::string& path, const std::vector<Row>& rows) {
    std::ofstream o(path);
    o << "family,name,nominal,engine,status,message,reps,file_bytes,in_vertices,in_tris,out_tris,extra_pct,splits,"
         "swaps,loops,indices,indices_per_tri,interior_vertices,interior_valence_not_3k,floor_indices_per_tri,"
         "gap_to_floor,fundamental,deferred,detours,genus,boundary_loops,decode_ok,verified,verify_message,t_bytes_s,"
         "t_read_s,t_check_s,t_adjacency_s,t_strip_s,t_encode_s,t_write_s,t_read_to_write_s,peak_kb,"
         "peak_bytes_per_tri,meshopt_vcache_s,meshopt_restart_s,meshopt_restart_indices,meshopt_restart_strips,"
         "meshopt_degen_s,meshopt_degen_indices,meshopt_degen_strips,wall_s\n";
    o.precision(9);
    auto q = [](std::string m) {
        std::replace(m.begin(), m.end(), '"', '\'');
        std::replace(m.begin(), m.end(), '\n', ' ');
        return "\"" + m + "\"";
    };
    for (const Row& row : rows) {
        for (int e = 0; e < kEngines; ++e) {
            const EngineRun& r = row.eng[e];
            const Reference& f = row.ref;
            if (r.status == -1) continue;
            const double tri = double(r.in_tris);
            o << row.spec.family << ',' << row.spec.name << ',' << row.spec.nominal << ',' << ename(e) << ',' << r.status << ','
              << q(r.message) << ',' << r.reps << ',' << f.file_bytes << ',' << r.in_vertices << ',' << r.in_tris << ',' << r.out_tris
              << ',' << extra(r) << ',' << r.splits << ',' << r.swaps << ',' << r.loops << ',' << r.indices << ',' << idx_per_tri(r) << ','
              << f.interior << ',' << f.interior_off3 << ',' << floor_idx(f) << ',' << idx_per_tri(r) - floor_idx(f) << ',' << r.fundamental
              << ',' << r.deferred << ',' << r.detours << ',' << r.genus << ',' << r.boundary_loops << ',' << r.decode_ok << ','
              << r.verified << ',' << q(r.verify_message) << ',' << f.t_bytes << ',' << r.t_read << ',' << r.t_check << ',' << r.t_adj
              << ',' << r.t_build << ',' << r.t_encode << ',' << r.t_write << ',' << r.t_total << ',' << r.peak_kb << ','
              << (tri > 0 ? r.peak_kb * 1024.0 / tri : NAN) << ',' << f.m_vcache << ',' << f.m_restart << ',' << f.m_restart_indices << ','
              << f.m_restart_strips << ',' << f.m_degen << ',' << f.m_degen_indices << ',' << f.m_degen_strips << ',' << r.wall << '\n';
        }
    }
}

void write_constraints_csv(const std::string& path, const std::vector<Row>& rows) {
    std::ofstream o(path);
    o << "name,in_tris,case,constraint_edges";
    for (int e = 0; e < kEngines; ++e)
        o << ',' << ename(e) << "_ok," << ename(e) << "_extra_pct," << ename(e) << "_indices_per_tri," << ename(e) << "_verified,"
          << ename(e) << "_error";
    o << '\n';
    o.precision(9);
    for (const Row& row : rows) {
        if (!row.has_constraints || row.con.status != 0) continue;
        for (int i = 0; i < row.con.cases; ++i) {
            const auto& c = row.con.c[i];
            o << row.spec.name << ',' << row.con.in_tris << ',' << i << ',' << c.constraint_edges;
            for (int e = 0; e < kEngines; ++e) {
                std::string m = c.error[e];
                std::replace(m.begin(), m.end(), '"', '\'');
                o << ',' << c.ok[e] << ',' << c.extra[e] << ',' << c.idx_per_tri[e] << ',' << c.verified[e] << ",\"" << m << '"';
            }
            o << '\n';
        }
    }
}

/// Quality: both engines, the swap floor and meshoptimizer's restart-mode strips.
std::string quality_table(const std::vector<const Row*>& rows) {
    std::ostringstream o;
    o << "| mesh | input tris | floor idx/tri";
    for (int e = 0; e < kEngines; ++e) {
        o << " | " << ename(e) << ": extra | swaps | idx/tri";
        if (e == 0) o << " | gap to floor";
    }
    o << " | meshopt: strips | meshopt: idx/tri | verified |\n|---|--:|--:|";
    for (int e = 0; e < kEngines; ++e) o << (e == 0 ? "--:|--:|--:|--:|" : "--:|--:|--:|");
    o << "--:|--:|---|\n";
    for (const Row* row : rows) {
        const Reference& f = row->ref;
        o << "| " << row->spec.name << " | " << fmt("%.0f", tris(*row)) << " | " << fmt("%.3f", floor_idx(f));
        for (int e = 0; e < kEngines; ++e) {
            const EngineRun& r = row->eng[e];
            o << " | " << engine_cell(r, pct(extra(r))) << " | " << engine_cell(r, std::to_string(r.swaps)) << " | "
              << engine_cell(r, fmt("%.3f", idx_per_tri(r)));
            if (e == 0) o << " | " << engine_cell(r, fmt("%+.3f", idx_per_tri(r) - floor_idx(f)));
        }
        o << " | " << (f.status == 0 && !f.meshopt_skipped ? std::to_string(f.m_restart_strips) : "–") << " | "
          << fmt("%.3f", meshopt_idx(f)) << " | " << verified_cell(*row) << " |\n";
    }
    return o.str();
}

/// Time per stage. read, check, adjacency and write do not depend on the engine: the default
/// engine's child gives them.
std::string time_table(const std::vector<const Row*>& rows, bool peak) {
    std::ostringstream o;
    o << "| mesh | input tris | read ms | check ms | adjacency ms";
    for (int e = 0; e < kEngines; ++e) o << " | " << ename(e) << ": strip ms | encode ms";
    o << " | write ms | meshopt: vcache ms | stripify ms";
    if (peak) {
        o << " | bytes read ms";
        for (int e = 0; e < kEngines; ++e) o << " | " << ename(e) << ": read → write ms | peak MB | B/tri";
    }
    o << " |\n|---|--:|--:|--:|--:|";
    for (int e = 0; e < kEngines; ++e) o << "--:|--:|";
    o << "--:|--:|--:|";
    if (peak) {
        o << "--:|";
        for (int e = 0; e < kEngines; ++e) o << "--:|--:|--:|";
    }
    o << '\n';
    for (const Row* row : rows) {
        const EngineRun& d = row->eng[0].status == 0 ? row->eng[0] : row->eng[1];
        o << "| " << row->spec.name << " | " << fmt("%.0f", tris(*row)) << " | " << ms(d.t_read) << " | " << ms(d.t_check) << " | "
          << ms(d.t_adj);
        for (int e = 0; e < kEngines; ++e) {
            const EngineRun& r = row->eng[e];
            o << " | " << engine_cell(r, ms(r.t_build)) << " | " << engine_cell(r, ms(r.t_encode));
        }
        o << " | " << ms(d.t_write) << " | " << ms(row->ref.m_vcache) << " | " << ms(row->ref.m_restart);
        if (peak) {
            o << " | " << ms(row->ref.t_bytes);
            for (int e = 0; e < kEngines; ++e) {
                const EngineRun& r = row->eng[e];
                o << " | " << engine_cell(r, ms(r.t_total)) << " | " << engine_cell(r, fmt("%.0f", r.peak_kb / 1024.0)) << " | "
                  << engine_cell(r, fmt("%.0f", r.peak_kb * 1024.0 / double(r.in_tris)));
            }
        }
        o << " |\n";
    }
    return o.str();
}

/// Exponent k of t ~ F^k between this size and the previous one of the same family.
double exponent(const Row* prev, const Row* cur, int e) {
    if (!prev) return NAN;
    const double t0 = core_time(prev->eng[e]), t1 = core_time(cur->eng[e]);
    const double f0 = tris(*prev), f1 = tris(*cur);
    if (!(t0 > 0) || !(t1 > 0) || f1 <= f0) return NAN;
    return std::log(t1 / t0) / std::log(f1 / f0);
}

/// Growth with size: per family and size, both engines' quality and time per triangle (adjacency
/// + strip + encode) with the exponent from the previous size, and meshoptimizer's pipeline.
std::string growth_table(const std::vector<const Row*>& rows) {
    std::ostringstream o;
    o << "| mesh | input tris";
    for (int e = 0; e < kEngines; ++e) o << " | " << ename(e) << ": extra | idx/tri | ns/tri | exponent";
    o << " | floor idx/tri | meshopt: idx/tri | ns/tri |\n|---|--:|";
    for (int e = 0; e < kEngines; ++e) o << "--:|--:|--:|--:|";
    o << "--:|--:|--:|\n";
    const Row* prev = nullptr;
    for (const Row* row : rows) {
        if (prev && prev->spec.family != row->spec.family) prev = nullptr;
        const double tri = tris(*row);
        o << "| " << row->spec.name << " | " << fmt("%.0f", tri);
        for (int e = 0; e < kEngines; ++e) {
            const EngineRun& r = row->eng[e];
            o << " | " << engine_cell(r, pct(extra(r))) << " | " << engine_cell(r, fmt("%.3f", idx_per_tri(r))) << " | "
              << engine_cell(r, fmt("%.0f", core_time(r) / tri * 1e9)) << " | " << engine_cell(r, fmt("%.2f", exponent(prev, row, e)));
        }
        o << " | " << fmt("%.3f", floor_idx(row->ref)) << " | ";
        if (row->ref.meshopt_skipped)
            o << "not run (valence " << row->ref.max_valence << ") | |\n";
        else
            o << fmt("%.3f", meshopt_idx(row->ref)) << " | " << fmt("%.0f", (row->ref.m_vcache + row->ref.m_restart) / tri * 1e9) << " |\n";
        prev = row;
    }
    return o.str();
}

std::vector<double> constraint_extras(const std::vector<Row>& rows, int e) {
    std::vector<double> v;
    for (const Row& row : rows)
        if (row.has_constraints && row.con.status == 0)
            for (int i = 0; i < row.con.cases; ++i)
                if (row.con.c[i].ok[e]) v.push_back(row.con.c[i].extra[e]);
    return v;
}

std::string constraints_table(const std::vector<Row>& rows) {
    std::ostringstream o;
    o << "| mesh | input tris | cases | constraint edges (mean)";
    for (int e = 0; e < kEngines; ++e) o << " | " << ename(e) << ": extra (median) | idx/tri (median) | verified";
    o << " |\n|---|--:|--:|--:|";
    for (int e = 0; e < kEngines; ++e) o << "--:|--:|---|";
    o << '\n';
    for (const Row& row : rows) {
        if (!row.has_constraints) continue;
        const ConstraintRun& c = row.con;
        if (c.status != 0) {
            o << "| " << row.spec.name << " | | | | " << (c.status == 1 ? "skipped: " : "failed: ") << c.message << " |\n";
            continue;
        }
        double edges = 0;
        for (int i = 0; i < c.cases; ++i) edges += c.c[i].constraint_edges;
        o << "| " << row.spec.name << " | " << c.in_tris << " | " << c.cases << " | " << fmt("%.0f", edges / c.cases);
        for (int e = 0; e < kEngines; ++e) {
            std::vector<double> x, y;
            int verified = 0, built = 0;
            std::string err;
            for (int i = 0; i < c.cases; ++i) {
                if (c.c[i].ok[e]) {
                    ++built;
                    x.push_back(c.c[i].extra[e]);
                    y.push_back(c.c[i].idx_per_tri[e]);
                    verified += c.c[i].verified[e] == 1;
                }
                if (err.empty() && c.c[i].error[e][0]) err = c.c[i].error[e];
            }
            std::replace(err.begin(), err.end(), '|', '/');
            o << " | " << pct(median(x)) << " | " << fmt("%.3f", median(y)) << " | " << verified << " of " << c.cases
              << (err.empty() ? "" : " (**" + err + "**)");
        }
        o << " |\n";
    }
    return o.str();
}

bool big_cgal(const Row& row) {
    return row.spec.kind == Kind::Cgal && ok(row) && tris(row) >= 1000;
}

/// Issue 15's targets (and the ones of issue 17 this run can measure), one line each.
std::string targets(const std::vector<Row>& rows, const Settings& cfg) {
    std::ostringstream o;
    o << "| target (issue) | measured (" << ename(0) << ", the default engine) | limit | result |\n|---|---|--:|---|\n";
    // Extra triangles: median over libcgal-demo meshes of >= 1000 triangles.
    {
        std::vector<double> x, g;
        for (const Row& row : rows)
            if (big_cgal(row)) {
                x.push_back(extra(row.eng[0]));
                g.push_back(extra(row.eng[1]));
            }
        const double m = median(x);
        o << "| median extra triangles, libcgal-demo meshes ≥ 1000 triangles (15) | " << pct2(m) << " over " << x.size() << " meshes ("
          << ename(1) << ": " << pct2(median(g)) << ") | 1.5% | " << pass_miss(m <= 1.5) << " |\n";
    }
    for (const auto& [name, lim] : std::vector<std::pair<std::string, double>>{{"fandisk.off", 2},
                                                                               {"head.off", 2},
                                                                               {"eight.off", 2},
                                                                               {"armadillo.off", 2},
                                                                               {"bunny00.off", 2},
                                                                               {"refined_elephant.off", 2},
                                                                               {"cheese.off", 4}}) {
        const Row* r = nullptr;
        for (const Row& row : rows)
            if (row.spec.kind == Kind::Cgal && row.spec.name == name) r = &row;
        if (!r || r->eng[0].status != 0) {
            o << "| extra triangles, " << name << " (15) | " << (r ? "did not run: " + std::string(r->eng[0].message) : "not in this run")
              << " | " << fmt("%.0f%%", lim) << " | " << (r ? pass_miss(false) : "–") << " |\n";
            continue;
        }
        const double x = extra(r->eng[0]);
        o << "| extra triangles, " << name << " (15) | " << pct2(x) << " (" << ename(1) << ": " << pct2(extra(r->eng[1])) << ") | "
          << fmt("%.0f%%", lim) << " | " << pass_miss(x <= lim) << " |\n";
    }
    // Awkward families: every size.
    {
        std::map<std::string, std::pair<double, std::string>> worst;
        for (const Row& row : rows) {
            if (row.spec.kind != Kind::Awkward) continue;
            const double x = row.eng[0].status == 0 ? extra(row.eng[0]) : INFINITY;
            auto& w = worst[row.spec.family];
            if (w.second.empty() || x > w.first) w = {x, row.spec.name};
        }
        for (const auto& [fam, w] : worst)
            o << "| extra triangles ≤ 10% on every awkward family, " << fam << " (15) | worst " << pct2(w.first) << " (" << w.second
              << ") | 10% | " << pass_miss(w.first <= 10) << " |\n";
    }
    {
        const std::vector<double> x = constraint_extras(rows, 0), g = constraint_extras(rows, 1);
        if (!x.empty()) {
            const double m = median(x);
            o << "| median extra triangles with random constraint polylines + source/target (15) | " << pct2(m) << " over " << x.size()
              << " cases (" << ename(1) << ": " << pct2(median(g)) << ") | 3% | " << pass_miss(m <= 3) << " |\n";
        }
    }
    // GL indices against meshoptimizer, and the gap to the swap floor.
    {
        int n = 0, pass = 0;
        std::string worst;
        double worst_d = -INFINITY;
        std::vector<double> gap;
        for (const Row& row : rows) {
            if (!big_cgal(row)) continue;
            ++n;
            const double d = idx_per_tri(row.eng[0]) - meshopt_idx(row.ref);
            pass += d <= 0;
            if (d > worst_d) {
                worst_d = d;
                worst = row.spec.name + ": " + fmt("%.3f", idx_per_tri(row.eng[0])) + " vs " + fmt("%.3f", meshopt_idx(row.ref));
            }
            gap.push_back(idx_per_tri(row.eng[0]) - floor_idx(row.ref));
        }
        if (n) {
            o << "| GL indices per triangle ≤ meshopt restart mode on every libcgal-demo mesh ≥ 1000 triangles (15) | " << pass << " of "
              << n << "; worst " << worst << " | ≤ meshopt | " << pass_miss(pass == n, std::to_string(n - pass) + " over") << " |\n";
            std::sort(gap.begin(), gap.end());
            const int within = static_cast<int>(std::count_if(gap.begin(), gap.end(), [](double g) { return g <= 0.10; }));
            o << "| gap to the swap floor, same meshes (15, aim) | median " << fmt("%.3f", median(gap)) << ", max "
              << fmt("%.3f", gap.back()) << "; " << within << " of " << n << " within 0.10 | 0.10 | "
              << pass_miss(gap.back() <= 0.10, std::to_string(n - within) + " over") << " |\n";
        }
    }
    // Strip stage: matching no slower than growth; aim 1 us per triangle.
    {
        int n = 0, pass = 0;
        double worst = 0, worst_ns = 0;
        std::string worst_name, worst_ns_name;
        for (const Row& row : rows) {
            if (!ok(row) || tris(row) < 1000 || row.eng[0].status != 0 || row.eng[1].status != 0) continue;
            ++n;
            const double q = row.eng[0].t_build / row.eng[1].t_build;
            pass += q <= 1.0;
            if (q > worst) {
                worst = q;
                worst_name = row.spec.name;
            }
            const double ns = row.eng[0].t_build / tris(row) * 1e9;
            if (tris(row) >= 100000 && ns > worst_ns) {
                worst_ns = ns;
                worst_ns_name = row.spec.name;
            }
        }
        if (n) {
            o << "| strip stage " << ename(0) << " ≤ " << ename(1) << " on the same mesh, meshes ≥ 1000 triangles (15) | " << pass << " of "
              << n << "; worst " << fmt("%.2f×", worst) << " (" << worst_name << ") | 1× | "
              << pass_miss(pass == n, std::to_string(n - pass) + " slower") << " |\n";
            if (!worst_ns_name.empty())
                o << "| strip stage per triangle, meshes ≥ 100K (15, aim) | worst " << fmt("%.0f ns", worst_ns) << " (" << worst_ns_name
                  << ") | 1000 ns | " << pass_miss(worst_ns <= 1000) << " |\n";
        }
    }
    // Linear: time per triangle at the largest size within 1.5x of 100K, per generated family.
    std::map<std::string, std::map<uint64_t, const Row*>> fam;
    for (const Row& row : rows)
        if (row.spec.nominal) fam[row.spec.family][row.spec.nominal] = &row;
    for (const auto& [name, sizes] : fam) {
        const auto a = sizes.find(100000);
        const Row* big = sizes.rbegin()->second;
        if (a == sizes.end() || big == a->second) continue;
        const char* issue = big->spec.kind == Kind::Awkward ? "17" : "15, 17";
        for (int e = 0; e < kEngines; ++e) {  // both engines: issue 17 asks linear time of each
            if (big->eng[e].status != 0 || a->second->eng[e].status != 0) {
                o << "| " << ename(e) << ": time per triangle at " << count_k(big->spec.nominal) << " ≤ 1.5× at 100K, " << name << " ("
                  << issue << ") | did not finish: " << big->eng[e].message << " | 1.5× | " << pass_miss(false) << " |\n";
                continue;
            }
            auto per = [e](const Row* r) { return core_time(r->eng[e]) / tris(*r); };
            const double q = per(big) / per(a->second);
            o << "| " << ename(e) << ": time per triangle (adjacency + strip + encode) at " << count_k(big->spec.nominal)
              << " ≤ 1.5× at 100K, " << name << " (" << issue << ") | " << fmt("%.0f", per(big) * 1e9) << " vs "
              << fmt("%.0f", per(a->second) * 1e9) << " ns = " << fmt("%.2f×", q) << " | 1.5× | " << pass_miss(q <= 1.5) << " |\n";
        }
    }
    // Peak memory at the largest scaling size.
    for (const auto& [name, sizes] : fam) {
        const Row* big = sizes.rbegin()->second;
        if (big->spec.kind != Kind::Scaling || big->spec.nominal < 1000000 || big->eng[0].status != 0) continue;
        const double bpt = big->eng[0].peak_kb * 1024.0 / tris(*big);
        const bool at10m = big->spec.nominal >= 10000000;
        o << "| peak memory at " << count_k(big->spec.nominal) << ", " << name << " (15: ≤ 120 B/tri at 10M; 17: ≤ 80) | "
          << fmt("%.0f", bpt) << " B/tri (" << fmt("%.0f", big->eng[0].peak_kb / 1024.0) << " MB)"
          << (at10m ? "" : " (10M with --with-10m)") << " | 120 / 80 B/tri | "
          << (bpt <= 80    ? pass_miss(true)
              : bpt <= 120 ? "met 120, missed 80"
                           : pass_miss(false))
          << " |\n";
    }
    // Issue 17: the default pipeline against meshoptimizer's, side by side.
    {
        int n = 0, pass1 = 0, pass2 = 0;
        double w1 = 0, w2 = 0;
        std::string n1, n2;
        for (const Row& row : rows) {
            const bool big =
                row.spec.kind == Kind::Cgal ? tris(row) >= 50000 : row.spec.kind == Kind::Scaling && row.spec.nominal >= 1000000;
            if (!big || row.eng[0].status != 0 || row.ref.status != 0) continue;
            ++n;
            const double q1 = (row.eng[0].t_adj + row.eng[0].t_build + row.eng[0].t_encode) / (row.ref.m_vcache + row.ref.m_restart);
            const double q2 = (row.eng[0].t_build + row.eng[0].t_encode) / row.ref.m_restart;
            pass1 += q1 <= 1;
            pass2 += q2 <= 5;
            if (q1 > w1) w1 = q1, n1 = row.spec.name;
            if (q2 > w2) w2 = q2, n2 = row.spec.name;
        }
        if (n) {
            o << "| adjacency + strip + encode ≤ meshopt vcache + stripify, libcgal-demo ≥ 50K and series ≥ 1M (17) | " << pass1 << " of "
              << n << "; worst " << fmt("%.2f×", w1) << " (" << n1 << ") | 1× | " << pass_miss(pass1 == n) << " |\n";
            o << "| strip + encode ≤ 5× meshopt stripify, same meshes (17) | " << pass2 << " of " << n << "; worst " << fmt("%.2f×", w2)
              << " (" << n2 << ") | 5× | " << pass_miss(pass2 == n) << " |\n";
        }
    }
    // Every result verified. A skipped input (rejected, or several components) is neither a
    // verified result nor a failure: it is counted apart.
    {
        int runs = 0, verified = 0, failed = 0, crashed = 0, skipped = 0;
        for (const Row& row : rows) {
            for (const EngineRun& e : row.eng) {
                if (e.status == 0) {
                    ++runs;
                    verified += e.verified == 1 && e.decode_ok;
                    failed += e.verified == 0 || !e.decode_ok;
                } else if (e.status == 1) {
                    ++skipped;
                } else if (e.status >= 2) {
                    ++crashed;
                }
            }
            if (!row.has_constraints) continue;
            if (row.con.status == 1) skipped += kEngines * std::min(cfg.constraint_cases, kMaxCases);
            if (row.con.status >= 2) ++crashed;
            if (row.con.status == 0)
                for (int i = 0; i < row.con.cases; ++i)
                    for (int e = 0; e < kEngines; ++e) {
                        ++runs;
                        verified += row.con.c[i].verified[e] == 1;
                        failed += row.con.c[i].verified[e] == 0 || !row.con.c[i].ok[e];
                    }
        }
        o << "| every result verified (15) | " << verified << " of " << runs << " verified, " << failed << " failed, " << crashed
          << " crashed or failed to build; " << runs - verified - failed << " over " << count_k(cfg.verify_max)
          << " triangles only decoded; " << skipped << " skipped (input rejected or several components, listed below) | 0 failures | "
          << pass_miss(failed == 0 && crashed == 0) << " |\n";
    }
    return o.str();
}

/// README's quality table: the meshes it has always shown, with both engines and meshoptimizer.
std::string readme_table(const std::vector<Row>& rows) {
    std::ostringstream o;
    o << "| mesh | input | " << ename(0) << " (default): output | extra | idx/tri | " << ename(1)
      << ": extra | idx/tri | meshopt idx/tri | paper |\n|---|--:|--:|--:|--:|--:|--:|--:|---|\n";
    const std::vector<std::pair<std::string, std::string>> show = {{"fandisk.off", "fandisk"},       {"head.off", "head (3 boundaries)"},
                                                                   {"eight.off", "eight (genus 2)"}, {"bunny00.off", "bunny00"},
                                                                   {"armadillo.off", "armadillo"},   {"cheese.off", "cheese (genus 133)"}};
    const std::map<std::string, std::string> paper = {{"fandisk.off", "16630 (+28.5%)"}, {"head.off", "3668 (+25.7%)"}};
    for (const auto& [file, label] : show)
        for (const Row& row : rows) {
            if (row.spec.kind != Kind::Cgal || row.spec.name != file || row.eng[0].status != 0) continue;
            const auto p = paper.find(file);
            o << "| " << label << " | " << row.eng[0].in_tris << " | " << row.eng[0].out_tris << " | " << fmt("%+.1f%%", extra(row.eng[0]))
              << " | " << fmt("%.3f", idx_per_tri(row.eng[0])) << " | " << engine_cell(row.eng[1], fmt("%+.1f%%", extra(row.eng[1])))
              << " | " << engine_cell(row.eng[1], fmt("%.3f", idx_per_tri(row.eng[1]))) << " | " << fmt("%.3f", meshopt_idx(row.ref))
              << " | " << (p == paper.end() ? "" : p->second) << " |\n";
        }
    return o.str();
}

/// gnuplot blocks, one per family: tris, then ns/tri (adjacency + strip + encode) per engine,
/// then meshopt's vcache + stripify; "?" where a run is missing.
void write_dat(const std::string& path, const std::vector<Row>& rows, Kind kind) {
    std::map<std::string, std::vector<const Row*>> fam;
    for (const Row& row : rows)
        if (row.spec.kind == kind && !std::isnan(tris(row))) fam[row.spec.family].push_back(&row);
    std::ofstream o(path);
    o << "# blocks per family: tris";
    for (int e = 0; e < kEngines; ++e) o << ", ns/tri " << ename(e);
    o << ", ns/tri meshopt vcache+stripify\n";
    for (const auto& [name, v] : fam) {
        o << "\"" << name << "\"\n";
        for (const Row* row : v) {
            const double t = tris(*row);
            auto val = [&](double x) { return std::isnan(x) ? std::string("?") : fmt("%.3f", x); };
            o << fmt("%.0f", t);
            for (int e = 0; e < kEngines; ++e) o << ' ' << val(core_time(row->eng[e]) / t * 1e9);
            o << ' ' << val((row->ref.m_vcache + row->ref.m_restart) / t * 1e9) << '\n';
        }
        o << "\n\n";
    }
}

int reps_for(uint64_t tris, bool quick) {
    if (quick) return tris > 200000 ? 1 : 3;
    if (tris <= 200000) return 7;
    if (tris <= 2000000) return 5;
    if (tris <= 6000000) return 3;
    return 1;
}

void usage() {
    std::cout << "usage: singlestrip_bench [--quick] [--out DIR] [--tmp DIR] [--cgal DIR] [--only SUBSTR]\n"
                 "         [--no-cgal] [--no-scaling] [--no-awkward] [--no-constraints] [--no-read] [--read-only] [--with-10m]\n"
                 "         [--max-size N] [--budget S] [--verify-max N] [--timeout S] [--mem-gb G]\n"
                 "  --quick          sizes up to 100K (1M for one family), 1-3 repetitions, 8 CGAL meshes (a smoke run)\n"
                 "  --no-read        skip the read section (read_mesh_file on generated files of each format)\n"
                 "  --read-only      only the read section\n"
                 "  --with-10m       add the 10M-triangle size to the scaling series (about 15 more minutes)\n"
                 "  --out DIR        where bench.csv, bench.md, ... go (default .)\n"
                 "  --tmp DIR        scratch for generated PLY inputs and outputs (default /tmp/singlestrip-bench)\n"
                 "  --cgal DIR       libcgal-demo meshes (default /tmp/cgaldata/data/meshes)\n"
                 "  --only S         only meshes whose name contains S\n"
                 "  --budget S       seconds of repetitions per mesh and engine (default 30, quick 4)\n"
                 "  --verify-max N   verify results of up to N triangles (default 2000000)\n"
                 "  --timeout S      per-child time limit in seconds (default 240)\n"
                 "  --mem-gb G       address-space cap per child (default 12)\n";
}

}  // namespace

int main(int argc, char** argv) {
    Settings cfg;
    bool cgal = true, scaling = true, awkward = true, constraints = true, with_10m = false, read = true;
    std::string out = ".", tmp = "/tmp/singlestrip-bench", cgal_dir = "/tmp/cgaldata/data/meshes", only;
    uint64_t max_size = 0;
    double mem_gb = 12, budget = -1;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto val = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::cerr << a << " needs a value\n";
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--quick")
            cfg.quick = true;
        else if (a == "--out")
            out = val();
        else if (a == "--tmp")
            tmp = val();
        else if (a == "--cgal")
            cgal_dir = val();
        else if (a == "--only")
            only = val();
        else if (a == "--no-cgal")
            cgal = false;
        else if (a == "--no-scaling")
            scaling = false;
        else if (a == "--no-awkward")
            awkward = false;
        else if (a == "--no-constraints")
            constraints = false;
        else if (a == "--no-read")
            read = false;
        else if (a == "--read-only")
            cgal = scaling = awkward = constraints = false;
        else if (a == "--with-10m")
            with_10m = true;
        else if (a == "--max-size")
            max_size = std::stoull(val());
        else if (a == "--budget")
            budget = std::stod(val());
        else if (a == "--verify-max")
            cfg.verify_max = std::stoull(val());
        else if (a == "--timeout")
            cfg.timeout = std::stod(val());
        else if (a == "--mem-gb")
            mem_gb = std::stod(val());
        else if (a == "-h" || a == "--help") {
            usage();
            return 0;
        } else {
            std::cerr << "unknown argument " << a << '\n';
            usage();
            return 2;
        }
    }
    cfg.budget = budget > 0 ? budget : cfg.quick ? 4 : 30;
    cfg.mem_limit = static_cast<uint64_t>(mem_gb * 1024 * 1024 * 1024);
    g_progress = isatty(2);
    fs::create_directories(out);
    fs::create_directories(tmp);

    std::vector<Spec> specs;
    std::vector<std::string> constraint_meshes;
    if (cgal) {
        std::vector<fs::path> files;
        std::error_code ec;
        for (const auto& e : fs::directory_iterator(cgal_dir, ec)) {
            std::string ext = e.path().extension().string();
            std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
            if (ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl") files.push_back(e.path());
        }
        if (ec) std::cerr << "warning: cannot list " << cgal_dir << ": " << ec.message() << '\n';
        std::sort(files.begin(), files.end());
        const std::vector<std::string> quick_set = {
            "fandisk.off",         "head.off", "eight.off", "cheese.off", "bunny00.off", "armadillo.off", "elephant-with-holes.off",
            "refined_elephant.off"};
        for (const fs::path& p : files) {
            const std::string name = p.filename().string();
            if (cfg.quick && std::find(quick_set.begin(), quick_set.end(), name) == quick_set.end()) continue;
            Spec s;
            s.kind = Kind::Cgal;
            s.family = "cgal";
            s.name = name;
            s.path = p.string();
            s.reps = cfg.quick ? 3 : 7;
            specs.push_back(s);
        }
    }
    auto add_families = [&](const std::vector<singlestrip::bench::Family>& fams, Kind kind) {
        for (const auto& f : fams) {
            for (const auto& [nominal, gen] : f.sizes) {
                if (nominal >= 10000000 && !with_10m) continue;
                if (cfg.quick && nominal > (f.quick_1m ? 1000000u : 100000u)) continue;
                if (max_size && nominal > max_size) continue;
                Spec s;
                s.kind = kind;
                s.family = f.name;
                s.name = f.name + "-" + count_k(nominal);
                s.path = (fs::path(tmp) / (s.name + ".ply")).string();
                if (f.walls) s.walls_path = (fs::path(tmp) / (s.name + ".walls.txt")).string();
                s.generate = gen;
                s.nominal = nominal;
                s.reps = reps_for(nominal, cfg.quick);
                specs.push_back(s);
            }
        }
    };
    if (scaling) add_families(singlestrip::bench::scaling_families(), Kind::Scaling);
    if (awkward) add_families(singlestrip::bench::awkward_families(), Kind::Awkward);
    if (!only.empty()) std::erase_if(specs, [&](const Spec& s) { return s.name.find(only) == std::string::npos; });

    std::vector<Row> rows;
    for (size_t i = 0; i < specs.size(); ++i) {
        const Spec& spec = specs[i];
        progress("[" + std::to_string(i + 1) + "/" + std::to_string(specs.size()) + "] " + spec.name + " ");
        Row row{spec, {}, {}, {}, false};
        const auto t0 = Clock::now();
        if (spec.generate) {
            // Generated in its own process so its memory never counts toward the measured one.
            const int st = run_child([&](int) { write_generated(spec); }, cfg.timeout, cfg.mem_limit, nullptr);
            if (st != 0) {
                row.ref.status = 3;
                set_message(row.ref, "generator failed (status " + std::to_string(st) + ")");
                rows.push_back(row);
                progress("generator failed\n");
                continue;
            }
            progress("g");
        }
        row.ref = run_pod<Reference>([&] { return measure_reference(spec, std::max(3, spec.reps), cfg.budget); }, cfg);
        progress("r");
        if (row.ref.status <= 0 || row.ref.status >= 2) {
            const std::string out_path = (fs::path(tmp) / (spec.name + ".strip.ply")).string();
            for (int e = 0; e < kEngines; ++e) {
                const auto te = Clock::now();
                row.eng[e] = run_pod<EngineRun>([&] { return measure_engine(spec, kEngine[e], out_path, cfg); }, cfg);
                row.eng[e].wall = seconds_since(te);
                progress(e + 1 < kEngines ? "|" : "");
            }
            std::error_code ec;
            fs::remove(out_path, ec);
        }
        if (constraints && spec.kind == Kind::Cgal && row.ref.status == 0 && row.ref.in_tris >= 1000) {
            row.has_constraints = true;
            row.con = run_pod<ConstraintRun>([&] { return measure_constraints(spec, cfg); }, cfg);
            progress("c");
        }
        std::error_code ec;
        if (spec.generate) fs::remove(spec.path, ec);
        if (!spec.walls_path.empty()) fs::remove(spec.walls_path, ec);
        progress(" " + fmt("%.1f s\n", seconds_since(t0)));
        rows.push_back(row);
        // Partial results survive an interrupted run.
        if ((i + 1) % 10 == 0) write_csv((fs::path(out) / "bench.csv").string(), rows);
    }

    write_csv((fs::path(out) / "bench.csv").string(), rows);
    write_constraints_csv((fs::path(out) / "constraints.csv").string(), rows);
    write_dat((fs::path(out) / "scaling.dat").string(), rows, Kind::Scaling);
    write_dat((fs::path(out) / "awkward.dat").string(), rows, Kind::Awkward);
    std::ofstream((fs::path(out) / "readme.md").string()) << readme_table(rows);

    std::vector<const Row*> ok_cgal, ok_scaling, ok_awkward, bad;
    for (const Row& row : rows) {
        const bool skipped = row.ref.status == 1 || row.eng[0].status == 1;
        bool failed = row.ref.status >= 2;
        for (const EngineRun& e : row.eng) failed |= e.status >= 2;
        if (skipped || failed) bad.push_back(&row);
        if (skipped || std::isnan(tris(row))) continue;
        (row.spec.kind == Kind::Cgal ? ok_cgal : row.spec.kind == Kind::Scaling ? ok_scaling : ok_awkward).push_back(&row);
    }
    std::ostringstream md;
    if (!rows.empty()) md << "### Targets\n\n" << targets(rows, cfg) << '\n';
    if (read) md << "### Reading (read_mesh_file, generated torus grids, page cache warm)\n\n" << read_section(tmp, cfg.quick) << '\n';
    if (!ok_cgal.empty()) {
        md << "### libcgal-demo meshes: quality\n\n" << quality_table(ok_cgal) << '\n';
        md << "### libcgal-demo meshes: time per stage\n\n" << time_table(ok_cgal, false) << '\n';
    }
    if (std::any_of(rows.begin(), rows.end(), [](const Row& r) { return r.has_constraints; })) {
        md << "### Random constraint polylines with source and target\n\n" << constraints_table(rows) << '\n';
    }
    if (!ok_scaling.empty()) {
        md << "### Scaling series: growth with size\n\n" << growth_table(ok_scaling) << '\n';
        md << "### Scaling series: time per stage\n\n" << time_table(ok_scaling, true) << '\n';
    }
    if (!ok_awkward.empty()) {
        md << "### Awkward families: growth with size\n\n" << growth_table(ok_awkward) << '\n';
        md << "### Awkward families: time per stage\n\n" << time_table(ok_awkward, true) << '\n';
    }
    if (!bad.empty()) {
        md << "### Skipped or failed inputs\n\nskipped = rejected by `read_mesh_file` or `prepare_soup` (with `orient`), as the "
              "CLI would; failed = our error; crashed = the child died or timed out.\n\n| mesh | part | status | reason |\n"
              "|---|---|---|---|\n";
        for (const Row* row : bad) {
            auto line = [&](const char* part, int status, std::string m) {
                if (status <= 0) return;
                std::replace(m.begin(), m.end(), '|', '/');
                std::replace(m.begin(), m.end(), '\n', ' ');
                if (const auto colon = m.find(": "); colon != std::string::npos && m.rfind(row->spec.path, 0) == 0) m = m.substr(colon + 2);
                const char* st = status == 1 ? "skipped" : status == 2 ? "failed" : "crashed";
                md << "| " << row->spec.name << " | " << part << " | " << st << " | " << m << " |\n";
            };
            if (row->ref.status == 1) {
                line("all", 1, row->ref.message);
                continue;
            }
            line("meshopt / floor", row->ref.status, row->ref.message);
            for (int e = 0; e < kEngines; ++e) line(ename(e), row->eng[e].status, row->eng[e].message);
        }
        md << '\n';
    }
    std::ofstream((fs::path(out) / "bench.md").string()) << md.str();
    std::cout << md.str();
    int failures = 0;
    for (const Row* row : bad)
        for (const EngineRun& e : row->eng) failures += e.status >= 2;
    return failures ? 1 : 0;
}
