// singlestrip — the range check of the float32 writers (glTF, binary STL).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "singlestrip/errors.hpp"
#include "singlestrip/soup.hpp"

namespace singlestrip {

/// \throw RequestError naming the vertex when a coordinate lies beyond float32's range
/// (|x| > 3.4e38), which a float32 format would store as infinity. Checked before anything is
/// written, so a refused output leaves no file.
/// Also when every coordinate is below float32's normal range (|x| < 1.2e-38, a mesh scaled
/// into float32's subnormals): there float32 keeps an absolute step of 1.4e-45, fewer than 24
/// bits of the mesh's size.
inline void check_float32_range(const std::string& path, const std::vector<Point3>& points, const char* format) {
    const double top = std::numeric_limits<float>::max(), low = std::numeric_limits<float>::min();
    const char* instead = " stores float32 positions; write .ply, .obj or .off (double precision) instead";
    double largest = 0;
    for (std::size_t v = 0; v < points.size(); ++v)
        for (double x : points[v]) {
            largest = std::max(largest, std::abs(x));
            if (std::abs(x) > top) {
                std::ostringstream os;
                os << path << ": vertex " << v << " has coordinate " << x << ", beyond float32's range (" << top << "), and " << format
                   << instead;
                throw RequestError(os.str());
            }
        }
    if (largest > 0 && largest < low) {
        std::ostringstream os;
        os << path << ": the largest coordinate, " << largest << ", is below float32's normal range (" << low
           << "): float32 would keep fewer than 24 bits of the mesh's size, and " << format << instead << " (or scale the mesh)";
        throw RequestError(os.str());
    }
}

}  // namespace singlestrip
