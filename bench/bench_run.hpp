// singlestrip_bench — internal: what the bench's parts share. bench_main.cpp runs each part in a
// forked child and writes the files; bench_measure.cpp measures in the children (engines,
// meshoptimizer reference, constraint cases); bench_report.cpp turns the rows into CSV, tables
// and targets. Children report POD structs through a pipe.
#pragma once

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "families.hpp"
#include "singlestrip/strip.hpp"

namespace singlestrip_bench {

namespace ss = singlestrip;
using EdgeList = singlestrip::bench::EdgeList;

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// The median of the values that are not NaN (NaN if none).
double median(std::vector<double> v);

/// Progress on stderr (main sets g_progress when stderr is a terminal).
extern bool g_progress;
void progress(const std::string& s);

// The engines, default first: every "default engine" number in the report is engines[0].
constexpr int kEngines = 2;
inline const ss::StripEngine kEngine[kEngines] = {ss::StripEngine::Matching, ss::StripEngine::Growth};

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
    bool has_cycles = false;  ///< set from the reference (Reference::cycle_rank > 0) before the engines run
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
    /// Adjacency + strip + encode, set by the parent for generated meshes (the linearity targets
    /// compare these, like with like at every size). t_first: this child's first repetition, in
    /// a fresh process (every array newly mapped, as in a CLI run); t_cold: the median of that
    /// and two more fresh processes; t_warm: the median of passes after the first in a process
    /// whose allocator keeps freed memory (every array already mapped).
    double t_first = NAN, t_cold = NAN, t_warm = NAN;
    uint64_t peak_kb = 0;
    /// `--cycles` (issue 17: at most 2x the strip time, 1.5x the memory), measured where the
    /// surface has cycles (Spec::has_cycles): their number, compute_fundamental_cycles() on the
    /// strip of one more pass, and the peak of a read -> write run with PipelineOptions::cycles.
    uint64_t cycles = 0;
    double t_cycles = NAN;
    uint64_t peak_kb_cycles = 0;
    double wall = NAN;  ///< filled by the parent
};

struct CoreRuns {
    int status = -1;  ///< as EngineRun::status
    char message[128] = {};
    double first = NAN;  ///< adjacency + strip + encode of the process's first pass
    double warm = NAN;   ///< median of the later passes (NaN with one pass)
};

struct Reference {
    int status = -1;
    char message[384] = {};
    uint64_t file_bytes = 0, in_vertices = 0, in_tris = 0, interior = 0, interior_off3 = 0;
    uint64_t bridges = 0, bridge_path = 0;  ///< of the dual graph; the most one path crosses (count_dual_bridges)
    double t_bytes = NAN;                   ///< reading the file's bytes into memory (page cache warm)
    double m_vcache = NAN, m_restart = NAN, m_degen = NAN;
    uint64_t m_restart_indices = 0, m_restart_strips = 0, m_degen_indices = 0, m_degen_strips = 0;
    uint64_t max_valence = 0;
    uint64_t cycle_rank = 0;       ///< 2g + h - 1 = 1 - Euler characteristic: the fundamental cycles' number
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
struct Row {
    Spec spec;
    Reference ref;
    EngineRun eng[kEngines];
    ConstraintRun con;
    bool has_constraints = false;
};

// --- measuring, in a child (bench_measure.cpp) ---------------------------------------------------

/// Writes the generated mesh of `spec` (and its walls) where spec says.
void write_generated(const Spec& spec);
EngineRun measure_engine(const Spec& spec, ss::StripEngine engine, const std::string& out_path, const Settings& cfg);
/// Up to `passes` passes of adjacency + strip + encode (at least three before `budget` seconds
/// stop them), in a fresh child. keep_memory: freed memory stays with the allocator (no mmap, no
/// trim), so the passes after the first are warm.
CoreRuns measure_core_runs(const Spec& spec, ss::StripEngine engine, int passes, bool keep_memory, double budget);
Reference measure_reference(const Spec& spec, int mreps, double budget);
ConstraintRun measure_constraints(const Spec& spec, const Settings& cfg);

// --- the report (bench_report.cpp) ----------------------------------------------------------------

/// printf of one number; "–" for NaN.
std::string fmt(const char* f, double v);
/// 1.2K, 3.4M.
std::string count_k(uint64_t n);
const char* ename(int e);
/// Input triangles of the row, NaN if nothing read the mesh.
double tris(const Row& row);
void write_csv(const std::string& path, const std::vector<Row>& rows);
void write_constraints_csv(const std::string& path, const std::vector<Row>& rows);
std::string quality_table(const std::vector<const Row*>& rows);
std::string time_table(const std::vector<const Row*>& rows, bool peak);
std::string growth_table(const std::vector<const Row*>& rows);
std::string constraints_table(const std::vector<Row>& rows);
/// `--cycles` beside the strip stage, for the rows with cycles and >= 10K triangles.
std::string cycles_table(const std::vector<Row>& rows);
std::string targets(const std::vector<Row>& rows, const Settings& cfg);
std::string readme_table(const std::vector<Row>& rows);
void write_dat(const std::string& path, const std::vector<Row>& rows, Kind kind);

}  // namespace singlestrip_bench
