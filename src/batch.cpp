// Batch mode: a small thread pool over input files; see batch.hpp.
#include "singlestrip/batch.hpp"

#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <new>
#include <ostream>
#include <sstream>
#include <thread>

#include "singlestrip/cycles.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/generators.hpp"
#include "singlestrip/gltf.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/validate.hpp"

namespace singlestrip {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

std::string stem_of(const std::string& input) {
    if (input.rfind("builtin:", 0) == 0) {
        std::string s = input;
        std::replace(s.begin(), s.end(), ':', '_');
        return s;
    }
    std::string s = fs::path(input).stem().string();
    return s.empty() ? std::string("mesh") : s;
}

TriangleSoup load(const std::string& input, const std::string& input_format) {
    if (input.rfind("builtin:", 0) == 0) {
        if (input != "builtin:genus2") throw RequestError("unknown built-in model '" + input + "' (available: builtin:genus2)");
        return make_builtin_model();
    }
    ReadOptions read;
    read.format = input_format;
    return read_mesh_file(input, read);
}

/// Strips one file; fills `item` and writes its outputs. Throws on failure (caught by caller).
void process(BatchItem& item, const BatchOptions& o, const std::string& base, json& report) {
    std::vector<std::string> written;  // removed again if a later step fails
    try {
        TriangleSoup soup = prepare_soup(load(item.input, o.input_format), PrepareOptions{o.orient}, item.input);
        StripOptions opt;
        opt.greedy = o.greedy;
        opt.seed_face = o.seed_face;
        StripResult result = build_strip(Mesh::from_soup(soup), opt);
        StripArrays arrays = strip_arrays(result);
        const std::vector<uint32_t> indices = encode_triangle_strip(arrays.faces);
        if (is_gltf_path(item.output))
            write_gltf_strip(item.output, arrays, indices);
        else
            write_strip_mesh(item.output, arrays.points, arrays.faces, arrays.parent);
        written.push_back(item.output);
        if (o.write_indices) {
            write_indices(base + ".indices.txt", indices);
            written.push_back(base + ".indices.txt");
        }
        std::size_t num_cycles = 0;
        if (o.cycles) {
            const Cycles c = compute_fundamental_cycles(result);
            num_cycles = c.cycles.size();
            write_cycles_json(base + ".cycles.json", c);
            written.push_back(base + ".cycles.json");
        }
        const auto& st = result.stats;
        item.input_triangles = st.input_triangles;
        item.output_triangles = st.output_triangles;
        item.splits = st.splits;
        item.strip_indices = indices.size();
        const double in_tris = st.input_triangles ? static_cast<double>(st.input_triangles) : 1.0;
        report["output_triangles"] = st.output_triangles;
        report["input_triangles"] = st.input_triangles;
        report["splits"] = st.splits;
        report["swaps"] = st.swaps;
        report["strip_indices"] = indices.size();
        report["genus"] = st.genus;
        report["boundary_loops"] = st.boundary_loops;
        report["fundamental_triangles"] = st.fundamental_triangles;
        report["deferred_regions"] = st.deferred_regions;
        report["indices_per_triangle"] = static_cast<double>(indices.size()) / in_tris;
        report["extra_percent"] = 100.0 * (static_cast<double>(st.output_triangles) - static_cast<double>(st.input_triangles)) / in_tris;
        if (o.cycles) report["cycles"] = num_cycles;
    } catch (...) {
        for (const auto& p : written) {
            std::error_code ec;
            fs::remove(p, ec);
        }
        throw;
    }
}

/// "\r[#####.....]  3/10  name" on stderr.
void draw_progress(size_t done, size_t total, size_t failed, const std::string& last) {
    constexpr int kWidth = 30;
    const int filled = total ? static_cast<int>(kWidth * done / total) : kWidth;
    std::string bar(static_cast<size_t>(filled), '#');
    bar.append(static_cast<size_t>(kWidth - filled), '.');
    std::string name = last.size() > 40 ? "..." + last.substr(last.size() - 37) : last;
    std::fprintf(stderr, "\r[%s] %zu/%zu%s  %-40s", bar.c_str(), done, total,
                 failed ? (" (" + std::to_string(failed) + " failed)").c_str() : "", name.c_str());
    std::fflush(stderr);
}

}  // namespace

BatchResult run_batch_files(const std::vector<std::string>& files, const BatchOptions& o) {
    std::string fmt = o.format;
    std::transform(fmt.begin(), fmt.end(), fmt.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (!fmt.empty() && fmt[0] == '.') fmt.erase(0, 1);
    if (fmt != "ply" && fmt != "obj" && fmt != "off" && fmt != "glb" && fmt != "gltf")
        throw RequestError("batch: unknown output format '" + o.format + "' (ply, obj, off, glb, gltf)");
    {
        std::error_code ec;
        fs::create_directories(o.out_dir.empty() ? fs::path(".") : fs::path(o.out_dir), ec);
        if (ec || !fs::is_directory(o.out_dir.empty() ? fs::path(".") : fs::path(o.out_dir)))
            throw OutputError(o.out_dir + ": cannot create the output directory" + (ec ? " (" + ec.message() + ")" : std::string()));
    }

    BatchResult res;
    res.items.resize(files.size());
    std::vector<std::string> bases(files.size());
    std::map<std::string, int> seen;
    for (size_t i = 0; i < files.size(); ++i) {
        std::string stem = stem_of(files[i]);
        const int n = ++seen[stem];
        if (n > 1) stem += "-" + std::to_string(n);
        bases[i] = (fs::path(o.out_dir) / stem).string();
        res.items[i].input = files[i];
        res.items[i].output = bases[i] + "." + fmt;
        res.items[i].report = bases[i] + ".report.json";
    }

    const bool show = o.progress && isatty(fileno(stderr)) && !files.empty();
    std::atomic<size_t> next{0};
    std::mutex mu;
    size_t done = 0, failed = 0;
    auto worker = [&] {
        for (size_t i = next++; i < files.size(); i = next++) {
            BatchItem& item = res.items[i];
            const auto t0 = std::chrono::steady_clock::now();
            json report;
            report["input"] = item.input;
            report["output"] = item.output;
            report["options"] = {{"greedy", o.greedy}, {"orient", o.orient}};
            if (o.seed_face) report["options"]["seed_face"] = *o.seed_face;
            try {
                process(item, o, bases[i], report);
                item.ok = true;
            } catch (const Error& e) {
                item.error = e.what();
                item.exit_code = e.exit_code();
            } catch (const std::bad_alloc&) {
                item.error = "out of memory";
                item.exit_code = kExitInternal;
            } catch (const std::exception& e) {
                item.error = std::string("internal: ") + e.what();
                item.exit_code = kExitInternal;
            }
            item.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            report["ok"] = item.ok;
            report["exit_code"] = item.exit_code;
            if (!item.ok) report["error"] = item.error;
            report["seconds"] = item.seconds;
            try {
                write_text_atomic(item.report, report.dump(2) + "\n");
            } catch (const Error& e) {
                if (item.ok) {
                    item.ok = false;
                    item.error = e.what();
                    item.exit_code = e.exit_code();
                    std::error_code ec;
                    fs::remove(item.output, ec);
                }
            }
            std::lock_guard<std::mutex> lock(mu);
            ++done;
            failed += item.ok ? 0 : 1;
            if (show) draw_progress(done, files.size(), failed, item.input);
        }
    };
    unsigned n = o.threads ? o.threads : std::max(1u, std::thread::hardware_concurrency());
    n = static_cast<unsigned>(std::min<size_t>(n, std::max<size_t>(files.size(), 1)));
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < n; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    if (show) std::fprintf(stderr, "\n");
    res.failed = failed;
    return res;
}

std::string batch_summary_table(const BatchResult& r) {
    std::ostringstream o;
    size_t w = 4;
    for (const auto& it : r.items) w = std::max(w, it.input.size());
    w = std::min<size_t>(w, 60);
    char line[512];
    std::snprintf(line, sizeof line, "%-*s  %-6s %10s %10s %8s %8s %10s %8s\n", static_cast<int>(w), "file", "status", "in tris",
                  "out tris", "splits", "extra%", "indices", "seconds");
    o << line << std::string(w + 2 + 6 + 1 + 10 + 1 + 10 + 1 + 8 + 1 + 8 + 1 + 10 + 1 + 8, '-') << '\n';
    uint64_t tin = 0, tout = 0, tsplit = 0, tidx = 0;
    double tsec = 0;
    for (const auto& it : r.items) {
        std::string name = it.input.size() > w ? "..." + it.input.substr(it.input.size() - (w - 3)) : it.input;
        if (it.ok) {
            const double extra = it.input_triangles ? 100.0 * (static_cast<double>(it.output_triangles) - it.input_triangles) / it.input_triangles : 0.0;
            std::snprintf(line, sizeof line, "%-*s  %-6s %10u %10u %8u %+7.1f%% %10zu %8.3f\n", static_cast<int>(w), name.c_str(), "ok",
                          it.input_triangles, it.output_triangles, it.splits, extra, it.strip_indices, it.seconds);
            tin += it.input_triangles, tout += it.output_triangles, tsplit += it.splits, tidx += it.strip_indices;
        } else {
            std::snprintf(line, sizeof line, "%-*s  %-6s %10s %10s %8s %8s %10s %8.3f\n", static_cast<int>(w), name.c_str(), "FAILED", "-",
                          "-", "-", "-", "-", it.seconds);
        }
        tsec += it.seconds;
        o << line;
    }
    std::snprintf(line, sizeof line, "%zu file(s): %zu ok, %zu failed; %llu -> %llu triangles, %llu splits, %llu indices, %.3f s of work\n",
                  r.items.size(), r.items.size() - r.failed, r.failed, static_cast<unsigned long long>(tin),
                  static_cast<unsigned long long>(tout), static_cast<unsigned long long>(tsplit), static_cast<unsigned long long>(tidx), tsec);
    o << line;
    for (const auto& it : r.items)
        if (!it.ok) o << "FAILED " << it.input << " (exit " << it.exit_code << "): " << it.error << '\n';
    return o.str();
}

int run_batch(const std::vector<std::string>& files, const BatchOptions& options, std::ostream& out) {
    const BatchResult r = run_batch_files(files, options);
    out << batch_summary_table(r);
    out.flush();
    for (const auto& it : r.items)
        if (!it.ok) return it.exit_code ? it.exit_code : kExitInternal;
    return kExitOk;
}

}  // namespace singlestrip
