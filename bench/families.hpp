// singlestrip bench — the generated families: the scaling series (ordinary meshes from 10K to
// 10M triangles) and the awkward families of issues 15 and 17 (shapes that once broke one
// strip's quality or linear time).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip::bench {

using EdgeList = std::vector<std::pair<uint32_t, uint32_t>>;

/// A generated input: the mesh and, for the walled families, constraint edges (input vertex
/// pairs) every engine must respect.
struct Generated {
    TriangleSoup soup;
    EdgeList walls;
};

struct Family {
    std::string name;
    /// (size class, generator); the generator's exact count is in the tables.
    std::vector<std::pair<uint64_t, std::function<Generated()>>> sizes;
    /// --quick keeps sizes up to 100K, and 1M for the families marked here (one is enough to see
    /// a large mesh go through).
    bool quick_1m = false;
    /// The generator gives walls: the engines get them as constraint edges.
    bool walls = false;
};

std::vector<Family> scaling_families();
std::vector<Family> awkward_families();

}  // namespace singlestrip::bench
