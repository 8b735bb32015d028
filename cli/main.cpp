// singlestrip command line tool: info, strip (one file, or a batch with --out-dir), verify, render.
//
// Exit codes (errors.hpp): 0 ok; 2 bad command line; 3 bad input (file or mesh; also `info` on
// a mesh that is not valid for stripping); 4 request cannot be met; 5 verification failed;
// 6 internal error; 7 output could not be written. Errors print "singlestrip: error: <message>".
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "singlestrip/batch.hpp"
#include "singlestrip/cycles.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/gltf.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/repair.hpp"
#include "singlestrip/report.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/validate.hpp"
#include "singlestrip/verify.hpp"
#ifdef SINGLESTRIP_HAVE_RENDER
#include "render/render.hpp"
#endif

namespace ss = singlestrip;
using json = nlohmann::json;

namespace {

class Stopwatch {
public:
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double s = std::chrono::duration<double>(now - start_).count();
        start_ = now;
        return s;
    }

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// Reads INPUT: a mesh file, or `builtin:genus2` (the demo model of generators.hpp).
/// `format` is `--input-format`: INPUT's format when its name does not tell (e.g. /dev/stdin).
ss::TriangleSoup load_input(const std::string& input, const std::string& format) {
    ss::ReadOptions read;
    read.format = format;
    return ss::read_input(input, read);
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

json info_json(const std::string& input, const ss::MeshInfo& m, long long flipped) {
    json j;
    j["file"] = input;
    j["vertices"] = m.vertices;
    j["referenced_vertices"] = m.referenced_vertices;
    j["faces"] = m.faces;
    j["polygons"] = m.polygons;
    j["edges"] = m.edges;
    j["boundary_edges"] = m.boundary_edges;
    j["non_manifold_edges"] = m.non_manifold_edges;
    j["components"] = m.components;
    j["component_sizes"] = m.component_sizes;
    j["boundary_loops"] = m.boundary_loops;
    j["euler_characteristic"] = m.euler_characteristic;
    j["genus"] = m.genus_valid ? json(m.genus) : json(nullptr);
    j["orientable"] = m.orientable;
    j["oriented"] = m.oriented;
    if (flipped >= 0) j["faces_flipped_by_orient"] = flipped;
    j["unwelded_vertices"] = m.unwelded_vertices;
    j["valid"] = m.valid();
    json ps = json::array();
    for (const auto& p : m.problems) ps.push_back({{"kind", p.kind}, {"message", p.message}});
    j["problems"] = ps;
    return j;
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
    if (as_json) {
        json j = info_json(input, m, orient ? flipped : -1);
        if (repaired) j["repair"] = json::parse(ss::repair_json(*repaired));
        std::cout << j.dump(2) << '\n';
    } else {
        std::cout << info_text(input, m, orient ? flipped : -1);
    }
    return m.valid() ? ss::kExitOk : ss::kExitBadInput;
}

struct StripArgs {
    std::vector<std::string> inputs;
    std::string input, output;
    std::optional<std::string> indices, report, constraints, cycles, cycles_obj, out_dir;
    std::string format = "ply";
    std::string input_format;  ///< `--input-format`
    unsigned jobs = 0;
    bool with_indices = false, with_cycles = false;
    std::optional<uint32_t> seed_face, source, target;
    bool no_greedy = false, orient = false;
    RepairArgs fix;
    ss::JoinMode join = ss::JoinMode::Degenerate;
    uint32_t restart_index = 0xffffffffu;
    ss::StripEngine engine = ss::StripEngine::Matching;
};

/// Removes the files this run has finished if a later step fails, so no partial set of outputs
/// is left behind (each single file is already written atomically).
class OutputSet {
public:
    void done(const std::string& path) { written_.push_back(path); }
    void commit() { written_.clear(); }
    ~OutputSet() {
        for (const auto& p : written_) {
            std::error_code ec;
            std::filesystem::remove(p, ec);
        }
    }

private:
    std::vector<std::string> written_;
};

ss::PipelineOptions pipeline_options(const StripArgs& a) {
    ss::PipelineOptions o;
    o.strip.engine = a.engine;
    o.strip.seed_face = a.seed_face;
    o.strip.greedy = !a.no_greedy;
    o.strip.source = a.source;
    o.strip.target = a.target;
    o.orient = a.orient;
    o.weld = a.fix.weld;
    o.repair = a.fix.repair;
    o.join = a.join;
    o.restart_index = a.restart_index;
    o.cycles = a.cycles || a.cycles_obj;
    o.name = a.input;
    o.constraints_file = a.constraints;
    return o;
}

/// Writes OUT and the optional files; returns the seconds spent.
double write_outputs(const StripArgs& a, const ss::PipelineResult& r, OutputSet& outputs) {
    Stopwatch clock;
    if (ss::is_gltf_path(a.output))
        ss::write_gltf_strip(a.output, r.arrays, ss::degenerate_joined_indices(r));
    else
        ss::write_strip_mesh(a.output, r.arrays.points, r.arrays.faces, r.arrays.parent);
    outputs.done(a.output);
    if (a.indices) {
        ss::write_indices(*a.indices, r.indices);
        outputs.done(*a.indices);
    }
    if (r.cycles && a.cycles) {
        ss::write_cycles_json(*a.cycles, *r.cycles);
        outputs.done(*a.cycles);
    }
    if (r.cycles && a.cycles_obj) {
        ss::write_cycles_obj(*a.cycles_obj, r.arrays, *r.cycles);
        outputs.done(*a.cycles_obj);
    }
    return clock.lap();
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
    if (a.indices || a.cycles || a.cycles_obj || a.constraints || a.source || a.target || a.seed_face)
        throw ss::RequestError(a.input +
                               ": a glTF scene is stripped primitive by primitive (vertex and face numbers are per primitive): "
                               "--indices, --cycles, --cycles-obj, --constraints, --source, --target and --seed-face need a "
                               ".ply/.obj/.off output (all triangle primitives as one mesh)");
    const auto prims = ss::strip_gltf_file(a.input, a.output, pipeline_options(a));
    json rep = {{"input", a.input}, {"output", a.output}, {"primitives", json::array()}};
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
        rep["primitives"].push_back({{"mesh", p.mesh},
                                     {"primitive", p.primitive},
                                     {"stripped", p.stripped},
                                     {"note", p.note},
                                     {"input_triangles", p.input_triangles},
                                     {"output_triangles", p.output_triangles},
                                     {"splits", p.splits},
                                     {"strips", p.strips},
                                     {"strip_indices", p.strip_indices},
                                     {"welded_vertices", p.welded},
                                     {"attributes", p.attributes},
                                     {"repair", p.repair}});
    }
    if (a.report) ss::write_text_atomic(*a.report, rep.dump(2) + "\n");
    return ss::kExitOk;
}

int run_strip(const StripArgs& a) {
    if (ss::is_gltf_path(a.input) && ss::is_gltf_path(a.output) && a.input_format.empty()) return run_strip_gltf(a);
    // Unknown extension: RequestError before any work.
    if (!ss::is_gltf_path(a.output)) ss::output_format_for(a.output);
    Stopwatch clock;
    ss::TriangleSoup soup = load_input(a.input, a.input_format);
    const double t_read = clock.lap();
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
        ss::write_text_atomic(*a.report, ss::report_json(rep));
        outputs.done(*a.report);
    }
    outputs.commit();
    print_summary(a.input, r);
    return ss::kExitOk;
}

struct VerifyArgs {
    std::string input, output;
    std::optional<std::string> indices, constraints, cycles;
    std::optional<uint32_t> source, target;
    std::string input_format;  ///< `--input-format`
    RepairArgs fix;
    bool orient = false;
    uint32_t restart_index = 0xffffffffu;
};

int run_verify(const VerifyArgs& a) {
    if (ss::is_gltf_path(a.output) && ss::is_gltf_path(a.input))
        throw ss::RequestError(a.output +
                               ": a glTF scene stripped primitive by primitive is not verified; write a .ply from the same "
                               "input (all its triangle primitives as one mesh) to verify");
    ss::VerifyFileOptions o;
    o.indices_path = a.indices;
    o.constraints_path = a.constraints;
    o.source = a.source;
    o.target = a.target;
    o.cycles_path = a.cycles;
    o.input_format = a.input_format;
    o.steps = {a.fix.weld, a.fix.repair, a.orient};
    o.restart_index = a.restart_index;
    // The built-in model has no file: it is generated and checked like a read input.
    const ss::VerifyReport rep = ss::is_builtin_input(a.input) ? ss::verify_files(load_input(a.input, a.input_format), a.output, o)
                                                               : ss::verify_files(a.input, a.output, o);
    std::cout << rep.to_string();
    if (!rep.to_string().empty() && rep.to_string().back() != '\n') std::cout << '\n';
    return rep.ok() ? ss::kExitOk : ss::kExitVerifyFailed;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"singlestrip: one triangle strip for an oriented 2-manifold triangle mesh"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "singlestrip 0.1.0");
    app.footer(
        "INPUT is a .obj, .off, .ply, .stl, .glb or .gltf file (or a pipe such as /dev/stdin with --input-format),\n"
        "or builtin:genus2 (the demo model).\n"
        "Exit codes: 0 ok, 2 usage, 3 bad input, 4 request cannot be met, 5 verification failed,\n"
        "6 internal error, 7 output not written.");

    std::string info_input;
    bool info_json_flag = false, info_orient = false;
    auto* info = app.add_subcommand("info", "Report counts, topology and every problem of a mesh (exit 3 if not valid for stripping)");
    info->add_option("INPUT", info_input, "Input mesh file or builtin:genus2")->required();
    info->add_flag("--json", info_json_flag, "Machine-readable JSON output");
    info->add_flag("--orient", info_orient, "Consistently re-orient an orientable mesh before reporting");
    RepairArgs info_fix;
    add_repair_options(info, info_fix);
    const char* kInputFormatHelp = "Format of INPUT (obj, off, ply, stl) when its name does not tell, e.g. /dev/stdin";
    const auto input_format_check = CLI::IsMember({"obj", "off", "ply", "stl"}, CLI::ignore_case);
    std::string info_format;
    info->add_option("--input-format", info_format, kInputFormatHelp)->check(input_format_check);

    StripArgs sa;
    auto* strip = app.add_subcommand("strip", "Turn the mesh into one triangle strip");
    strip->add_option("INPUT", sa.inputs, "Input mesh file(s) or builtin:genus2 (several need --out-dir)")->required();
    strip->add_option("-o,--output", sa.output, "Output mesh (.ply binary with parent, .obj, .off, .glb/.gltf), faces in strip order");
    strip->add_option("--out-dir", sa.out_dir,
                      "Batch mode: strip every INPUT on all cores into DIR (<stem>.<format> + <stem>.report.json)");
    strip->add_option("--format", sa.format, "Batch mode: result format (ply, obj, off, glb, gltf)")->capture_default_str();
    strip->add_option("-j,--jobs", sa.jobs, "Batch mode: worker threads (0 = all cores)");
    strip->add_flag("--with-indices", sa.with_indices, "Batch mode: also write <stem>.indices.txt");
    strip->add_flag("--with-cycles", sa.with_cycles, "Batch mode: also write <stem>.cycles.json");
    strip->add_option("--indices", sa.indices, "Write the GL_TRIANGLE_STRIP index sequence (text)");
    strip->add_option("--report", sa.report, "Write a JSON report");
    strip->add_option("--seed-face", sa.seed_face, "Input face to start the strip from");
    add_engine_option(
        strip, [&sa](ss::StripEngine e) { sa.engine = e; },
        "Strip engine: matching (default) or growth (the paper's builder, for comparison)");
    strip->add_flag("--no-greedy", sa.no_greedy, "Use the paper's plain same-direction turn rule");
    strip->add_flag("--orient", sa.orient, "Consistently re-orient an orientable mesh first (each component keeps its majority)");
    add_repair_options(strip, sa.fix);
    strip
        ->add_option_function<std::string>(
            "--join", [&sa](const std::string& m) { sa.join = *ss::parse_join_mode(m); },
            "Several components: join their strips in the index file by degenerate triangles (default) or a restart index")
        ->check(CLI::IsMember({"degenerate", "restart"}));
    strip->add_option("--restart-index", sa.restart_index, "Restart index for --join restart (default 4294967295)");
    strip->add_option("--input-format", sa.input_format, kInputFormatHelp)->check(input_format_check);
    strip->add_option("--constraints", sa.constraints, "Edges the strip must not cross: one polyline of vertex indices per line");
    strip->add_option("--source", sa.source, "The strip starts at a face incident to this input vertex");
    strip->add_option("--target", sa.target, "The strip ends at a face incident to this input vertex");
    strip->add_option("--cycles", sa.cycles,
                      "Write the fundamental cycles (paper section 4) as JSON {\"cycles\": [[face, ...], ...], \"lengths\": [...]}");
    strip->add_option("--cycles-obj", sa.cycles_obj,
                      "Write the fundamental cycles as OBJ polylines through face centroids and shared-edge midpoints");

    VerifyArgs va;
    auto* verify = app.add_subcommand("verify", "Independently check a strip output against its input (exit 5 on failure)");
    verify->add_option("IN", va.input, "Input mesh file (or builtin:genus2)")->required();
    verify->add_option("OUT", va.output, "Output mesh written by `singlestrip strip`")->required();
    verify->add_option("--indices", va.indices, "GL_TRIANGLE_STRIP index file to check against OUT");
    verify->add_option("--constraints", va.constraints, "Constraint polylines the strip must respect");
    verify->add_option("--source", va.source, "Required first-face vertex");
    verify->add_option("--target", va.target, "Required last-face vertex");
    verify->add_option("--cycles", va.cycles, "Cycles JSON to check for independence");
    verify->add_option("--input-format", va.input_format, kInputFormatHelp)->check(input_format_check);
    add_repair_options(verify, va.fix);
    verify->add_flag("--orient", va.orient, "OUT was made with --orient: check against the re-oriented input");
    verify->add_option("--restart-index", va.restart_index, "Restart index in the --indices file (default 4294967295)");

#ifdef SINGLESTRIP_HAVE_RENDER
    ss::render::RenderArgs ra;
    auto* render = app.add_subcommand("render", "Draw a strip result to a PNG (offscreen OpenGL, strip coloured along its order)");
    render->add_option("RESULT", ra.input, "Result mesh written by `singlestrip strip` (.ply/.obj/.off)")->required();
    render->add_option("-o,--output", ra.output, "PNG picture")->required();
    render->add_option("--cycles", ra.cycles, "Cycles JSON to draw");
    add_engine_option(
        render, [&ra](ss::StripEngine e) { ra.engine = e; },
        "Strip RESULT first with this engine (matching or growth): RESULT is then any input mesh");
    render->add_flag("--with-cycles", ra.with_cycles, "With --engine: compute the fundamental cycles and draw them");
    render->add_option("--constraints", ra.constraints, "Constraint polylines to draw");
    render->add_option("--source", ra.source, "Vertex marked green (strip start)");
    render->add_option("--target", ra.target, "Vertex marked red (strip end)");
    render->add_option("--azimuth", ra.view.azimuth_deg, "Camera azimuth (degrees)")->capture_default_str();
    render->add_option("--elevation", ra.view.elevation_deg, "Camera elevation (degrees)")->capture_default_str();
    render->add_flag("--z-up", ra.view.z_up, "Model's up axis is +z (default +y)");
    render->add_option("--width", ra.style.width, "Picture width in pixels")->capture_default_str();
    render->add_option("--height", ra.style.height, "Picture height in pixels")->capture_default_str();
#endif

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return ss::kExitUsage;
    }

    try {
        if (info->parsed()) return run_info(info_input, info_format, info_json_flag, info_orient, info_fix);
        if (strip->parsed()) {
            if (sa.out_dir) {
                if (!sa.output.empty() || sa.constraints || sa.source || sa.target || sa.report || sa.indices || sa.cycles ||
                    sa.cycles_obj) {
                    std::cerr << "singlestrip: error: --out-dir (batch mode) cannot be combined with -o, --report, --indices, "
                                 "--cycles, --cycles-obj, --constraints, --source or --target (they are per file)\n";
                    return ss::kExitUsage;
                }
                ss::BatchOptions b;
                b.out_dir = *sa.out_dir;
                b.format = sa.format;
                b.input_format = sa.input_format;
                b.write_indices = sa.with_indices;
                b.cycles = sa.with_cycles;
                b.greedy = !sa.no_greedy;
                b.engine = sa.engine;
                b.orient = sa.orient;
                b.weld = sa.fix.weld;
                b.repair = sa.fix.repair;
                b.join = sa.join;
                b.seed_face = sa.seed_face;
                b.threads = sa.jobs;
                return ss::run_batch(sa.inputs, b, std::cout);
            }
            if (sa.inputs.size() != 1 || sa.output.empty()) {
                std::cerr << "singlestrip: error: strip needs exactly one INPUT and -o OUT (or several INPUTs with --out-dir DIR)\n";
                return ss::kExitUsage;
            }
            sa.input = sa.inputs.front();
            return run_strip(sa);
        }
        if (verify->parsed()) return run_verify(va);
#ifdef SINGLESTRIP_HAVE_RENDER
        if (render->parsed()) {
            if (ra.cycles && ra.engine) {
                std::cerr << "singlestrip: error: render --cycles names faces of a result file; with --engine use --with-cycles\n";
                return ss::kExitUsage;
            }
            if (ra.with_cycles && !ra.engine) {
                std::cerr << "singlestrip: error: render --with-cycles needs --engine (the input is then stripped first)\n";
                return ss::kExitUsage;
            }
            return ss::render::run_render_command(ra);
        }
#endif
        return ss::kExitUsage;
    } catch (const ss::Error& e) {
        std::cerr << "singlestrip: error: " << e.what() << '\n';
        return e.exit_code();
    } catch (const std::bad_alloc&) {
        std::cerr << "singlestrip: error: out of memory\n";
        return ss::kExitInternal;
    } catch (const std::exception& e) {
        std::cerr << "singlestrip: error: internal: " << e.what() << '\n';
        return ss::kExitInternal;
    }
}
