// singlestrip — tests: the least splits some meshes need, from their dual graph alone.
#include "split_bounds.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace singlestrip::testing {

uint32_t dual_tree_diameter(const TriangleSoup& s) {
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> faces_of_edge;
    for (uint32_t f = 0; f < s.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) faces_of_edge[std::minmax(s.triangles[f][k], s.triangles[f][(k + 1) % 3])].push_back(f);
    std::vector<std::vector<uint32_t>> next(s.triangles.size());
    for (const auto& [edge, faces] : faces_of_edge)
        if (faces.size() == 2) next[faces[0]].push_back(faces[1]), next[faces[1]].push_back(faces[0]);
    auto farthest = [&](uint32_t from) {
        std::vector<uint32_t> dist(next.size(), UINT32_MAX), queue{from};
        dist[from] = 0;
        for (size_t i = 0; i < queue.size(); ++i)
            for (uint32_t g : next[queue[i]])
                if (dist[g] == UINT32_MAX) dist[g] = dist[queue[i]] + 1, queue.push_back(g);
        return std::pair{queue.back(), dist[queue.back()]};
    };
    return farthest(farthest(0).first).second;
}

}  // namespace singlestrip::testing
