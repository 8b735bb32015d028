// Batch mode: a small thread pool over input files; see batch.hpp.
#include "app/batch.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <mutex>
#include <new>
#include <optional>
#include <ostream>
#include <sstream>
#include <thread>

#include "app/exit_codes.hpp"
#include "singlestrip/cycles.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/gltf.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/report.hpp"
#include "singlestrip/route.hpp"

namespace singlestrip::app {
namespace {

namespace fs = std::filesystem;

std::string stem_of(const std::string& input) {
    if (is_builtin_input(input)) {
        std::string s = input;
        std::replace(s.begin(), s.end(), ':', '_');
        return s;
    }
    std::string s = fs::path(input).stem().string();
    return s.empty() ? std::string("mesh") : s;
}

PipelineOptions pipeline_options(const BatchOptions& o, const std::string& input) {
    PipelineOptions p = o.pipeline;
    p.name = input;
    p.release_intermediates = true;  // only the arrays, indices, cycles and stats are written
    return p;
}

/// Writes the result of one file (and its optional files), removing what it wrote if a later
/// write fails.
void write_outputs(const BatchItem& item, const BatchOptions& o, const std::string& base, const PipelineResult& r) {
    std::vector<std::string> written;
    try {
        if (is_gltf_path(item.output))
            write_gltf_strip(item.output, r.arrays, degenerate_joined_indices(r));
        else
            write_strip_mesh(item.output, r.arrays.points, r.arrays.faces, r.arrays.parent, r.arrays.attributes);
        written.push_back(item.output);
        if (o.write_indices) {
            write_indices(base + ".indices.txt", r.indices);
            written.push_back(base + ".indices.txt");
        }
        if (r.cycles) {
            write_cycles_json(base + ".cycles.json", *r.cycles);
            written.push_back(base + ".cycles.json");
        }
        if (o.write_path) {
            write_route(base + ".route.csv", strip_route(r.arrays));
            written.push_back(base + ".route.csv");
        }
    } catch (...) {
        for (const auto& p : written) {
            std::error_code ec;
            fs::remove(p, ec);
        }
        throw;
    }
}

/// Strips one file, writes its outputs and fills the item's counts. Throws on failure.
PipelineResult process(BatchItem& item, const BatchOptions& o, const std::string& base) {
    ReadOptions read;
    read.format = o.input_format;
    PipelineResult r = stripify(read_input(item.input, read), pipeline_options(o, item.input));
    write_outputs(item, o, base, r);
    const auto& st = r.strip.stats;
    item.input_triangles = st.input_triangles;
    item.output_triangles = st.output_triangles;
    item.splits = st.splits;
    item.strip_indices = r.indices.size();
    return r;
}

/// Runs one file and records its outcome in `item`; the result is kept for the report.
std::optional<PipelineResult> run_one(BatchItem& item, const BatchOptions& o, const std::string& base) {
    std::optional<PipelineResult> result;
    try {
        result = process(item, o, base);
        item.ok = true;
    } catch (const std::exception& e) {
        item.error = error_message(e);
        item.exit_code = exit_code(e);
    }
    return result;
}

/// Writes <stem>.report.json; a file whose report cannot be written counts as failed.
void write_report(BatchItem& item, const BatchOptions& o, const PipelineResult* result) {
    const PipelineOptions requested = pipeline_options(o, item.input);
    ReportInput rep;
    rep.input = item.input;
    rep.output = item.ok ? item.output : std::string();  // a failed file has no result to name
    rep.options = result ? nullptr : &requested;
    rep.result = result;
    rep.outcome = RunOutcome{item.ok, item.exit_code, item.error, item.seconds};
    try {
        write_text_atomic(item.report, report_json(rep));
    } catch (const Error& e) {
        if (item.ok) {
            item.ok = false;
            item.error = e.what();
            item.exit_code = exit_code(e);
            std::error_code ec;
            fs::remove(item.output, ec);
        }
    }
}

/// Every file the run may write, checked against the inputs before any work.
void refuse_batch_overwrites(const std::vector<std::string>& files, const std::vector<BatchItem>& items,
                             const std::vector<std::string>& bases, const BatchOptions& o) {
    std::vector<std::pair<std::string, std::string>> inputs, outputs;
    for (const auto& f : files)
        if (!is_builtin_input(f)) inputs.emplace_back("input", f);
    for (size_t i = 0; i < items.size(); ++i) {
        outputs.emplace_back("result", items[i].output);
        outputs.emplace_back("report", items[i].report);
        if (o.write_indices) outputs.emplace_back("indices", bases[i] + ".indices.txt");
        if (o.pipeline.cycles) outputs.emplace_back("cycles", bases[i] + ".cycles.json");
        if (o.write_path) outputs.emplace_back("route", bases[i] + ".route.csv");
    }
    refuse_overwrites(inputs, outputs);
}

}  // namespace

BatchResult run_batch_files(const std::vector<std::string>& files, const BatchOptions& o, const BatchProgressFn& progress) {
    std::string fmt = ascii_lower(o.format);
    if (!fmt.empty() && fmt[0] == '.') fmt.erase(0, 1);
    if (fmt != "ply" && fmt != "obj" && fmt != "off" && fmt != "stl" && fmt != "glb" && fmt != "gltf")
        throw RequestError("batch: unknown output format '" + o.format + "' (ply, obj, off, stl, glb, gltf)");
    {
        std::error_code ec;
        fs::create_directories(o.out_dir.empty() ? fs::path(".") : fs::path(o.out_dir), ec);
        if (ec || !fs::is_directory(o.out_dir.empty() ? fs::path(".") : fs::path(o.out_dir)))
            throw OutputError(o.out_dir + ": cannot create the output directory" + (ec ? " (" + ec.message() + ")" : std::string()));
    }

    BatchResult res;
    res.items.resize(files.size());
    std::vector<std::string> bases(files.size());
    std::map<std::string, std::pair<int, size_t>> seen;  // stem -> uses, first input
    for (size_t i = 0; i < files.size(); ++i) {
        std::string stem = stem_of(files[i]);
        auto [it, fresh] = seen.try_emplace(stem, 0, i);
        const int n = ++it->second.first;
        if (n > 1) {
            stem += "-" + std::to_string(n);
            res.items[i].renamed_from = files[it->second.second];
        }
        bases[i] = (fs::path(o.out_dir) / stem).string();
        res.items[i].input = files[i];
        res.items[i].output = bases[i] + "." + fmt;
        res.items[i].report = bases[i] + ".report.json";
    }
    refuse_batch_overwrites(files, res.items, bases, o);

    std::atomic<size_t> next{0};
    std::mutex mu;
    size_t done = 0, failed = 0;
    auto worker = [&] {
        for (size_t i = next++; i < files.size(); i = next++) {
            BatchItem& item = res.items[i];
            const auto t0 = std::chrono::steady_clock::now();
            std::optional<PipelineResult> result = run_one(item, o, bases[i]);
            item.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            write_report(item, o, result ? &*result : nullptr);
            result.reset();
            std::lock_guard<std::mutex> lock(mu);
            ++done;
            failed += item.ok ? 0 : 1;
            if (progress) progress(BatchProgress{done, files.size(), failed, item.input});
        }
    };
    unsigned n = o.threads ? o.threads : std::max(1u, std::thread::hardware_concurrency());
    n = static_cast<unsigned>(std::min<size_t>(n, std::max<size_t>(files.size(), 1)));
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < n; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
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
            const double extra =
                it.input_triangles ? 100.0 * (static_cast<double>(it.output_triangles) - it.input_triangles) / it.input_triangles : 0.0;
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
                  static_cast<unsigned long long>(tout), static_cast<unsigned long long>(tsplit), static_cast<unsigned long long>(tidx),
                  tsec);
    o << line;
    for (const auto& it : r.items)
        if (!it.renamed_from.empty())
            o << "note: " << it.input << " has the same name as " << it.renamed_from << ": "
              << (it.ok ? "its results are " + it.output + " and " + it.report : "its report is " + it.report) << '\n';
    for (const auto& it : r.items)
        if (!it.ok) o << "FAILED " << it.input << " (exit " << it.exit_code << "): " << it.error << '\n';
    return o.str();
}

int run_batch(const std::vector<std::string>& files, const BatchOptions& options, std::ostream& out, const BatchProgressFn& progress) {
    const BatchResult r = run_batch_files(files, options, progress);
    out << batch_summary_table(r);
    out.flush();
    for (const auto& it : r.items)
        if (!it.ok) return it.exit_code ? it.exit_code : kExitInternal;
    return kExitOk;
}

}  // namespace singlestrip::app
