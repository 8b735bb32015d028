// Regenerates the README pictures (docs/img/render_*.png) through the same path as
// `singlestrip render`: strip -> result PLY (+ cycles JSON, constraints file) -> run_render_command.
//
//   singlestrip_pictures <dir with fandisk.off, head.off, eight.off> <out dir>
// scripts/pictures builds and runs it on Debian's libcgal-demo meshes, writing docs/img/.
//
// The intermediate files are kept in <out dir>/render_work/ (handy for the README commands).
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <string>
#include <vector>

#include "render/render.hpp"
#include "singlestrip/cycles.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/pipeline.hpp"

namespace fs = std::filesystem;
using namespace singlestrip;

namespace {

struct Picture {
    std::string mesh, name;
    render::View view;
    bool cycles = false;
    bool constrained = false;
    /// Fixed request (the README's worked example) instead of the generated constraint path.
    std::string constraints_file;
    std::optional<uint32_t> source, target;
    /// The room: `singlestrip render`'s defaults (a flat mesh seen from above) and the route.
    bool default_view = false;
    bool route = false;
};

/// Shortest vertex path (edge lengths) from a to b: the constraint polyline of the example.
std::vector<uint32_t> shortest_path(const TriangleSoup& s, uint32_t a, uint32_t b) {
    std::vector<std::vector<uint32_t>> adj(s.points.size());
    for (const Triangle& t : s.triangles)
        for (int k = 0; k < 3; ++k) adj[t[k]].push_back(t[(k + 1) % 3]), adj[t[(k + 1) % 3]].push_back(t[k]);
    std::vector<double> dist(s.points.size(), std::numeric_limits<double>::infinity());
    std::vector<uint32_t> prev(s.points.size(), kNone);
    using Item = std::pair<double, uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> q;
    dist[a] = 0;
    q.push({0, a});
    while (!q.empty()) {
        auto [d, u] = q.top();
        q.pop();
        if (d > dist[u]) continue;
        for (uint32_t v : adj[u]) {
            double e = 0;
            for (int k = 0; k < 3; ++k) e += (s.points[u][k] - s.points[v][k]) * (s.points[u][k] - s.points[v][k]);
            const double nd = d + std::sqrt(e);
            if (nd < dist[v]) dist[v] = nd, prev[v] = u, q.push({nd, v});
        }
    }
    std::vector<uint32_t> path;
    for (uint32_t v = b; v != kNone; v = prev[v]) path.insert(path.begin(), v);
    return path;
}

/// Vertex with the largest (sign * coordinate `axis`).
uint32_t extreme(const TriangleSoup& s, int axis, double sign) {
    uint32_t best = 0;
    for (uint32_t v = 0; v < s.points.size(); ++v)
        if (sign * s.points[v][axis] > sign * s.points[best][axis]) best = v;
    return best;
}

void make(const Picture& p, const fs::path& meshes, const fs::path& out) {
    const fs::path work = out / "render_work";
    fs::create_directories(work);
    const std::string in = fs::path(p.mesh).is_absolute() ? p.mesh : (meshes / p.mesh).string();
    TriangleSoup soup = read_input(in);
    PipelineOptions opt;
    opt.name = in;
    opt.cycles = p.cycles;
    render::RenderArgs args;
    if (!p.constraints_file.empty()) {
        opt.constraints_file = args.constraints = p.constraints_file;
        args.source = p.source;
        args.target = p.target;
        opt.strip.source = p.source ? std::optional(VertexId(*p.source)) : std::nullopt;
        opt.strip.target = p.target ? std::optional(VertexId(*p.target)) : std::nullopt;
    } else if (p.constrained) {
        // A constraint polyline across the model and source/target at its two far ends.
        const uint32_t a = extreme(soup, 0, -1), b = extreme(soup, 0, 1);
        const uint32_t mid_lo = extreme(soup, 1, -1), mid_hi = extreme(soup, 1, 1);
        const std::vector<uint32_t> path = shortest_path(soup, mid_lo, mid_hi);
        const fs::path cfile = work / (p.name + ".constraints.txt");
        std::ofstream c(cfile);
        for (size_t i = 0; i < path.size(); ++i) c << path[i] << (i + 1 < path.size() ? ' ' : '\n');
        c.close();
        opt.constraints_file = args.constraints = cfile.string();
        args.source = a;
        args.target = b;
        opt.strip.source = VertexId(a);
        opt.strip.target = VertexId(b);
        std::printf("%s: constraints %s, --source %u --target %u\n", p.name.c_str(), cfile.c_str(), a, b);
    }
    const PipelineResult r = stripify(std::move(soup), opt);
    const fs::path ply = work / (p.name + ".ply");
    write_strip_mesh(ply.string(), r.arrays.points, r.arrays.faces, r.arrays.parent);
    if (r.cycles) {
        const fs::path cj = work / (p.name + ".cycles.json");
        write_cycles_json(cj.string(), *r.cycles);
        args.cycles = cj.string();
        std::printf("%s: %zu cycles\n", p.name.c_str(), r.cycles->cycles.size());
    }
    args.input = ply.string();
    args.output = (out / ("render_" + p.name + ".png")).string();
    args.view = p.view;
    args.auto_view = p.default_view;
    args.route = p.route;
    if (p.route) args.style.bands = 3;  // the route is long: repeat the hues so neighbours differ
    args.style.width = 900;
    args.style.height = 700;
    render::run_render_command(args);
    const StripStats& st = r.strip.stats;
    std::printf("%s: %s, %u -> %u triangles, %u splits -> %s\n", p.name.c_str(), engine_name(st.engine), st.input_triangles,
                st.output_triangles, st.splits, args.output.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s <dir with fandisk.off head.off eight.off> <out dir>\n", argv[0]);
        return 2;
    }
    const std::vector<Picture> pictures = {
        {"fandisk.off", "fandisk", {40, 30, false}, false, false, {}, {}, {}, false, false},
        {"head.off", "head", {200, 10, false}, true, false, {}, {}, {}, false, false},
        {"eight.off", "eight", {90, 60, false}, true, false, {}, {}, {}, false, false},
        {"elephant.off", "constrained", {270, 15, true}, false, true, {}, {}, {}, false, false},
        // README worked example: examples/room with its walls, --source 0 --target 650.
        {std::string(SINGLESTRIP_SOURCE_DIR) + "/examples/room/room.off",
         "room",
         {-90, 90, true},
         false,
         false,
         std::string(SINGLESTRIP_SOURCE_DIR) + "/examples/room/walls.txt",
         0u,
         650u,
         true,
         true},
    };
    int rc = 0;
    for (const Picture& p : pictures) {
        try {
            make(p, argv[1], argv[2]);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s: %s\n", p.name.c_str(), e.what());
            rc = 1;
        }
    }
    return rc;
}
