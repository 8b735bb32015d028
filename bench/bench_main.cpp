// singlestrip_bench — singlestrip next to meshoptimizer on real and generated meshes.
//
// For every mesh, in ONE forked child process (so peak memory is per mesh):
//   ours:     read_mesh_file -> prepare_soup(orient) -> Mesh::from_soup -> build_strip +
//             strip_arrays + encode_triangle_strip -> write_strip_mesh (binary PLY),
//             repeated `reps` times; each stage's time is the median over the repetitions.
//             Peak memory = getrusage(RUSAGE_SELF).ru_maxrss right after the FIRST repetition,
//             in a child forked from a parent that holds no mesh (a few MB): it is the peak of
//             one full read-to-write run plus the process baseline, reported as is.
//   meshopt:  on the same (prepared) triangles: meshopt_optimizeVertexCacheStrip, then
//             meshopt_stripify with restart index 0xffffffff and with 0 (degenerate joins, as
//             documented in meshoptimizer.h 0.18); median time of each, strips, indices.
// Generated meshes are first written as binary PLY files by another child (so the generator's
// memory never counts), then read like any file.
//
// Output: <out>/bench.csv, <out>/bench.md (tables and targets), <out>/scaling.dat (gnuplot).
// Progress goes to stderr only when it is a terminal.
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
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <meshoptimizer.h>

#include "scaling.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/generators.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/validate.hpp"

namespace fs = std::filesystem;
namespace ss = singlestrip;

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}
double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

bool g_progress = false;
void progress(const std::string& s) {
    if (g_progress) std::cerr << s << std::flush;
}

struct Spec {
    std::string family;  ///< "cgal" or a scaling family name
    std::string name;
    std::string path;    ///< input file (cgal) or where the generated PLY goes
    std::function<ss::TriangleSoup()> generate;  ///< empty for files
    uint64_t nominal = 0;  ///< scaling size class (10K, ...), 0 for cgal
    int reps = 5;
};

/// Everything a child reports; POD so it can go through a pipe as bytes.
struct Result {
    int status = 0;  ///< 0 ok, 1 skipped (input rejected), 2 failed (our error), 3 crash/timeout
    char message[512] = {};
    int reps = 0;
    uint64_t in_vertices = 0, in_tris = 0, out_tris = 0, splits = 0, swaps = 0, indices = 0;
    uint64_t fundamental = 0, deferred = 0, detours = 0;
    long long genus = 0;
    uint64_t boundary_loops = 0;
    bool decode_ok = false;
    double t_read = NAN, t_check = NAN, t_adj = NAN, t_build = NAN, t_encode = NAN, t_write = NAN;
    double t_strip = NAN;  ///< build_strip + strip_arrays + encode (median of the sums)
    uint64_t peak_kb = 0;  ///< ru_maxrss after the first repetition
    uint64_t file_bytes = 0;
    // meshoptimizer
    double m_vcache = NAN, m_restart = NAN, m_degen = NAN;
    uint64_t m_restart_indices = 0, m_restart_strips = 0, m_degen_indices = 0, m_degen_strips = 0;
    // filled by the parent
    double wall = NAN;
    uint64_t child_maxrss_kb = 0;
};

void set_message(Result& r, const std::string& s) {
    std::snprintf(r.message, sizeof r.message, "%s", s.c_str());
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

Result measure(const Spec& spec, const std::string& out_path) {
    Result r;
    r.reps = spec.reps;
    std::vector<double> tr, tc, ta, tb, te, tw, ts;
    try {
        std::error_code ec;
        r.file_bytes = fs::file_size(spec.path, ec);
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
            // The mesh holds its own copy of everything: drop the soup, as a memory-aware caller would.
            soup = ss::TriangleSoup{};
            t = Clock::now();
            ss::StripResult res = ss::build_strip(std::move(mesh));
            const double build = seconds_since(t);
            t = Clock::now();
            ss::StripArrays arr = ss::strip_arrays(res);
            const std::vector<uint32_t> indices = ss::encode_triangle_strip(arr.faces);
            const double enc = seconds_since(t);
            tb.push_back(build);
            te.push_back(enc);
            ts.push_back(build + enc);
            if (rep == 0) {
                const ss::StripStats& st = res.stats;
                r.out_tris = st.output_triangles;
                r.splits = st.splits;
                r.swaps = st.swaps;
                r.fundamental = st.fundamental_triangles;
                r.deferred = st.deferred_regions;
                r.detours = st.detours;
                r.genus = st.genus;
                r.boundary_loops = st.boundary_loops;
                r.indices = indices.size();
                // Cheap sanity check (the full verifier is the test suite's job): the indices
                // decode to exactly the strip's faces.
                const std::vector<ss::Triangle> dec = ss::decode_triangle_strip(indices);
                r.decode_ok = dec.size() == arr.faces.size() && arr.faces.size() == r.out_tris &&
                              std::equal(dec.begin(), dec.end(), arr.faces.begin(), same_oriented);
            }
            res = ss::StripResult{};
            t = Clock::now();
            ss::write_strip_mesh(out_path, arr.points, arr.faces, arr.parent);
            tw.push_back(seconds_since(t));
            if (rep == 0) {
                rusage ru{};
                getrusage(RUSAGE_SELF, &ru);
                r.peak_kb = static_cast<uint64_t>(ru.ru_maxrss);
            }
            progress(".");
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
    r.t_strip = median(ts);

    // meshoptimizer on the same triangles (read and prepared again, untimed).
    try {
        ss::TriangleSoup soup = ss::prepare_soup(ss::read_mesh_file(spec.path), ss::PrepareOptions{true}, spec.path);
        const size_t nidx = soup.triangles.size() * 3, nv = soup.points.size();
        std::vector<unsigned> ib(nidx);
        for (size_t f = 0; f < soup.triangles.size(); ++f)
            for (int k = 0; k < 3; ++k) ib[3 * f + k] = soup.triangles[f][k];
        soup = ss::TriangleSoup{};
        std::vector<unsigned> opt(nidx), dst(meshopt_stripifyBound(nidx));
        std::vector<double> tv, t1, t0;
        size_t n1 = 0, n0 = 0;
        const int mreps = std::max(3, spec.reps);
        for (int rep = 0; rep < mreps; ++rep) {
            auto t = Clock::now();
            meshopt_optimizeVertexCacheStrip(opt.data(), ib.data(), nidx, nv);
            tv.push_back(seconds_since(t));
        }
        for (int rep = 0; rep < mreps; ++rep) {
            auto t = Clock::now();
            n1 = meshopt_stripify(dst.data(), opt.data(), nidx, nv, ~0u);
            t1.push_back(seconds_since(t));
        }
        r.m_restart_indices = n1;
        r.m_restart_strips = 1 + static_cast<uint64_t>(std::count(dst.begin(), dst.begin() + n1, ~0u));
        for (int rep = 0; rep < mreps; ++rep) {
            auto t = Clock::now();
            n0 = meshopt_stripify(dst.data(), opt.data(), nidx, nv, 0u);
            t0.push_back(seconds_since(t));
        }
        dst.resize(n0);
        r.m_degen_indices = n0;
        r.m_degen_strips = count_degenerate_strips(dst);
        r.m_vcache = median(tv);
        r.m_restart = median(t1);
        r.m_degen = median(t0);
    } catch (const std::exception& e) {
        r.status = 2;
        set_message(r, std::string("meshopt phase: ") + e.what());
    }
    return r;
}

/// Runs fn in a forked child with a memory cap; returns its exit status (or -signal / -999 on
/// timeout) and fills `ru`. The child's stdout is the pipe `out_fd` when given.
int run_child(const std::function<void(int)>& fn, double timeout_s, uint64_t mem_limit_bytes, rusage& ru,
              std::string* payload) {
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
            break;  // EOF: child closed the pipe (exited)
        }
        if (seconds_since(start) > timeout_s) {
            kill(pid, SIGKILL);
            timed_out = true;
            break;
        }
    }
    close(fds[0]);
    int st = 0;
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
std::string ms(double s) { return fmt(s < 0.01 ? "%.2f" : (s < 1 ? "%.1f" : "%.0f"), s * 1e3); }
std::string count_k(uint64_t n) {
    char b[32];
    if (n >= 1000000) std::snprintf(b, sizeof b, "%.2fM", n / 1e6);
    else if (n >= 10000) std::snprintf(b, sizeof b, "%.1fK", n / 1e3);
    else std::snprintf(b, sizeof b, "%llu", static_cast<unsigned long long>(n));
    return b;
}

struct Row {
    Spec spec;
    Result r;
};

double ratio_strip(const Result& r) { return r.t_strip / r.m_restart; }

void write_csv(const std::string& path, const std::vector<Row>& rows) {
    std::ofstream o(path);
    o << "family,name,nominal,status,message,reps,file_bytes,in_vertices,in_tris,out_tris,extra_pct,splits,swaps,"
         "indices,indices_per_tri,fundamental,deferred,detours,genus,boundary_loops,decode_ok,"
         "t_read_s,t_check_s,t_adjacency_s,t_build_s,t_encode_s,t_strip_s,t_write_s,peak_kb,peak_bytes_per_tri,"
         "child_maxrss_kb,meshopt_vcache_s,meshopt_restart_s,meshopt_restart_indices,meshopt_restart_strips,"
         "meshopt_degen_s,meshopt_degen_indices,meshopt_degen_strips,ratio_strip_over_stripify,wall_s\n";
    o.precision(9);
    for (const Row& row : rows) {
        const Result& r = row.r;
        std::string msg = r.message;
        std::replace(msg.begin(), msg.end(), '"', '\'');
        std::replace(msg.begin(), msg.end(), '\n', ' ');
        const double tri = static_cast<double>(r.in_tris);
        o << row.spec.family << ',' << row.spec.name << ',' << row.spec.nominal << ',' << r.status << ",\"" << msg
          << "\"," << r.reps << ',' << r.file_bytes << ',' << r.in_vertices << ',' << r.in_tris << ',' << r.out_tris
          << ',' << (r.in_tris ? 100.0 * (double(r.out_tris) - tri) / tri : NAN) << ',' << r.splits << ','
          << r.swaps << ',' << r.indices << ',' << (r.in_tris ? r.indices / tri : NAN) << ',' << r.fundamental
          << ',' << r.deferred << ',' << r.detours << ',' << r.genus << ',' << r.boundary_loops << ','
          << r.decode_ok << ',' << r.t_read << ',' << r.t_check << ',' << r.t_adj << ',' << r.t_build << ','
          << r.t_encode << ',' << r.t_strip << ',' << r.t_write << ',' << r.peak_kb << ','
          << (r.in_tris ? r.peak_kb * 1024.0 / tri : NAN) << ',' << r.child_maxrss_kb << ',' << r.m_vcache << ','
          << r.m_restart << ',' << r.m_restart_indices << ',' << r.m_restart_strips << ',' << r.m_degen << ','
          << r.m_degen_indices << ',' << r.m_degen_strips << ',' << ratio_strip(r) << ',' << r.wall << '\n';
    }
}

std::string ours_table(const std::vector<const Row*>& rows) {
    std::ostringstream o;
    o << "| mesh | input tris | output tris | extra | splits | swaps | strip idx/tri | read ms | check ms | "
         "adjacency ms | strip ms | write ms | peak MB | peak B/tri |\n"
         "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (const Row* row : rows) {
        const Result& r = row->r;
        const double tri = static_cast<double>(r.in_tris);
        o << "| " << row->spec.name << " | " << r.in_tris << " | " << r.out_tris << " | "
          << fmt("%.1f%%", 100.0 * (double(r.out_tris) - tri) / tri) << " | " << r.splits << " | " << r.swaps
          << " | " << fmt("%.3f", r.indices / tri) << (r.decode_ok ? "" : " (decode MISMATCH)") << " | "
          << ms(r.t_read) << " | " << ms(r.t_check) << " | " << ms(r.t_adj) << " | " << ms(r.t_strip) << " | "
          << ms(r.t_write) << " | " << fmt("%.0f", r.peak_kb / 1024.0) << " | "
          << fmt("%.0f", r.peak_kb * 1024.0 / tri) << " |\n";
    }
    return o.str();
}

std::string meshopt_table(const std::vector<const Row*>& rows) {
    std::ostringstream o;
    o << "| mesh | input tris | ours: strips | ours: idx/tri | ours: strip ms | meshopt vcache ms | "
         "restart: strips | restart: idx/tri | restart: ms | degenerate: strips | degenerate: idx/tri | "
         "degenerate: ms | ratio strip / stripify |\n"
         "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (const Row* row : rows) {
        const Result& r = row->r;
        const double tri = static_cast<double>(r.in_tris);
        o << "| " << row->spec.name << " | " << r.in_tris << " | 1 | " << fmt("%.3f", r.indices / tri) << " | "
          << ms(r.t_strip) << " | " << ms(r.m_vcache) << " | " << r.m_restart_strips << " | "
          << fmt("%.3f", r.m_restart_indices / tri) << " | " << ms(r.m_restart) << " | " << r.m_degen_strips
          << " | " << fmt("%.3f", r.m_degen_indices / tri) << " | " << ms(r.m_degen) << " | "
          << fmt("%.2f×", ratio_strip(r)) << " |\n";
    }
    return o.str();
}

std::string pass_miss(bool pass, const std::string& by) { return pass ? "**PASS**" : "**MISS** (" + by + ")"; }

std::string targets(const std::vector<Row>& rows, bool quick) {
    std::ostringstream o;
    o << "| target | mesh | measured | limit | result |\n|---|---|--:|--:|---|\n";
    // 1. strip <= 3x meshopt_stripify on meshes >= 50K triangles: each mesh listed.
    const Row* worst = nullptr;
    int n1 = 0, miss1 = 0;
    for (const Row& row : rows) {
        if (row.r.status != 0 || row.r.in_tris < 50000) continue;
        ++n1;
        const double q = ratio_strip(row.r);
        if (q > 3.0) {
            ++miss1;
            o << "| strip ≤ 3× meshopt_stripify | " << row.spec.name << " | " << fmt("%.2f×", q) << " | 3× | "
              << pass_miss(false, fmt("%.2f×", q / 3.0) + " over") << " |\n";
        }
        if (!worst || q > ratio_strip(worst->r)) worst = &row;
    }
    if (worst)
        o << "| strip ≤ 3× meshopt_stripify (" << n1 - miss1 << " of " << n1 << " meshes ≥ 50K pass) | worst: "
          << worst->spec.name << " | " << fmt("%.2f×", ratio_strip(worst->r)) << " | 3× | "
          << pass_miss(miss1 == 0, std::to_string(miss1) + " meshes over") << " |\n";
    // 2. time per triangle at 10M within 1.5x of that at 100K, per family (adjacency + strip).
    std::map<std::string, std::map<uint64_t, const Row*>> fam;
    for (const Row& row : rows)
        if (row.spec.nominal && row.r.status == 0) fam[row.spec.family][row.spec.nominal] = &row;
    const uint64_t big = quick ? 1000000 : 10000000;
    for (const auto& [name, sizes] : fam) {
        auto a = sizes.find(100000), b = sizes.find(big);
        if (a == sizes.end() || b == sizes.end()) {
            // A timed-out or crashed big run is a miss, not a gap.
            const Row* dead = nullptr;
            for (const Row& row : rows)
                if (row.spec.family == name && row.spec.nominal == big && row.r.status != 0) dead = &row;
            o << "| time/tri at " << count_k(big) << " ≤ 1.5× at 100K | " << name << " | "
              << (dead ? std::string(dead->r.message) : std::string("–")) << " | 1.5× | "
              << (dead ? pass_miss(false, "did not finish") : std::string("not measured")) << " |\n";
            continue;
        }
        auto per = [](const Result& r) { return (r.t_adj + r.t_strip) / double(r.in_tris); };
        const double q = per(b->second->r) / per(a->second->r);
        o << "| time/tri (adjacency + strip) at " << count_k(big) << " ≤ 1.5× at 100K | " << name << " | "
          << fmt("%.0f", per(b->second->r) * 1e9) << " vs " << fmt("%.0f", per(a->second->r) * 1e9)
          << " ns = " << fmt("%.2f×", q) << " | 1.5× | " << pass_miss(q <= 1.5, fmt("%.2f×", q / 1.5) + " over")
          << " |\n";
    }
    // 3. peak memory <= 120 B per input triangle at 10M; 4. 10M binary PLY read <= 3 s.
    for (const auto& [name, sizes] : fam) {
        auto b = sizes.find(big);
        if (b == sizes.end()) continue;
        const Result& r = b->second->r;
        const double bpt = r.peak_kb * 1024.0 / double(r.in_tris);
        o << "| peak memory ≤ 120 B/tri at " << count_k(big) << " | " << b->second->spec.name << " | "
          << fmt("%.0f", bpt) << " B/tri (" << fmt("%.0f", r.peak_kb / 1024.0) << " MB) | 120 B/tri | "
          << pass_miss(bpt <= 120, fmt("%.2f×", bpt / 120) + " of the limit") << " |\n";
    }
    for (const auto& [name, sizes] : fam) {
        auto b = sizes.find(big);
        if (b == sizes.end()) continue;
        const Result& r = b->second->r;
        const double lim = quick ? 0.3 : 3.0;
        o << "| binary PLY read of " << count_k(big) << " tris ≤ " << fmt("%.1f", lim) << " s | "
          << b->second->spec.name << " (" << fmt("%.0f", r.file_bytes / 1e6) << " MB) | "
          << fmt("%.2f s", r.t_read) << " | " << fmt("%.1f s", lim) << " | "
          << pass_miss(r.t_read <= lim, fmt("%.2f×", r.t_read / lim) + " of the limit") << " |\n";
    }
    return o.str();
}

void write_scaling_dat(const std::string& path, const std::vector<Row>& rows) {
    std::map<std::string, std::vector<const Row*>> fam;
    for (const Row& row : rows)
        if (row.spec.nominal && row.r.status == 0) fam[row.spec.family].push_back(&row);
    std::ofstream o(path);
    o << "# blocks per family (gnuplot index): tris, ns/tri adjacency+strip, ns/tri strip, ns/tri read, "
         "ns/tri meshopt_stripify, ns/tri meshopt vcache+stripify\n";
    for (const auto& [name, v] : fam) {
        o << "\"" << name << "\"\n";
        for (const Row* row : v) {
            const Result& r = row->r;
            const double t = double(r.in_tris);
            o << r.in_tris << ' ' << (r.t_adj + r.t_strip) / t * 1e9 << ' ' << r.t_strip / t * 1e9 << ' '
              << r.t_read / t * 1e9 << ' ' << r.m_restart / t * 1e9 << ' ' << (r.m_vcache + r.m_restart) / t * 1e9
              << '\n';
        }
        o << "\n\n";
    }
}

struct Family {
    std::string name;
    std::vector<std::pair<uint64_t, std::function<ss::TriangleSoup()>>> sizes;
};

std::vector<Family> scaling_families() {
    using S = ss::TriangleSoup;
    auto sphere = [](uint32_t n) { return [n]() -> S { return singlestrip::bench::make_geodesic_sphere(n); }; };
    auto torus = [](uint32_t a, uint32_t b) { return [a, b]() -> S { return ss::make_torus(a, b); }; };
    auto genus = [](uint32_t r) { return [r]() -> S { return ss::make_genus_surface(20, r); }; };
    auto holes = [](uint32_t r) { return [r]() -> S { return ss::make_disk_with_holes(1000, r); }; };
    // Parameters chosen so F is near 10K / 100K / 1M / 4M / 10M (exact counts are in the tables).
    return {
        {"sphere", {{10000, sphere(22)}, {100000, sphere(71)}, {1000000, sphere(224)}, {4000000, sphere(447)},
                    {10000000, sphere(707)}}},
        {"torus", {{10000, torus(100, 50)}, {100000, torus(316, 158)}, {1000000, torus(1000, 500)},
                   {4000000, torus(2000, 1000)}, {10000000, torus(3162, 1581)}}},
        {"genus20", {{10000, genus(5)}, {100000, genus(15)}, {1000000, genus(49)}, {4000000, genus(98)},
                     {10000000, genus(155)}}},
        {"holes1000", {{10000, holes(1)}, {100000, holes(3)}, {1000000, holes(10)}, {4000000, holes(20)},
                       {10000000, holes(32)}}},
    };
}

int reps_for(uint64_t tris, bool quick) {
    if (quick) return tris > 200000 ? 1 : 3;
    if (tris <= 200000) return 7;
    if (tris <= 2000000) return 5;
    if (tris <= 6000000) return 3;
    return 1;  // 10M: one timed run (the stages take minutes); meshopt still gets 3
}

void usage() {
    std::cout << "usage: singlestrip_bench [--quick] [--out DIR] [--tmp DIR] [--cgal DIR] [--only SUBSTR]\n"
                 "                         [--no-cgal] [--no-scaling] [--max-size N] [--timeout S] [--mem-gb G]\n"
                 "  --quick      sizes up to 1M, 1-3 repetitions, 8 CGAL meshes (a smoke run)\n"
                 "  --out DIR    where bench.csv, bench.md, scaling.dat go (default .)\n"
                 "  --tmp DIR    scratch for generated PLY inputs and outputs (default /tmp/singlestrip-bench)\n"
                 "  --cgal DIR   libcgal-demo meshes (default /tmp/cgaldata/data/meshes)\n"
                 "  --only S     only meshes whose name contains S\n"
                 "  --timeout S  per-mesh time limit in seconds (default 1800)\n"
                 "  --mem-gb G   address-space cap per mesh process (default 12)\n";
}

}  // namespace

int main(int argc, char** argv) {
    bool quick = false, cgal = true, scaling = true;
    std::string out = ".", tmp = "/tmp/singlestrip-bench", cgal_dir = "/tmp/cgaldata/data/meshes", only;
    uint64_t max_size = 0;
    double timeout = 1800, mem_gb = 12;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto val = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::cerr << a << " needs a value\n";
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--quick") quick = true;
        else if (a == "--out") out = val();
        else if (a == "--tmp") tmp = val();
        else if (a == "--cgal") cgal_dir = val();
        else if (a == "--only") only = val();
        else if (a == "--no-cgal") cgal = false;
        else if (a == "--no-scaling") scaling = false;
        else if (a == "--max-size") max_size = std::stoull(val());
        else if (a == "--timeout") timeout = std::stod(val());
        else if (a == "--mem-gb") mem_gb = std::stod(val());
        else if (a == "-h" || a == "--help") {
            usage();
            return 0;
        } else {
            std::cerr << "unknown argument " << a << '\n';
            usage();
            return 2;
        }
    }
    g_progress = isatty(2);
    fs::create_directories(out);
    fs::create_directories(tmp);

    std::vector<Spec> specs;
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
        const std::vector<std::string> quick_set = {"fandisk.off", "head.off", "eight.off", "cheese.off",
                                                    "bunny00.off", "armadillo.off", "elephant-with-holes.off",
                                                    "turbine.off"};
        for (const fs::path& p : files) {
            const std::string name = p.filename().string();
            if (quick && std::find(quick_set.begin(), quick_set.end(), name) == quick_set.end()) continue;
            Spec s;
            s.family = "cgal";
            s.name = name;
            s.path = p.string();
            const uint64_t sz = fs::file_size(p, ec);
            s.reps = quick ? 3 : (sz > 20'000'000 ? 5 : 7);
            specs.push_back(s);
        }
    }
    if (scaling) {
        for (const Family& f : scaling_families()) {
            for (const auto& [nominal, gen] : f.sizes) {
                if (quick && nominal > 1000000) continue;
                if (max_size && nominal > max_size) continue;
                Spec s;
                s.family = f.name;
                s.name = f.name + "-" + count_k(nominal);
                s.path = (fs::path(tmp) / (s.name + ".ply")).string();
                s.generate = gen;
                s.nominal = nominal;
                s.reps = reps_for(nominal, quick);
                specs.push_back(s);
            }
        }
    }
    if (!only.empty())
        std::erase_if(specs, [&](const Spec& s) { return s.name.find(only) == std::string::npos; });

    const uint64_t mem_limit = static_cast<uint64_t>(mem_gb * 1024 * 1024 * 1024);
    std::vector<Row> rows;
    for (size_t i = 0; i < specs.size(); ++i) {
        const Spec& spec = specs[i];
        progress("[" + std::to_string(i + 1) + "/" + std::to_string(specs.size()) + "] " + spec.name + " ");
        Row row{spec, {}};
        rusage ru{};
        if (spec.generate) {
            // Generate in its own process so its memory never counts toward the measured one.
            const int st = run_child(
                [&](int) { singlestrip::bench::write_binary_ply(spec.path, spec.generate()); }, timeout, mem_limit,
                ru, nullptr);
            if (st != 0) {
                row.r.status = 3;
                set_message(row.r, "generator failed (status " + std::to_string(st) + ")");
                rows.push_back(row);
                progress("generator failed\n");
                continue;
            }
            progress("g");
        }
        const std::string out_path = (fs::path(tmp) / (spec.name + ".strip.ply")).string();
        std::string payload;
        const auto t0 = Clock::now();
        const int st = run_child(
            [&](int fd) {
                const Result r = measure(spec, out_path);
                const char* p = reinterpret_cast<const char*>(&r);
                size_t left = sizeof r;
                while (left) {
                    const ssize_t n = write(fd, p, left);
                    if (n <= 0) break;
                    p += n;
                    left -= static_cast<size_t>(n);
                }
            },
            timeout, mem_limit, ru, &payload);
        if (st == 0 && payload.size() == sizeof(Result)) {
            std::memcpy(&row.r, payload.data(), sizeof(Result));
        } else {
            row.r.status = 3;
            set_message(row.r, st == -999 ? "timeout after " + fmt("%.0f", timeout) + " s"
                                          : "child died (status " + std::to_string(st) + ")");
        }
        row.r.wall = seconds_since(t0);
        row.r.child_maxrss_kb = static_cast<uint64_t>(ru.ru_maxrss);
        std::error_code ec;
        fs::remove(out_path, ec);
        if (spec.generate) fs::remove(spec.path, ec);
        progress(row.r.status == 0 ? " " + fmt("%.1f s\n", row.r.wall) : std::string(" ") + row.r.message + "\n");
        rows.push_back(row);
    }

    write_csv((fs::path(out) / "bench.csv").string(), rows);
    write_scaling_dat((fs::path(out) / "scaling.dat").string(), rows);

    std::ostringstream md;
    std::vector<const Row*> ok_cgal, ok_scaling, bad;
    for (const Row& row : rows) {
        if (row.r.status != 0) bad.push_back(&row);
        else (row.spec.nominal ? ok_scaling : ok_cgal).push_back(&row);
    }
    md << "### Targets\n\n" << targets(rows, quick) << '\n';
    if (!ok_cgal.empty()) {
        md << "### libcgal-demo meshes: singlestrip\n\n" << ours_table(ok_cgal) << '\n';
        md << "### libcgal-demo meshes: next to meshoptimizer\n\n" << meshopt_table(ok_cgal) << '\n';
    }
    if (!ok_scaling.empty()) {
        md << "### Scaling series: singlestrip\n\n" << ours_table(ok_scaling) << '\n';
        md << "### Scaling series: next to meshoptimizer\n\n" << meshopt_table(ok_scaling) << '\n';
    }
    if (!bad.empty()) {
        md << "### Skipped or failed inputs\n\nskipped = rejected by `read_mesh_file` or `prepare_soup` (with `orient`), as the CLI "
              "would; failed = our error; crashed = the child died or timed out.\n\n| mesh | status | reason |\n"
              "|---|---|---|\n";
        for (const Row* row : bad) {
            std::string m = row->r.message;
            std::replace(m.begin(), m.end(), '|', '/');
            std::replace(m.begin(), m.end(), '\n', ' ');
            if (const auto slash = m.find(": "); slash != std::string::npos && m.rfind(row->spec.path, 0) == 0)
                m = m.substr(slash + 2);
            const char* st = row->r.status == 1 ? "skipped" : row->r.status == 2 ? "failed" : "crashed";
            md << "| " << row->spec.name << " | " << st << " | " << m << " |\n";
        }
        md << '\n';
    }
    std::ofstream((fs::path(out) / "bench.md").string()) << md.str();
    std::cout << md.str();
    int failures = 0;
    for (const Row* row : bad) failures += row->r.status >= 2;
    return failures ? 1 : 0;
}
