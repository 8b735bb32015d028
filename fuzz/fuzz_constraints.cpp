// libFuzzer target for the constraint-file parser. The first two bytes choose num_vertices; the
// rest is the file. read_constraints() must return pairs in range or throw InputError. When the
// file parses against a 5x5-vertex grid, the constraints go through the checked pipeline on that
// grid (a constraint that is not an edge or cuts the surface is a RequestError, fine).
#include <cstdint>
#include <cstring>
#include <exception>
#include <string>

#include "check_pipeline.hpp"
#include "decode_mesh.hpp"
#include "fixtures.hpp"
#include "fuzz_common.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace singlestrip;
    if (size < 2) return -1;
    static const TriangleSoup grid = [] {
        TriangleSoup g = make_grid_disk(4, 4);
        fuzzcheck::jitter(g, 7, 0.1);
        return g;
    }();
    const uint32_t grid_nv = static_cast<uint32_t>(grid.points.size());
    uint32_t nv = data[0] & 0x80 ? grid_nv : (static_cast<uint32_t>(data[0]) << 8 | data[1]);
    if ((data[0] & 0xc0) == 0x40) nv = 0xffffffffu - data[1];  // near the top of the range
    const std::string path = fuzzcheck::write_temp(data + 2, size - 2, ".txt");
    std::vector<ConstraintEdge> edges;
    try {
        edges = read_constraints(path, nv);
    } catch (const InputError& e) {
        if (std::strncmp(e.what(), path.c_str(), path.size()) != 0)
            fuzzcheck::finding(std::string("InputError message does not start with the path: ") + e.what());
        return 0;
    } catch (const std::exception& e) {
        fuzzcheck::finding(std::string("read_constraints threw a non-InputError: ") + e.what());
    }
    for (const ConstraintEdge& e : edges)
        if (e.a >= nv || e.b >= nv) fuzzcheck::finding("read_constraints returned a pair out of range");
    if (nv == grid_nv && edges.size() <= 64) {
        fuzzcheck::Request req;
        req.strip.constraint_edges = edges;
        if (auto p = fuzzcheck::check_pipeline(grid, req); !p.empty()) fuzzcheck::finding(p);
    }
    return 0;
}
