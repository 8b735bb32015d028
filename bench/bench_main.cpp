// singlestrip_bench — both strip engines next to meshoptimizer on real and generated meshes. This
// file: the options, the mesh list, a forked child per part, the output files (the parts:
// bench_measure.cpp measures, bench_report.cpp tabulates; bench_run.hpp holds what they share).
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

#include "bench_run.hpp"
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
using namespace singlestrip_bench;

namespace singlestrip_bench {

bool g_progress = false;
void progress(const std::string& s) {
    if (g_progress) std::cerr << s << std::flush;
}
namespace {

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
int reps_for(uint64_t tris, bool quick) {
    if (quick) return tris > 200000 ? 1 : 3;
    if (tris <= 200000) return 7;
    if (tris <= 2000000) return 5;
    if (tris <= 6000000) return 3;
    return 1;
}

/// Fresh and warm times of adjacency + strip + encode (EngineRun::t_cold, t_warm): a median of
/// repetitions where 100K meshes reuse heap memory and 10M ones map fresh pages every time
/// compares memory states, not sizes.
void core_runs(const Spec& spec, EngineRun& run, ss::StripEngine engine, const Settings& cfg) {
    const int passes = 1 + std::max(2, spec.reps);
    const CoreRuns warm = run_pod<CoreRuns>([&] { return measure_core_runs(spec, engine, passes, true, cfg.budget / 2); }, cfg);
    const CoreRuns fresh = run_pod<CoreRuns>([&] { return measure_core_runs(spec, engine, 1, false, 0); }, cfg);
    std::vector<double> t{run.t_first};
    for (const CoreRuns* c : {&warm, &fresh})
        if (c->status == 0) t.push_back(c->first);
    std::sort(t.begin(), t.end());
    run.t_cold = t[t.size() / 2];
    if (warm.status == 0) run.t_warm = warm.warm;
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

}  // namespace singlestrip_bench

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
        Spec& spec = specs[i];
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
            spec.has_cycles = row.ref.status == 0 && row.ref.cycle_rank > 0;
            const std::string out_path = (fs::path(tmp) / (spec.name + ".strip.ply")).string();
            for (int e = 0; e < kEngines; ++e) {
                const auto te = Clock::now();
                row.eng[e] = run_pod<EngineRun>([&] { return measure_engine(spec, kEngine[e], out_path, cfg); }, cfg);
                row.eng[e].wall = seconds_since(te);
                if (spec.generate && row.eng[e].status == 0) core_runs(spec, row.eng[e], kEngine[e], cfg);
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
    if (std::any_of(rows.begin(), rows.end(), [](const Row& r) { return r.eng[0].status == 0 && r.eng[0].cycles > 0; })) {
        md << "### `--cycles`: the fundamental cycles beside the strip stage\n\n"
              "compute_fundamental_cycles() on the strip of one more pass (each engine; the growth builder's own fundamental "
              "triangles, the matching engine's by replay), and the peak memory of a read → write run without and with "
              "`PipelineOptions::cycles`; meshes with cycles (2g + h − 1 > 0) of ≥ 10K triangles.\n\n"
           << cycles_table(rows) << '\n';
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
