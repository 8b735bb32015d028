// singlestrip — batch mode: many input files stripped on all cores (app layer: the CLI's
// `strip --out-dir`; the library has no notion of a run over files).
//
// `singlestrip strip A.obj B.ply ... --out-dir DIR` runs run_batch(). Each input gets its own
// result file and JSON report in DIR; a bad file is reported and does not stop the others.
//
// Naming. DIR/<stem>.<format> (result), DIR/<stem>.report.json, and with options
// DIR/<stem>.indices.txt and DIR/<stem>.cycles.json, where <stem> is the input's file name
// without its extension ("builtin:genus2" -> "builtin_genus2"). When two inputs share a stem, the
// later ones (in command-line order) get "<stem>-2", "<stem>-3", ... so no output is overwritten;
// the item's `renamed_from` then names the earlier input whose stem it shares and the summary says
// so. An output that would overwrite one of the inputs (e.g. --out-dir . on a.ply with format ply)
// stops the run before any work (RequestError). With `write_path`, DIR/<stem>.route.csv
// (route.hpp).
//
// Each file is processed exactly like `singlestrip strip` on that file (read_input, stripify()
// of pipeline.hpp, write atomically); the report (report.hpp) has the same keys as the CLI's
// --report plus "ok"/"error"/"exit_code", with "seconds" the file's total time. A failed file
// leaves no result of its own behind (its finished outputs are removed), but its report is
// written with the error and without an "output" key.
//
// Concurrency: files are processed by min(threads, files) std::threads pulling from a shared
// counter; results are collected in input order, so the summary is deterministic.
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "singlestrip/pipeline.hpp"

namespace singlestrip::app {

struct BatchOptions {
    std::string out_dir;         ///< created if missing
    std::string format = "ply";  ///< result extension: ply, obj, off, stl, glb or gltf
    std::string input_format;    ///< ReadOptions::format for every input (empty: by extension)
    bool write_indices = false;  ///< also <stem>.indices.txt
    bool write_path = false;     ///< also <stem>.route.csv (route.hpp)
    unsigned threads = 0;        ///< 0 = std::thread::hardware_concurrency()
    /// stripify()'s options for every file (name is the file's; cycles also writes
    /// <stem>.cycles.json; a seed face out of range fails that file). Per-file requests
    /// (constraints_file, strip.source / target / constraint_edges) must be unset.
    PipelineOptions pipeline;
};

/// Where a batch run is: called after each file (from the worker that finished it, one call at
/// a time), e.g. to draw a progress bar (ProgressBar, progress.hpp).
struct BatchProgress {
    size_t done = 0, total = 0, failed = 0;
    std::string last;  ///< the input just finished
};
using BatchProgressFn = std::function<void(const BatchProgress&)>;

/// Outcome for one input file.
struct BatchItem {
    std::string input;
    std::string output;        ///< result path (even when failed: where it would have been)
    std::string report;        ///< report path
    std::string renamed_from;  ///< non-empty: the earlier input whose stem this one shares
    bool ok = false;
    int exit_code = 0;  ///< the CLI exit code this file alone would have given (exit_codes.hpp)
    std::string error;  ///< message when !ok
    uint32_t input_triangles = 0, output_triangles = 0, splits = 0;
    size_t strip_indices = 0;
    double seconds = 0;
};

struct BatchResult {
    std::vector<BatchItem> items;  ///< in input order
    size_t failed = 0;
};

/// Processes `files` as described above. Never throws for a per-file problem (it is recorded in
/// the item); \throw RequestError for an unknown format or an output that would overwrite an
/// input, OutputError if out_dir cannot be created.
BatchResult run_batch_files(const std::vector<std::string>& files, const BatchOptions& options, const BatchProgressFn& progress = {});

/// Fixed-width summary table (one row per file, totals, failures with their messages).
std::string batch_summary_table(const BatchResult& result);

/// CLI entry point: run_batch_files(), the summary table on `out`, and the exit code: 0 if every
/// file succeeded, else the exit code of the first failed file (input order), so e.g. a bad mesh
/// gives 3. Errors of the whole run (bad format, out_dir) are thrown as for run_batch_files().
int run_batch(const std::vector<std::string>& files, const BatchOptions& options, std::ostream& out, const BatchProgressFn& progress = {});

}  // namespace singlestrip::app
