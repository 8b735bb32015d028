// singlestrip_bench — the measurements, each run in a forked child: one engine's repetitions
// (read -> prepare -> build -> encode -> write, peak memory, verified), the meshoptimizer
// reference and swap floor, and random constraint polylines on both engines.
#include <fcntl.h>
#include <malloc.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>
#include <limits>

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
#include "singlestrip/pipeline.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/validate.hpp"
#include "singlestrip/verify.hpp"

namespace fs = std::filesystem;

namespace singlestrip_bench {

double median(std::vector<double> v) {
    std::erase_if(v, [](double x) { return std::isnan(x); });
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

namespace {

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

/// Bridges of the dual graph (interior edges whose removal disconnects the faces) and the most of
/// them that one path of faces crosses (the diameter of the tree of 2-edge-connected pieces). A
/// strip crosses an edge at most once unless it is split, and it must enter and leave the far
/// side of every bridge that does not separate its two ends: any single strip splits at least
/// bridges − diameter of them, +2 triangles each (docs/algorithm.md, step 3). An ear's edge is
/// such a bridge. Meshes over 4M faces are skipped (diameter = bridges = 0).
void count_dual_bridges(const ss::TriangleSoup& s, uint64_t& bridges, uint64_t& diameter) {
    bridges = diameter = 0;
    const size_t nf = s.triangles.size();
    if (nf == 0 || nf > 4000000) return;
    constexpr uint32_t kNo = UINT32_MAX;
    auto key = [&](uint32_t c) {
        const ss::Triangle& t = s.triangles[c / 3];
        return uint64_t{t[c % 3]} << 32 | t[(c % 3 + 1) % 3];
    };
    std::vector<uint32_t> by_key(3 * nf), twin(3 * nf, kNo);
    std::iota(by_key.begin(), by_key.end(), 0u);
    std::sort(by_key.begin(), by_key.end(), [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
    for (uint32_t c = 0; c < 3 * nf; ++c) {
        const uint64_t k = key(c), want = (k & 0xffffffffu) << 32 | k >> 32;
        const auto it = std::lower_bound(by_key.begin(), by_key.end(), want, [&](uint32_t x, uint64_t w) { return key(x) < w; });
        if (it != by_key.end() && key(*it) == want) twin[c] = *it;
    }
    by_key = {};
    // Tarjan's lowpoints, iteratively; the entry corner of each face is not walked back.
    std::vector<uint32_t> disc(nf, 0), low(nf, 0), entry(nf, kNo);
    std::vector<uint8_t> bridge(3 * nf, 0);
    std::vector<std::pair<uint32_t, uint32_t>> stack;  // (face, next side)
    uint32_t timer = 0;
    for (uint32_t r = 0; r < nf; ++r) {
        if (disc[r]) continue;
        disc[r] = low[r] = ++timer;
        stack.assign(1, {r, 0});
        while (!stack.empty()) {
            auto& [f, k] = stack.back();
            if (k == 3) {
                const uint32_t done = f;
                stack.pop_back();
                if (stack.empty()) break;
                const uint32_t p = stack.back().first;
                low[p] = std::min(low[p], low[done]);
                if (low[done] > disc[p]) bridge[entry[done]] = bridge[twin[entry[done]]] = 1;
                continue;
            }
            const uint32_t c = 3 * f + k++;
            if (twin[c] == kNo || c == entry[f]) continue;
            const uint32_t g = twin[c] / 3;
            if (disc[g]) {
                low[f] = std::min(low[f], disc[g]);
            } else {
                disc[g] = low[g] = ++timer;
                entry[g] = twin[c];
                stack.push_back({g, 0});
            }
        }
    }
    disc = {}, low = {}, entry = {};
    // Pieces joined by non-bridge edges; then the tree of pieces and its diameter (two searches).
    std::vector<uint32_t> piece(nf, kNo), queue;
    uint32_t pieces = 0;
    for (uint32_t r = 0; r < nf; ++r) {
        if (piece[r] != kNo) continue;
        piece[r] = pieces;
        queue.assign(1, r);
        for (size_t h = 0; h < queue.size(); ++h)
            for (uint32_t c = 3 * queue[h]; c < 3 * queue[h] + 3; ++c)
                if (twin[c] != kNo && !bridge[c] && piece[twin[c] / 3] == kNo) piece[twin[c] / 3] = pieces, queue.push_back(twin[c] / 3);
        ++pieces;
    }
    std::vector<std::vector<uint32_t>> tree(pieces);
    for (uint32_t c = 0; c < 3 * nf; ++c)
        if (bridge[c]) ++bridges, tree[piece[c / 3]].push_back(piece[twin[c] / 3]);
    bridges /= 2;
    auto farthest = [&](uint32_t from, uint64_t& dist) {
        std::vector<uint32_t> d(pieces, kNo);
        d[from] = 0;
        queue.assign(1, from);
        uint32_t last = from;
        for (size_t h = 0; h < queue.size(); ++h)
            for (uint32_t q : tree[last = queue[h]])
                if (d[q] == kNo) d[q] = d[queue[h]] + 1, queue.push_back(q);
        dist = d[last];
        return last;
    };
    uint64_t ignored = 0;
    (void)farthest(farthest(0, ignored), diameter);
}

/// Interior vertices and those whose valence is not a multiple of 3. Each such vertex forces
/// half a swap in any strip (issue 15), so 1 + off3 / (2F) indices per triangle is a floor.
void count_interior_valence(const ss::TriangleSoup& s, Reference& r) {
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
    count_dual_bridges(s, r.bridges, r.bridge_path);
    r.interior = r.interior_off3 = 0;
    r.max_valence = deg.empty() ? 0 : *std::max_element(deg.begin(), deg.end());
    for (size_t v = 0; v < deg.size(); ++v) {
        if (deg[v] == 0 || boundary[v]) continue;
        ++r.interior;
        r.interior_off3 += deg[v] % 3 != 0;
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

EdgeList read_walls(const std::string& path) {
    EdgeList e;
    std::ifstream in(path);
    uint32_t a = 0, b = 0;
    while (in >> a >> b) e.push_back({a, b});
    return e;
}

/// As stripify() does when prepare_soup_components() renumbered the vertices (`origin`, the
/// given vertex of each): constraint pairs go in in that numbering ...
ss::StripOptions in_numbering(const ss::StripOptions& given, const std::vector<uint32_t>& origin) {
    if (origin.empty() || given.constraint_edges.empty()) return given;
    std::vector<uint32_t> internal(origin.size());
    for (uint32_t i = 0; i < origin.size(); ++i) internal[origin[i]] = i;
    ss::StripOptions o = given;
    for (ss::ConstraintEdge& e : o.constraint_edges) e = ss::ConstraintEdge{internal[e.a], internal[e.b], e.line};
    return o;
}

/// ... and the output comes back in the given one.
void to_given_vertices(ss::StripArrays& arr, const std::vector<uint32_t>& origin) {
    const size_t nv = origin.size();
    if (nv == 0) return;
    const std::vector<ss::Point3> first(arr.points.begin(), arr.points.begin() + static_cast<std::ptrdiff_t>(nv));
    for (size_t i = 0; i < nv; ++i) arr.points[origin[i]] = first[i];
    for (ss::Triangle& t : arr.faces)
        for (uint32_t& v : t) v = v < nv ? origin[v] : v;
}

}  // namespace

void write_generated(const Spec& spec) {
    const singlestrip::bench::Generated g = spec.generate();
    singlestrip::bench::write_binary_ply(spec.path, g.soup);
    if (!spec.walls_path.empty()) {
        std::ofstream o(spec.walls_path);
        for (const auto& [a, b] : g.walls) o << a << ' ' << b << '\n';
        if (!o) throw ss::OutputError(spec.walls_path + ": write failed");
    }
}

/// Peak memory (KB) as the CLI has it: read, stripify() with the soup given up, write, with the
/// CLI's mmap threshold. In a child of its own: the threshold would slow the timed repetitions
/// below (every large array a fresh mapping), and they hold the soup beside the mesh and a copy
/// of the points, which the tool never does. 0 on failure.
uint64_t tool_peak_kb(const std::string& path, const ss::StripOptions& strip, bool cycles) {
    const std::string out = path + ".peak.ply";
    const pid_t pid = fork();
    if (pid < 0) return 0;
    if (pid == 0) {
        mallopt(M_MMAP_THRESHOLD, 1 << 20);
        int code = 0;
        try {
            ss::PipelineOptions o;
            o.strip = strip;
            o.orient = true;
            o.cycles = cycles;
            o.release_intermediates = true;
            o.name = path;
            const ss::PipelineResult pr = ss::stripify(ss::read_mesh_file(path), o);
            ss::write_strip_mesh(out, pr.arrays.points, pr.arrays.faces, pr.arrays.parent);
        } catch (const std::exception&) {
            code = 1;
        }
        std::remove(out.c_str());
        _exit(code);
    }
    int status = 0;
    rusage ru{};
    if (wait4(pid, &status, 0, &ru) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return 0;
    return static_cast<uint64_t>(ru.ru_maxrss);
}

namespace {

/// One pass as the CLI makes it, each stage timed: read -> prepare_soup_components(orient) ->
/// Mesh::from_soup (with the checks' edge pairing, one component) -> build_strip -> strip_arrays + encode_triangle_strip. status 1: the
/// input was rejected (skipped, not failed); 2: our error. Other exceptions propagate.
struct Pass {
    int status = 0;
    std::string message;
    double read = 0, check = 0, adj = 0, build = 0, encode = 0, cycles = NAN;
    uint64_t in_vertices = 0, in_tris = 0, num_cycles = 0;
    ss::StripStats stats;
    ss::StripArrays arr;
    std::vector<uint32_t> indices;
};

Pass strip_once(const Spec& spec, const ss::StripOptions& options, bool cycles = false) {
    Pass p;
    auto t = Clock::now();
    ss::TriangleSoup soup;
    try {
        soup = ss::read_mesh_file(spec.path);
    } catch (const ss::InputError& e) {
        p.status = 1;  // a file the reader rejects (e.g. a point cloud) is skipped, not failed
        p.message = e.what();
        return p;
    }
    p.read = seconds_since(t);
    t = Clock::now();
    // As stripify() does: a large shuffled soup is checked and stripped in a Z-order.
    std::vector<uint32_t> origin, vertex_origin, twin;
    try {
        ss::PreparedSoup prepared = ss::prepare_soup_components(std::move(soup), ss::PrepareOptions{true, true, true}, spec.path);
        soup = std::move(prepared.soup);
        origin = std::move(prepared.face_origin);
        vertex_origin = std::move(prepared.vertex_origin);
        twin = std::move(prepared.twin);
    } catch (const ss::InputError& e) {
        p.status = 1;
        p.message = e.what();
        return p;
    }
    p.check = seconds_since(t);
    p.in_vertices = soup.points.size();
    p.in_tris = soup.triangles.size();
    t = Clock::now();
    ss::Mesh mesh = twin.empty() ? ss::Mesh::from_soup(soup) : ss::Mesh::from_soup(soup, std::move(twin));
    p.adj = seconds_since(t);
    if (const uint32_t parts = mesh.num_components(); parts > 1) {  // timed here as one strip
        p.status = 1;
        p.message = std::to_string(parts) + " edge-connected components (the bench times one strip; stripify() strips each)";
        return p;
    }
    // The mesh holds its own copy of everything: drop the soup, as a memory-aware caller would.
    soup = ss::TriangleSoup{};
    t = Clock::now();
    ss::StripResult res = ss::build_strip(std::move(mesh), in_numbering(options, vertex_origin));
    p.build = seconds_since(t);
    if (cycles) {  // as the pipeline does: on the strip, before the arrays take it
        t = Clock::now();
        p.num_cycles = ss::compute_fundamental_cycles(res).cycles.size();
        p.cycles = seconds_since(t);
    }
    t = Clock::now();
    p.arr = ss::strip_arrays(std::move(res));  // as stripify() does: the points are moved, not copied
    for (uint32_t& f : p.arr.parent)
        if (!origin.empty()) f = origin[f];
    to_given_vertices(p.arr, vertex_origin);
    p.indices = ss::encode_triangle_strip(p.arr.faces);
    p.encode = seconds_since(t);
    p.stats = res.stats;
    return p;
}

ss::StripOptions engine_options(const Spec& spec, ss::StripEngine engine) {
    ss::StripOptions options;
    options.engine = engine;
    if (!spec.walls_path.empty()) options.constraint_edges = ss::as_constraints(read_walls(spec.walls_path));
    return options;
}

}  // namespace

EngineRun measure_engine(const Spec& spec, ss::StripEngine engine, const std::string& out_path, const Settings& cfg) {
    EngineRun r;
    std::vector<double> tr, tc, ta, tb, te, tw, tt;
    ss::StripArrays last;
    std::vector<uint32_t> last_indices;
    const ss::StripOptions options = engine_options(spec, engine);
    // Both peaks here, from the same parent state: a child forked later inherits the heap the
    // repetitions grew, and its peak counts those pages too (100K faces: 11 MB became 20 MB).
    r.peak_kb = tool_peak_kb(spec.path, options, false);
    if (spec.has_cycles) r.peak_kb_cycles = tool_peak_kb(spec.path, options, true);
    const auto start = Clock::now();
    try {
        for (int rep = 0; rep < spec.reps; ++rep) {
            Pass p = strip_once(spec, options);
            if (p.status != 0) {
                r.status = p.status;
                set_message(r, p.message);
                return r;
            }
            tr.push_back(p.read);
            tc.push_back(p.check);
            ta.push_back(p.adj);
            tb.push_back(p.build);
            te.push_back(p.encode);
            if (rep == 0) {
                r.in_vertices = p.in_vertices;
                r.in_tris = p.in_tris;
                r.t_first = p.adj + p.build + p.encode;  // a fresh process: every array newly mapped
                const ss::StripStats& st = p.stats;
                r.out_tris = st.output_triangles;
                r.splits = st.splits;
                r.swaps = st.swaps;
                r.loops = st.loops;
                r.fundamental = st.fundamental_triangles;
                r.deferred = st.deferred_regions;
                r.detours = st.detours;
                r.genus = st.genus;
                r.boundary_loops = st.boundary_loops;
                r.indices = p.indices.size();
                const std::vector<ss::Triangle> dec = ss::decode_triangle_strip(p.indices);
                r.decode_ok = dec.size() == p.arr.faces.size() && p.arr.faces.size() == r.out_tris &&
                              std::equal(dec.begin(), dec.end(), p.arr.faces.begin(), same_oriented);
            }
            const auto t = Clock::now();
            ss::write_strip_mesh(out_path, p.arr.points, p.arr.faces, p.arr.parent);
            tw.push_back(seconds_since(t));
            tt.push_back(tr.back() + tc.back() + ta.back() + tb.back() + te.back() + tw.back());
            last = std::move(p.arr);
            last_indices = std::move(p.indices);
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
    if (spec.has_cycles) {
        try {
            std::vector<double> tcyc;  // median of up to 3 passes: one caught a load spike
            for (const auto t0 = Clock::now(); tcyc.size() < 3 && (tcyc.empty() || seconds_since(t0) < 2.0);) {
                const Pass p = strip_once(spec, options, true);
                r.cycles = p.num_cycles, tcyc.push_back(p.cycles);
            }
            r.t_cycles = median(tcyc);
        } catch (const std::exception& e) {
            r.status = 2;
            set_message(r, std::string("--cycles: ") + e.what());
            return r;
        }
    }
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

CoreRuns measure_core_runs(const Spec& spec, ss::StripEngine engine, int passes, bool keep_memory, double budget) {
    if (keep_memory) {  // every block from the heap, which keeps what is freed
        mallopt(M_MMAP_MAX, 0);
        mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
    }
    CoreRuns r;
    std::vector<double> later;
    try {
        const ss::StripOptions options = engine_options(spec, engine);
        const auto start = Clock::now();
        for (int i = 0; i < passes && (i < 3 || seconds_since(start) < budget); ++i) {
            const Pass p = strip_once(spec, options);
            r.status = p.status;
            set_message(r, p.message);
            if (p.status != 0) return r;
            (i == 0 ? r.first : later.emplace_back()) = p.adj + p.build + p.encode;
        }
    } catch (const std::exception& e) {
        r.status = 2;
        set_message(r, e.what());
        return r;
    }
    if (!later.empty()) r.warm = median(later);
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
        count_interior_valence(soup, r);
        {
            const ss::Mesh mesh = ss::Mesh::from_soup(soup);
            const long long chi = mesh.euler_characteristic();
            r.cycle_rank = mesh.num_components() == 1 && chi < 1 ? static_cast<uint64_t>(1 - chi) : 0;
        }
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

namespace {

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

}  // namespace

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

}  // namespace singlestrip_bench
