// Test helper: locating the libcgal-demo meshes (data/meshes/*.off).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace singlestrip::test {

/// Path of the libcgal-demo mesh `name` (e.g. "fandisk.off"), or "" when unavailable (the test
/// should then GTEST_SKIP). Looks in $SINGLESTRIP_CGAL_DATA (a directory holding the file
/// directly, or meshes/NAME, or data/meshes/NAME); without the variable, extracts
/// /usr/share/doc/libcgal-dev/data.tar.gz once into "cgal-data/" next to the test executable
/// (atomically: extract to a temporary directory, then rename).
std::string cgal_mesh_path(const std::string& name);

/// A libcgal-demo mesh whose topology is known (counted by hand and by CGAL).
struct KnownTopology {
    const char* name;
    long long genus;
    uint32_t boundary_loops;
};

/// fandisk, head, eight, cheese, elephant-with-holes and double-torus-3-holes.
const std::vector<KnownTopology>& known_topologies();

}  // namespace singlestrip::test
