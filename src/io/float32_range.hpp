// singlestrip — the range check of the float32 writers (glTF, binary STL).
#pragma once

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
inline void check_float32_range(const std::string& path, const std::vector<Point3>& points, const char* format) {
    const double top = std::numeric_limits<float>::max();
    for (std::size_t v = 0; v < points.size(); ++v)
        for (double x : points[v])
            if (std::abs(x) > top) {
                std::ostringstream os;
                os << path << ": vertex " << v << " has coordinate " << x << ", beyond float32's range (" << top << "), and " << format
                   << " stores float32 positions; write .ply, .obj or .off (double precision) instead";
                throw RequestError(os.str());
            }
}

}  // namespace singlestrip
