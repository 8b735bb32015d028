// singlestrip-render: `singlestrip render` as its own executable, so that only pictures load
// OSMesa and LLVM (about 50 MB and 0.17 s): `singlestrip render ...` execs this program.
// Exit codes and messages are the CLI's (src/app/exit_codes.hpp).
#include <CLI/CLI.hpp>

#include <iostream>
#include <string>

#include "app/exit_codes.hpp"
#include "render/render.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/strip.hpp"

namespace ss = singlestrip;

namespace {

/// Adds the options of `singlestrip render` to `app`, filling `ra`.
void add_options(CLI::App& app, ss::render::RenderArgs& ra) {
    app.add_option("RESULT", ra.input,
                   "A result mesh written by `singlestrip strip` (.ply, .obj or .off; glTF cannot be read back), or with --engine "
                   "any input mesh (.obj, .off, .ply, .stl) or builtin:genus2")
        ->required();
    app.add_option("-o,--output", ra.output, "PNG picture")->required();
    app.add_option("--cycles", ra.cycles, "Cycles JSON (from `strip --cycles`) to draw");
    auto* engine = app.add_option_function<std::string>(
        "--engine", [&ra](const std::string& name) { ra.engine = *ss::parse_engine(name); },
        "Strip RESULT first with this engine (matching or growth): RESULT is then any input mesh");
    engine->check(CLI::Validator(
        [](std::string& name) {
            return ss::parse_engine(name) ? std::string() : "unknown engine '" + name + "' (choices: matching, growth)";
        },
        "matching|growth"));
    app.add_flag("--with-cycles", ra.with_cycles, "With --engine: compute the fundamental cycles and draw them");
    app.add_flag("--polish", ra.polish, "With --engine matching: fewer swaps for more time (as `singlestrip strip --polish`)");
    app.add_option("--constraints", ra.constraints, "Constraint polylines to draw (black)");
    app.add_option("--source", ra.source, "Vertex marked green (strip start)");
    app.add_option("--target", ra.target, "Vertex marked red (strip end)");
    app.add_option("--index-base", ra.index_base, "Vertex numbers in --constraints, --source and --target start at 0 or 1")
        ->check(CLI::IsMember({0u, 1u}))
        ->capture_default_str();
    app.add_flag("--route", ra.route, "Draw the strip's route (centroids and shared-edge midpoints) as a line, start green, end red");
    app.add_option("--bands", ra.style.bands,
                   "Repeat the blue-to-red colour ramp this many times along the strip, so that neighbouring parts differ")
        ->capture_default_str();
    auto* az = app.add_option("--azimuth", ra.view.azimuth_deg, "Camera azimuth in degrees (default 35, or 0 for a flat mesh)");
    auto* el = app.add_option("--elevation", ra.view.elevation_deg, "Camera elevation in degrees (default 25, or 90 for a flat mesh)");
    auto* up = app.add_flag("--z-up", ra.view.z_up, "The model's up axis is +z (default +y, or the normal of a flat mesh)");
    app.callback([&ra, az, el, up] { ra.auto_view = !(az->count() || el->count() || up->count()); });
    app.add_option("--width", ra.style.width, "Picture width in pixels")->capture_default_str();
    app.add_option("--height", ra.style.height, "Picture height in pixels")->capture_default_str();
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"singlestrip render: draw a strip result to a PNG (offscreen OpenGL, the strip coloured along its order)",
                 "singlestrip render"};
    app.footer(
        "A flat mesh (a floor plan) is seen from straight above, otherwise from azimuth 35, elevation 25, +y up;\n"
        "any of --azimuth, --elevation, --z-up sets the view by hand.\n"
        "Exit codes: 0 ok, 2 usage, 3 bad input, 4 request cannot be met, 6 internal error, 7 output not written.");
    ss::render::RenderArgs ra;
    add_options(app, ra);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return ss::app::kExitUsage;
    }
    return ss::app::run_reporting_errors([&] {
        if (ra.cycles && ra.engine) {
            std::cerr << "singlestrip: error: render --cycles names faces of a result file; with --engine use --with-cycles\n";
            return int{ss::app::kExitUsage};
        }
        if (ra.with_cycles && !ra.engine) {
            std::cerr << "singlestrip: error: render --with-cycles needs --engine (the input is then stripped first)\n";
            return int{ss::app::kExitUsage};
        }
        return ss::render::run_render_command(ra);
    });
}
