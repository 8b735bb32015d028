// singlestrip command line tool: info, strip (one file, or a batch with --out-dir), verify; `render`
// is its own program (singlestrip-render, render/), exec'd here so that the other commands never
// load OSMesa and LLVM.
//
// Exit codes (src/app/exit_codes.hpp): 0 ok; 2 bad command line; 3 bad input (file or mesh; also `info` on
// a mesh that is not valid for stripping); 4 request cannot be met (including outputs that would
// overwrite an input or each other); 5 verification failed; 6 internal error; 7 output could not
// be written. Errors print "singlestrip: error: <message>".
//
// "-" is standard input for INPUT (with --input-format) and standard output for one of -o (with
// --format), --indices, --report, --cycles, --cycles-obj, --path (with --path-format).
#include <CLI/CLI.hpp>

#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/batch.hpp"
#include "app/exit_codes.hpp"
#include "app/progress.hpp"
#include "singlestrip/cycles.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/gltf.hpp"
#include "singlestrip/gltf_scene.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/repair.hpp"
#include "singlestrip/report.hpp"
#include "singlestrip/route.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/validate.hpp"
#include "singlestrip/verify.hpp"

namespace ss = singlestrip;
namespace app = singlestrip::app;

namespace {

/// Seconds since `start`.
double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// INPUT "-" is standard input, whose format nothing tells.
std::string input_path(const std::string& input, const std::string& format) {
    if (input != "-") return input;
    if (format.empty()) throw ss::RequestError("reading standard input (-) needs --input-format obj, off, ply or stl");
    return "/dev/stdin";
}

/// Reads INPUT: a mesh file, "-" (standard input), or `builtin:genus2` (the demo model of
/// models.hpp). `format` is `--input-format`: INPUT's format when its name does not tell.
ss::TriangleSoup load_input(const std::string& input, const std::string& format) {
    ss::ReadOptions read;
    read.format = format;
    return ss::read_input(input_path(input, format), read);
}

/// A user vertex number (`--index-base`) as the library's 0-based one.
std::optional<uint32_t> based(const std::optional<uint32_t>& v, uint32_t base, const char* what) {
    if (!v) return v;
    return ss::from_index_base(*v, base, what);
}

/// An optional number as an optional id of kind I.
template <class I>
std::optional<I> as_id(const std::optional<uint32_t>& v) {
    return v ? std::optional<I>(I(*v)) : std::nullopt;
}

/// `--engine`: a CLI11 option whose bad value is a usage error listing the choices.
CLI::Option* add_engine_option(CLI::App* app, std::function<void(ss::StripEngine)> set, const std::string& help) {
    auto* opt = app->add_option_function<std::string>(
        "--engine", [set = std::move(set)](const std::string& name) { set(*ss::parse_engine(name)); }, help);
    opt->check(CLI::Validator(
        [](std::string& name) {
            return ss::parse_engine(name) ? std::string() : "unknown engine '" + name + "' (choices: matching, growth)";
        },
        "matching|growth"));
    return opt;
}

std::string yes_no(bool b) {
    return b ? "yes" : "no";
}

std::string info_text(const std::string& input, const ss::MeshInfo& m, long long flipped) {
    std::ostringstream o;
    o << "file:                 " << input << '\n'
      << "vertices:             " << m.vertices << " (" << m.referenced_vertices << " referenced)\n"
      << "faces:                " << m.faces << " triangles";
    if (m.polygons != m.faces) o << " (from " << m.polygons << " polygons, fan-triangulated)";
    o << '\n'
      << "edges:                " << m.edges << " (" << m.boundary_edges << " boundary, " << m.non_manifold_edges << " non-manifold)\n"
      << "components:           " << m.components;
    if (m.components > 1) {
        o << " (faces:";
        for (std::size_t i = 0; i < m.component_sizes.size() && i < 10; ++i) o << ' ' << m.component_sizes[i];
        if (m.component_sizes.size() > 10) o << " ...";
        o << ')';
    }
    o << '\n'
      << "boundary loops:       " << m.boundary_loops << '\n'
      << "Euler characteristic: " << m.euler_characteristic << '\n'
      << "genus:                " << (m.genus_valid ? std::to_string(m.genus) : std::string("n/a (not a manifold orientable surface)"))
      << '\n'
      << "unwelded vertices:    " << m.unwelded_vertices << (m.unwelded_vertices ? " (--weld or --repair merges them)\n" : "\n")
      << "orientable:           " << yes_no(m.orientable) << '\n'
      << "consistently oriented:" << ' ' << yes_no(m.oriented);
    if (flipped >= 0) o << " (after --orient flipped " << flipped << " faces)";
    o << '\n';
    if (m.problems.empty()) {
        o << "problems:             none\nvalid for stripping:  yes\n";
    } else {
        o << "problems:             " << m.problems.size() << '\n';
        for (const auto& p : m.problems) o << "  [" << p.kind << "] " << p.message << '\n';
        o << "valid for stripping:  no\n";
    }
    return o.str();
}

/// `info`, `strip`, `verify`: --weld and --repair (repair.hpp).
struct RepairArgs {
    bool weld = false, repair = false;
};

void add_repair_options(CLI::App* app, RepairArgs& r) {
    app->add_flag("--weld", r.weld, "Merge vertices with exactly equal coordinates first (always done for STL)");
    app->add_flag("--repair", r.repair,
                  "Repair first: weld, drop degenerate and duplicate faces, cut non-manifold and non-orientable parts apart, "
                  "orient (docs/repair.md)");
}

int run_info(const std::string& input, const std::string& format, bool as_json, bool orient, const RepairArgs& ra) {
    ss::TriangleSoup soup = load_input(input, format);
    std::optional<ss::RepairReport> repaired;
    if (ra.repair) {
        ss::RepairedSoup rs = ss::repair_soup(soup);
        soup = std::move(rs.soup);
        repaired = std::move(rs.report);
        std::cerr << "singlestrip: " << input << ": repair: " << repaired->summary() << '\n';
    } else if (ra.weld) {
        std::cerr << "singlestrip: " << input << ": weld: " << ss::weld_soup(soup) << " vertices merged\n";
    }
    long long flipped = -1;
    if (orient) flipped = ss::orient_soup(soup);  // -1: not orientable, reported as a problem
    const ss::MeshInfo m = ss::mesh_info(soup);
    std::vector<std::string> attributes;
    for (const auto& a : soup.attributes) attributes.push_back(a.name);
    if (as_json) {
        std::cout << ss::info_json(input, m, orient ? flipped : -1, repaired ? &*repaired : nullptr, attributes);
    } else {
        std::string text = info_text(input, m, orient ? flipped : -1);
        // Attributes split vertices at seams, which shows in the counts above: say why.
        std::string line = "attributes:          ";
        for (const auto& a : attributes) line += " " + a;
        if (!attributes.empty()) text.insert(text.find("problems:"), line + " (a vertex per position and attribute values)\n");
        std::cout << text;
    }
    return m.valid() ? app::kExitOk : app::kExitBadInput;
}

struct StripArgs {
    std::vector<std::string> inputs;
    std::string input, output;
    std::optional<std::string> indices, report, constraints, cycles, cycles_obj, out_dir, path;
    std::string format = "ply";
    std::string input_format;  ///< `--input-format`
    std::string path_format;   ///< `--path-format`: of `--path -` (default csv)
    uint32_t index_base = 0;
    unsigned jobs = 0;
    bool with_indices = false, with_cycles = false, with_path = false;
    std::optional<uint32_t> seed_face, source, target;
    bool no_greedy = false, orient = false, polish = false;
    RepairArgs fix;
    ss::JoinMode join = ss::JoinMode::Degenerate;
    uint32_t restart_index = 0xffffffffu;
    ss::StripEngine engine = ss::StripEngine::Matching;
};

/// Removes the files this run has finished if a later step fails, so no partial set of outputs
/// is left behind (each single file is already written atomically). The output named "-" is
/// written to a temporary file (the writers choose the format by extension) and copied to
/// standard output at commit(), once everything has succeeded.
class OutputSet {
public:
    /// The path to write for `path`: a temporary "<tmp>/singlestrip-stdout-<pid>.<ext>" for "-".
    std::string target(const std::string& path, const std::string& ext) {
        if (path != "-") return path;
        stdout_tmp_ = (std::filesystem::temp_directory_path() / ("singlestrip-stdout-" + std::to_string(getpid()) + "." + ext)).string();
        return stdout_tmp_;
    }
    void done(const std::string& path) { written_.push_back(path); }
    void commit() {
        if (!stdout_tmp_.empty()) {
            // Unlinked before copying: a reader that stops early (`| head`) ends this process by
            // SIGPIPE, which must not leave the temporary behind.
            std::ifstream in(stdout_tmp_, std::ios::binary);
            std::error_code ec;
            std::filesystem::remove(stdout_tmp_, ec);
            std::cout << in.rdbuf();
            std::cout.flush();
            if (!std::cout) throw ss::OutputError("standard output: write failed");
            written_.clear();
            return;
        }
        written_.clear();
    }
    ~OutputSet() {
        for (const auto& p : written_) {
            std::error_code ec;
            std::filesystem::remove(p, ec);
        }
    }

private:
    std::vector<std::string> written_;
    std::string stdout_tmp_;
};

ss::PipelineOptions pipeline_options(const StripArgs& a) {
    ss::PipelineOptions o;
    o.strip.engine = a.engine;
    o.strip.seed_face = as_id<ss::FaceId>(a.seed_face);
    o.strip.greedy = !a.no_greedy;
    o.strip.polish = a.polish;
    o.strip.source = as_id<ss::VertexId>(based(a.source, a.index_base, "--source"));
    o.strip.target = as_id<ss::VertexId>(based(a.target, a.index_base, "--target"));
    o.orient = a.orient;
    o.weld = a.fix.weld;
    o.repair = a.fix.repair;
    o.join = a.join;
    o.restart_index = a.restart_index;
    o.cycles = a.cycles || a.cycles_obj;
    o.name = a.input;
    o.constraints_file = a.constraints;
    o.index_base = a.index_base;
    o.release_intermediates = true;  // only the arrays, indices, cycles and stats are written
    return o;
}

/// Writes one output through `write(path)`, to standard output for "-".
template <class Write>
void write_one(OutputSet& outputs, const std::string& path, const std::string& ext, Write&& write) {
    const std::string target = outputs.target(path, ext);
    write(target);
    outputs.done(target);
}

/// Writes OUT and the optional files; returns the seconds spent.
double write_outputs(const StripArgs& a, const ss::PipelineResult& r, OutputSet& outputs) {
    const auto start = std::chrono::steady_clock::now();
    write_one(outputs, a.output, a.format, [&](const std::string& p) {
        if (ss::is_gltf_path(p))
            ss::write_gltf_strip(p, r.arrays, ss::degenerate_joined_indices(r));
        else
            ss::write_strip_mesh(p, r.arrays.points, r.arrays.faces, r.arrays.parent, r.arrays.attributes);
    });
    if (a.indices) write_one(outputs, *a.indices, "txt", [&](const std::string& p) { ss::write_indices(p, r.indices); });
    if (r.cycles && a.cycles) write_one(outputs, *a.cycles, "json", [&](const std::string& p) { ss::write_cycles_json(p, *r.cycles); });
    if (r.cycles && a.cycles_obj)
        write_one(outputs, *a.cycles_obj, "obj",
                  [&](const std::string& p) { ss::write_cycles_obj(p, ss::cycle_polylines(r.arrays, *r.cycles)); });
    if (a.path) {
        const ss::Route route = ss::strip_route(r.arrays);
        write_one(outputs, *a.path, a.path_format.empty() ? "csv" : a.path_format,
                  [&](const std::string& p) { ss::write_route(p, route); });
    }
    return seconds_since(start);
}

/// Checks the output names before any work: known extensions (or formats for "-"), and no
/// output that overwrites an input or another output.
void check_strip_outputs(const StripArgs& a) {
    if (a.output == "-") {
        if (a.format != "glb" && a.format != "gltf") ss::output_format_for("standard output." + a.format);
    } else if (!ss::is_gltf_path(a.output)) {
        ss::output_format_for(a.output);
    }
    if (a.path && *a.path != "-") ss::route_format_for(*a.path);
    if (a.path && *a.path == "-") ss::parse_route_format(a.path_format.empty() ? "csv" : a.path_format);
    std::vector<std::pair<std::string, std::string>> inputs{{"input", a.input}}, outputs{{"-o", a.output}};
    if (a.constraints) inputs.emplace_back("constraints file", *a.constraints);
    for (const auto& [what, p] : {std::pair{"--indices", a.indices},
                                  {"--report", a.report},
                                  {"--cycles", a.cycles},
                                  {"--cycles-obj", a.cycles_obj},
                                  {"--path", a.path}})
        if (p) outputs.emplace_back(what, *p);
    ss::refuse_overwrites(inputs, outputs);
}

/// The input's attributes that OUT's format has no place for (README, "Vertex attributes").
std::vector<std::string> attributes_not_written(const StripArgs& a, const ss::PipelineResult& r) {
    const std::string out = a.output == "-" ? "standard output." + a.format : a.output;
    std::vector<std::string> lost;
    for (const auto& at : r.arrays.attributes) {
        bool kept = ss::is_gltf_path(out);
        if (!kept) {
            const ss::OutputFormat f = ss::output_format_for(out);
            const bool common = at.name == "TEXCOORD_0" || at.name == "NORMAL" || at.name == "COLOR_0";
            kept = f == ss::OutputFormat::Ply || ((f == ss::OutputFormat::Obj || f == ss::OutputFormat::Off) && common);
        }
        if (!kept) lost.push_back(at.name);
    }
    return lost;
}

void print_summary(const std::string& input, const ss::PipelineResult& r) {
    const auto& st = r.strip.stats;
    const auto& t = r.seconds;
    if (r.repair) std::cerr << "singlestrip: " << input << ": repair: " << r.repair->summary() << '\n';
    if (r.options.weld && !r.options.repair) std::cerr << "singlestrip: " << input << ": weld: " << r.welded << " vertices merged\n";
    for (const auto& w : r.warnings) std::cerr << "singlestrip: " << input << ": warning: " << w << '\n';
    const std::string strips = r.components.size() == 1
                                   ? std::string("1 strip")
                                   : std::to_string(r.components.size()) + " strips (" + ss::join_mode_name(r.options.join) + " joins)";
    char line[640];
    std::snprintf(line, sizeof line,
                  "singlestrip: %s: %u -> %u triangles (%+.1f%%, %u splits), %s of %zu indices (%.3f per input triangle), "
                  "genus %lld, %u boundary loops; read %.3fs build %.3fs strip %.3fs write %.3fs\n",
                  input.c_str(), st.input_triangles, st.output_triangles, ss::extra_percent(st), st.splits, strips.c_str(),
                  r.indices.size(), ss::indices_per_triangle(st, r.indices.size()), st.genus, st.boundary_loops, t.read, t.build, t.strip,
                  t.write);
    std::cerr << line;
}

/// glTF in and out: every triangle primitive stripped, the rest of the scene kept (gltf.hpp).
int run_strip_gltf(const StripArgs& a) {
    if (a.indices || a.cycles || a.cycles_obj || a.constraints || a.source || a.target || a.seed_face || a.path)
        throw ss::RequestError(a.input +
                               ": a glTF scene is stripped primitive by primitive (vertex and face numbers are per primitive): "
                               "--indices, --cycles, --cycles-obj, --path, --constraints, --source, --target and --seed-face need "
                               "a .ply/.obj/.off output (all triangle primitives as one mesh)");
    const auto prims = ss::strip_gltf_file(a.input, a.output, pipeline_options(a));
    for (const auto& p : prims) {
        std::cerr << "singlestrip: " << a.input << ": mesh " << p.mesh << " primitive " << p.primitive << ": ";
        if (!p.stripped) {
            std::cerr << "kept as it was: " << p.note << '\n';
        } else {
            std::cerr << p.input_triangles << " -> " << p.output_triangles << " triangles, " << p.strips << " strip(s) of "
                      << p.strip_indices << " indices";
            if (!p.repair.empty()) std::cerr << "; repair: " << p.repair;
            std::cerr << '\n';
        }
    }
    if (a.report) ss::write_text_atomic(*a.report, ss::gltf_report_json(a.input, a.output, prims));
    return app::kExitOk;
}

int run_strip(const StripArgs& a) {
    if (ss::is_gltf_path(a.input) && ss::is_gltf_path(a.output) && a.input_format.empty()) return run_strip_gltf(a);
    // Unknown extension, overwriting: RequestError before any work.
    check_strip_outputs(a);
    const auto start = std::chrono::steady_clock::now();
    ss::TriangleSoup soup = load_input(a.input, a.input_format);
    const double t_read = seconds_since(start);
    ss::PipelineResult r = ss::stripify(std::move(soup), pipeline_options(a));
    r.seconds.read = t_read;

    OutputSet outputs;
    // "write" covers the mesh and index files; the report itself is written after measuring.
    r.seconds.write = write_outputs(a, r, outputs);
    if (a.report) {
        ss::ReportInput rep;
        rep.input = a.input;
        rep.output = a.output;
        rep.result = &r;
        rep.stage_seconds = true;
        write_one(outputs, *a.report, "json", [&](const std::string& p) { ss::write_text_atomic(p, ss::report_json(rep)); });
    }
    outputs.commit();
    print_summary(a.input, r);
    // Never drop what the input carried without a word (issue 18).
    if (const auto lost = attributes_not_written(a, r); !lost.empty()) {
        std::cerr << "singlestrip: " << a.input << ": note: " << a.output << " has no place for the vertex attributes";
        for (const auto& n : lost) std::cerr << ' ' << n;
        std::cerr << " (.ply keeps them all; .obj and .off keep TEXCOORD_0, NORMAL and COLOR_0)\n";
    }
    return app::kExitOk;
}

struct VerifyArgs {
    std::string input, output;
    std::optional<std::string> indices, constraints, cycles;
    std::optional<uint32_t> source, target;
    std::string input_format;  ///< `--input-format`
    uint32_t index_base = 0;
    RepairArgs fix;
    bool orient = false;
    uint32_t restart_index = 0xffffffffu;
};

int run_verify(const VerifyArgs& a) {
    if (std::filesystem::path(a.output).extension() == ".stl")
        throw ss::RequestError(
            a.output +
            ": verify reads .ply, .obj, .off and glTF results (STL stores float32 corners and no shared vertices to check); "
            "write a .ply with the same options to verify");
    ss::VerifyFileOptions o;
    o.indices_path = a.indices;
    o.constraints_path = a.constraints;
    o.source = based(a.source, a.index_base, "--source");
    o.target = based(a.target, a.index_base, "--target");
    o.cycles_path = a.cycles;
    o.input_format = a.input_format;
    o.index_base = a.index_base;
    o.steps = {a.fix.weld, a.fix.repair, a.orient};
    o.restart_index = a.restart_index;
    // The built-in model has no file: it is generated and checked like a read input.
    const ss::VerifyReport rep = ss::is_builtin_input(a.input) ? ss::verify_files(load_input(a.input, a.input_format), a.output, o)
                                                               : ss::verify_files(input_path(a.input, a.input_format), a.output, o);
    std::cout << rep.to_string();
    if (!rep.to_string().empty() && rep.to_string().back() != '\n') std::cout << '\n';
    return rep.ok() ? app::kExitOk : app::kExitVerifyFailed;
}

/// singlestrip-render next to this executable (build tree, install prefix), else empty (then
/// PATH is searched).
std::string render_program() {
    std::error_code ec;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    const auto candidate = self.parent_path() / "singlestrip-render";
    return std::filesystem::exists(candidate, ec) ? candidate.string() : std::string();
}

bool render_available() {
    if (!render_program().empty()) return true;
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "");
    for (std::string d; std::getline(dirs, d, ':');)
        if (!d.empty() && access((std::filesystem::path(d) / "singlestrip-render").c_str(), X_OK) == 0) return true;
    return false;
}

/// `singlestrip render ARGS` runs `singlestrip-render ARGS` in this process; returns only on failure.
int exec_render(int argc, char** argv) {
    std::vector<char*> args;
    std::string name = "singlestrip-render";
    args.push_back(name.data());
    for (int i = 2; i < argc; ++i) args.push_back(argv[i]);
    args.push_back(nullptr);
    const std::string program = render_program();
    if (!program.empty())
        execv(program.c_str(), args.data());
    else
        execvp(name.c_str(), args.data());
    std::cerr << "singlestrip: error: `render` is not available: singlestrip-render was not found next to this program or on PATH ("
              << std::strerror(errno) << "); it is built when OSMesa and libpng are installed (libosmesa6-dev, libpng-dev)\n";
    return app::kExitBadRequest;
}

constexpr const char* kCommands[] = {"info", "strip", "verify", "render"};

/// `singlestrip` alone or with an unknown first word: CLI11 would say "A subcommand is required".
std::optional<int> check_command(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "singlestrip: error: a command is required: info, strip, verify or render (see singlestrip --help)\n";
        return app::kExitUsage;
    }
    const std::string first = argv[1];
    if (first.empty() || first[0] == '-') return std::nullopt;  // --help, --version, or CLI11's own message
    for (const char* c : kCommands)
        if (first == c) return std::nullopt;
    std::cerr << "singlestrip: error: unknown command '" << first << "' (commands: info, strip, verify, render; see singlestrip --help)\n";
    return app::kExitUsage;
}

const char* const kInputFormatHelp = "Format of INPUT (obj, off, ply, stl) when its name does not tell: a pipe, or - (standard input)";
const char* const kIndexBaseHelp =
    "Vertex numbers in --constraints, --source and --target start at 0 (default; the numbering of every output file) or 1 (OBJ's)";
const char* const kInputFooter =
    "INPUT is a .obj, .off, .ply, .stl, .glb or .gltf file, - (standard input, with --input-format), or builtin:genus2 (the demo\n"
    "model).";
const char* const kExitFooter =
    "Exit codes: 0 ok, 2 usage, 3 bad input, 4 request cannot be met (including an output that would overwrite\n"
    "an input or another output), 5 verification failed, 6 internal error, 7 output not written.";

CLI::App* add_info(CLI::App& app, std::string& input, std::string& format, bool& as_json, bool& orient, RepairArgs& fix) {
    auto* info = app.add_subcommand("info", "Report counts, topology and every problem of a mesh (exit 3 if not valid for stripping)");
    info->add_option("INPUT", input, "Input mesh file, - (standard input) or builtin:genus2")->required();
    info->add_flag("--json", as_json, "Machine-readable JSON output");
    info->add_flag("--orient", orient, "Consistently re-orient an orientable mesh before reporting");
    add_repair_options(info, fix);
    info->add_option("--input-format", format, kInputFormatHelp)->check(CLI::IsMember({"obj", "off", "ply", "stl"}, CLI::ignore_case));
    info->footer(std::string(kInputFooter) + "\n" + kExitFooter);
    return info;
}

CLI::App* add_strip(CLI::App& app, StripArgs& sa) {
    auto* strip = app.add_subcommand("strip", "Turn the mesh into one triangle strip");
    strip->add_option("INPUT", sa.inputs, "Input mesh file(s), - (standard input) or builtin:genus2 (several need --out-dir)")->required();
    strip->add_option("-o,--output", sa.output,
                      "Output mesh (.ply binary with parent, .obj, .off, .stl, .glb/.gltf), faces in strip order; - for standard "
                      "output (format from --format)");
    strip->add_option("--out-dir", sa.out_dir,
                      "Batch mode: strip every INPUT on all cores into DIR (<stem>.<format> + <stem>.report.json)");
    strip->add_option("--format", sa.format, "Result format in batch mode and for -o - (ply, obj, off, stl, glb, gltf)")
        ->check(CLI::IsMember({"ply", "obj", "off", "stl", "glb", "gltf"}, CLI::ignore_case))
        ->capture_default_str();
    strip->add_option("-j,--jobs", sa.jobs, "Batch mode: worker threads (0 = all cores)");
    strip->add_flag("--with-indices", sa.with_indices, "Batch mode: also write <stem>.indices.txt");
    strip->add_flag("--with-cycles", sa.with_cycles, "Batch mode: also write <stem>.cycles.json");
    strip->add_flag("--with-path", sa.with_path, "Batch mode: also write the route as <stem>.route.csv");
    strip->add_option("--indices", sa.indices, "Write the GL_TRIANGLE_STRIP index sequence (text)");
    strip->add_option("--report", sa.report, "Write a JSON report");
    strip->add_option("--path", sa.path,
                      "Write the strip's route through face centroids and shared-edge midpoints: .csv, .json (length, per-point "
                      "face), .obj (polyline) or .geojson (LineString, flat meshes)");
    strip->add_option("--path-format", sa.path_format, "Format of --path - (standard output): csv (default), json, obj, geojson")
        ->check(CLI::IsMember({"csv", "json", "obj", "geojson"}, CLI::ignore_case));
    strip->add_option("--seed-face", sa.seed_face, "Input face (0-based triangle, after fan triangulation) to start the strip from");
    add_engine_option(
        strip, [&sa](ss::StripEngine e) { sa.engine = e; },
        "Strip engine: matching (default) or growth (the paper's builder, for comparison)");
    strip->add_flag("--no-greedy", sa.no_greedy, "Use the paper's plain same-direction turn rule");
    strip->add_flag("--polish", sa.polish,
                    "Matching engine: spend two to three times the strip time on fewer swaps (about 1% fewer GL indices)");
    strip->add_flag("--orient", sa.orient, "Consistently re-orient an orientable mesh first (each component keeps its majority)");
    add_repair_options(strip, sa.fix);
    strip
        ->add_option_function<std::string>(
            "--join", [&sa](const std::string& m) { sa.join = *ss::parse_join_mode(m); },
            "Several components: join their strips in the index file by degenerate triangles (default) or a restart index")
        ->check(CLI::IsMember({"degenerate", "restart"}));
    strip->add_option("--restart-index", sa.restart_index, "Restart index for --join restart (default 4294967295)");
    strip->add_option("--input-format", sa.input_format, kInputFormatHelp)
        ->check(CLI::IsMember({"obj", "off", "ply", "stl"}, CLI::ignore_case));
    strip->add_option("--constraints", sa.constraints, "Edges the strip must not cross: one polyline of vertex numbers per line");
    strip->add_option("--source", sa.source, "The strip starts at a face incident to this input vertex");
    strip->add_option("--target", sa.target, "The strip ends at a face incident to this input vertex");
    strip->add_option("--index-base", sa.index_base, kIndexBaseHelp)->check(CLI::IsMember({0u, 1u}))->capture_default_str();
    strip->add_option("--cycles", sa.cycles,
                      "Write the fundamental cycles (paper section 4) as JSON {\"cycles\": [[face, ...], ...], \"lengths\": [...]}");
    strip->add_option("--cycles-obj", sa.cycles_obj,
                      "Write the fundamental cycles as OBJ polylines through face centroids and shared-edge midpoints");
    strip->footer(std::string(kInputFooter) + "\n" + kExitFooter);
    return strip;
}

CLI::App* add_verify(CLI::App& app, VerifyArgs& va) {
    auto* verify = app.add_subcommand("verify", "Independently check a strip output against its input (exit 5 on failure)");
    verify->add_option("IN", va.input, "Input mesh file, - (standard input) or builtin:genus2")->required();
    verify->add_option("OUT", va.output, "Output mesh written by `singlestrip strip` (.ply, .obj, .off, or .glb/.gltf)")->required();
    verify->add_option("--indices", va.indices, "GL_TRIANGLE_STRIP index file to check against OUT");
    verify->add_option("--constraints", va.constraints, "Constraint polylines the strip must respect");
    verify->add_option("--source", va.source, "Required first-face vertex");
    verify->add_option("--target", va.target, "Required last-face vertex");
    verify->add_option("--index-base", va.index_base, kIndexBaseHelp)->check(CLI::IsMember({0u, 1u}))->capture_default_str();
    verify->add_option("--cycles", va.cycles, "Cycles JSON to check for independence");
    verify->add_option("--input-format", va.input_format, kInputFormatHelp)
        ->check(CLI::IsMember({"obj", "off", "ply", "stl"}, CLI::ignore_case));
    add_repair_options(verify, va.fix);
    verify->add_flag("--orient", va.orient, "OUT was made with --orient: check against the re-oriented input");
    verify->add_option("--restart-index", va.restart_index, "Restart index in the --indices file (default 4294967295)");
    verify->footer(kExitFooter);
    return verify;
}

int run_batch_mode(const StripArgs& sa) {
    if (!sa.output.empty() || sa.constraints || sa.source || sa.target || sa.report || sa.indices || sa.cycles || sa.cycles_obj ||
        sa.path) {
        std::cerr << "singlestrip: error: --out-dir (batch mode) cannot be combined with -o, --report, --indices, --cycles, "
                     "--cycles-obj, --path, --constraints, --source or --target (they are per file; use --with-indices, "
                     "--with-cycles, --with-path)\n";
        return app::kExitUsage;
    }
    for (const auto& in : sa.inputs)
        if (in == "-") throw ss::RequestError("batch mode reads files: - (standard input) is for a single INPUT");
    app::BatchOptions b;
    b.out_dir = *sa.out_dir;
    b.format = sa.format;
    b.input_format = sa.input_format;
    b.write_indices = sa.with_indices;
    b.write_path = sa.with_path;
    b.threads = sa.jobs;
    b.pipeline = pipeline_options(sa);
    b.pipeline.cycles = sa.with_cycles;
    const app::ProgressBar bar;
    return app::run_batch(sa.inputs, b, std::cout, bar.callback());
}

}  // namespace

int main(int argc, char** argv) {
#if defined(__GLIBC__)
    // Arrays of 1 MB and more are mmapped, so a freed soup or scratch array goes back to the system.
    // glibc's default raises this threshold up to 32 MB after the first such free: later arrays
    // then come from the heap, and freed ones stay in the peak (issue 17: up to 80 MB at 4M faces).
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
    if (argc >= 2 && std::string(argv[1]) == "render") return exec_render(argc, argv);
    if (auto code = check_command(argc, argv)) return *code;

    CLI::App cli{"singlestrip: one triangle strip for an oriented 2-manifold triangle mesh"};
    cli.require_subcommand(1);
    cli.set_version_flag("--version", "singlestrip 0.1.0");
    cli.footer(std::string(kInputFooter) + "\nsinglestrip COMMAND --help describes each command.\n" + kExitFooter);

    std::string info_input, info_format;
    bool info_json_flag = false, info_orient = false;
    RepairArgs info_fix;
    auto* info = add_info(cli, info_input, info_format, info_json_flag, info_orient, info_fix);
    StripArgs sa;
    auto* strip = add_strip(cli, sa);
    VerifyArgs va;
    auto* verify = add_verify(cli, va);
    // Listed for --help only: `render` is exec'd above, before parsing.
    if (render_available())
        cli.add_subcommand("render", "Draw a strip result to a PNG (offscreen OpenGL; see singlestrip render --help)")
            ->allow_extras()
            ->prefix_command();

    try {
        cli.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return cli.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return cli.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return cli.exit(e);
    } catch (const CLI::ParseError& e) {
        cli.exit(e);
        return app::kExitUsage;
    }

    return app::run_reporting_errors([&] {
        if (info->parsed()) return run_info(info_input, info_format, info_json_flag, info_orient, info_fix);
        if (strip->parsed()) {
            if (sa.out_dir) return run_batch_mode(sa);
            if (sa.inputs.size() != 1 || sa.output.empty()) {
                std::cerr << "singlestrip: error: strip needs exactly one INPUT and -o OUT (or several INPUTs with --out-dir DIR)\n";
                return int{app::kExitUsage};
            }
            sa.input = sa.inputs.front();
            return run_strip(sa);
        }
        if (verify->parsed()) return run_verify(va);
        return int{app::kExitUsage};
    });
}
