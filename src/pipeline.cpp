// The pipeline every front end calls; see pipeline.hpp.
#include "singlestrip/pipeline.hpp"

#include <chrono>
#include <string>
#include <utility>

#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/generators.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/validate.hpp"

namespace singlestrip {
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

void enter(PipelineStage* stage, PipelineStage s) {
    if (stage) *stage = s;
}

void append_constraint_file(const std::string& path, uint32_t index_base, const TriangleSoup& soup, StripOptions& strip) {
    std::vector<uint32_t> lines;
    const auto pairs = read_constraints_based(path, static_cast<uint32_t>(soup.points.size()), index_base, &lines);
    try {
        check_constraint_edges(path, pairs, lines, soup);
    } catch (const RequestError& e) {
        if (index_base == 0) throw;
        // The check names the pair 0-based; say so rather than show numbers the file lacks.
        throw RequestError(std::string(e.what()) + " (vertex numbers counted from 0 here: add 1 for the file's numbering)");
    }
    strip.constraint_edges.insert(strip.constraint_edges.end(), pairs.begin(), pairs.end());
}

// prepare_soup() promises a soup Mesh::from_soup() accepts: a refusal here is a bug.
Mesh build_mesh(const TriangleSoup& soup, bool self_check) {
    Mesh mesh;
    try {
        mesh = Mesh::from_soup(soup);
    } catch (const InputError& e) {
        throw InternalError(std::string("prepare_soup accepted a soup that Mesh::from_soup rejects: ") + e.what());
    }
    if (self_check) {
        mesh.validate();
        if (const uint32_t n = mesh.num_components(); n != 1)
            throw InternalError("prepare_soup accepted a mesh with " + std::to_string(n) + " components");
    }
    return mesh;
}

double per_input_triangle(const StripStats& stats) noexcept {
    return stats.input_triangles ? static_cast<double>(stats.input_triangles) : 1.0;
}

}  // namespace

bool is_builtin_input(const std::string& input) noexcept {
    return input.rfind("builtin:", 0) == 0;
}

TriangleSoup read_input(const std::string& input, const ReadOptions& options) {
    if (!is_builtin_input(input)) return read_mesh_file(input, options);
    if (input != kBuiltinGenus2) throw RequestError("unknown built-in model '" + input + "' (available: " + kBuiltinGenus2 + ")");
    return make_builtin_model();
}

const char* stage_name(PipelineStage stage) noexcept {
    switch (stage) {
        case PipelineStage::Checks:
            return "prepare_soup";
        case PipelineStage::Constraints:
            return "constraints";
        case PipelineStage::Mesh:
            return "Mesh::from_soup";
        case PipelineStage::Strip:
            return "build_strip";
        case PipelineStage::Encode:
            return "encode_triangle_strip";
        case PipelineStage::Cycles:
            return "compute_fundamental_cycles";
        case PipelineStage::Done:
            return "done";
    }
    return "unknown";
}

PipelineResult stripify(TriangleSoup soup, const PipelineOptions& options, PipelineStage* stage) {
    Stopwatch clock;
    PipelineResult r;
    r.options = options;
    enter(stage, PipelineStage::Checks);
    r.input = prepare_soup(std::move(soup), PrepareOptions{options.orient}, options.name);
    if (options.constraints_file) {
        enter(stage, PipelineStage::Constraints);
        append_constraint_file(*options.constraints_file, options.index_base, r.input, r.options.strip);
    }
    enter(stage, PipelineStage::Mesh);
    Mesh mesh = build_mesh(r.input, options.self_check);
    r.seconds.build = clock.lap();

    enter(stage, PipelineStage::Strip);
    r.strip = build_strip(std::move(mesh), r.options.strip);
    if (options.self_check) r.strip.mesh.validate();
    enter(stage, PipelineStage::Encode);
    r.arrays = strip_arrays(r.strip);
    r.indices = encode_triangle_strip(r.arrays.faces);
    if (options.cycles) {
        enter(stage, PipelineStage::Cycles);
        r.cycles = compute_fundamental_cycles(r.strip);
    }
    r.seconds.strip = clock.lap();
    enter(stage, PipelineStage::Done);
    return r;
}

double extra_percent(const StripStats& stats) noexcept {
    return 100.0 * (static_cast<double>(stats.output_triangles) - static_cast<double>(stats.input_triangles)) / per_input_triangle(stats);
}

double indices_per_triangle(const StripStats& stats, size_t strip_indices) noexcept {
    return static_cast<double>(strip_indices) / per_input_triangle(stats);
}

}  // namespace singlestrip
