// Fundamental cycles (paper §4, src/algo/cycles.cpp) against our reference tree–cotree generators
// (Eppstein 2003, src/algo/tree_cotree.cpp) on the same strips, for each strip engine: count, mean
// length in faces and in geometric length (polyline through face centroids and shared-edge
// midpoints), time. Every set of cycles is checked by the independent verifier before it is
// reported.
//
//   singlestrip_cycles_bench [MESH.off ...]   (default: the libcgal-demo meshes of issue 5)
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "singlestrip/cycles.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/tree_cotree.hpp"
#include "singlestrip/validate.hpp"
#include "singlestrip/verify.hpp"

using namespace singlestrip;

namespace {

struct Summary {
    size_t count = 0;
    double mean_faces = 0, mean_length = 0, seconds = 0;
    bool verified = false;
};

Summary summarize(const TriangleSoup& soup, const StripArrays& a, const Cycles& c, double seconds) {
    Summary s;
    s.count = c.cycles.size();
    s.seconds = seconds;
    for (size_t i = 0; i < c.cycles.size(); ++i) {
        s.mean_faces += static_cast<double>(c.cycles[i].size());
        s.mean_length += c.lengths[i];
    }
    if (s.count) {
        s.mean_faces /= static_cast<double>(s.count);
        s.mean_length /= static_cast<double>(s.count);
    }
    VerifyInput vi = verify_input(soup, a, {});
    vi.indices.reset();  // the cycles are checked, not an index sequence
    vi.cycles = c.cycles;
    s.verified = verify(vi).ok();
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) files.push_back(argv[i]);
    if (files.empty())
        for (const char* n :
             {"eight.off", "head.off", "double-torus-example.off", "elephant-with-holes.off", "turbine.off", "cheese.off", "knot1.off"})
            files.push_back(std::string("/tmp/cgaldata/data/meshes/") + n);
    std::printf(
        "| mesh | engine | cycles | strip cycles: mean faces | mean length | time | tree–cotree: mean faces | mean length | time | "
        "verified |\n");
    std::printf("|---|---|--:|--:|--:|--:|--:|--:|--:|---|\n");
    for (const auto& f : files)
        for (const StripEngine engine : {StripEngine::Matching, StripEngine::Growth}) {
            try {
                const TriangleSoup soup = prepare_soup(read_mesh_file(f), {}, f);
                StripOptions options;
                options.engine = engine;
                const StripResult r = build_strip(Mesh::from_soup(soup), options);
                const StripArrays a = strip_arrays(r);
                auto t0 = std::chrono::steady_clock::now();
                const Cycles strip_cycles = compute_fundamental_cycles(r);
                auto t1 = std::chrono::steady_clock::now();
                const Cycles tc = tree_cotree_cycles(r);
                auto t2 = std::chrono::steady_clock::now();
                const Summary s = summarize(soup, a, strip_cycles, std::chrono::duration<double>(t1 - t0).count());
                const Summary t = summarize(soup, a, tc, std::chrono::duration<double>(t2 - t1).count());
                const std::string name = f.substr(f.find_last_of('/') + 1);
                std::printf(
                    "| %s | %s | %zu | %.1f | %.3f | %.3fs | %.1f | %.3f | %.3fs | %s |\n", name.c_str(), engine_name(engine), s.count,
                    s.mean_faces, s.mean_length, s.seconds, t.mean_faces, t.mean_length, t.seconds,
                    s.verified && t.verified ? "both" : (s.verified ? "strip only" : (t.verified ? "tree–cotree only" : "NEITHER")));
            } catch (const std::exception& e) {
                std::printf("| %s | %s | error: %s |\n", f.c_str(), engine_name(engine), e.what());
            }
        }
}
