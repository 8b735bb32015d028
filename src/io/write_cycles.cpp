// singlestrip — writing fundamental cycles (cycles.hpp computes them): JSON face lists and OBJ
// polylines, atomically.
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/soup.hpp"

namespace singlestrip {

void write_cycles_json(const std::string& path, const Cycles& cycles) {
    std::ostringstream os;
    os << std::setprecision(std::numeric_limits<double>::max_digits10);
    os << "{\"cycles\": [";
    for (size_t i = 0; i < cycles.cycles.size(); ++i) {
        os << (i ? ",\n  [" : "\n  [");
        for (size_t j = 0; j < cycles.cycles[i].size(); ++j) os << (j ? "," : "") << cycles.cycles[i][j];
        os << "]";
    }
    os << (cycles.cycles.empty() ? "],\n \"lengths\": [" : "\n ],\n \"lengths\": [");
    for (size_t i = 0; i < cycles.lengths.size(); ++i) {
        const double l = cycles.lengths[i];
        os << (i ? ", " : "");
        if (std::isfinite(l))
            os << l;
        else
            os << "null";  // JSON has no NaN/Inf
    }
    os << "]}\n";
    write_text_atomic(path, os.str());
}

void write_cycles_obj(const std::string& path, const std::vector<std::vector<Point3>>& polylines) {
    std::ostringstream os;
    os << std::setprecision(std::numeric_limits<double>::max_digits10);
    os << "# singlestrip fundamental cycles: " << polylines.size()
       << " closed polylines through face centroids and shared-edge midpoints\n";
    std::vector<std::pair<size_t, size_t>> ranges;  // first OBJ vertex (1-based), count
    size_t next = 1;
    for (const std::vector<Point3>& pts : polylines) {
        for (const Point3& q : pts) os << "v " << q[0] << ' ' << q[1] << ' ' << q[2] << '\n';
        ranges.emplace_back(next, pts.size());
        next += pts.size();
    }
    for (size_t i = 0; i < ranges.size(); ++i) {
        const auto [first, count] = ranges[i];
        if (count < 2) continue;  // a single point is not a polyline
        os << "o cycle_" << i << "\nl";
        for (size_t k = 0; k < count; ++k) os << ' ' << first + k;
        os << ' ' << first << '\n';
    }
    write_text_atomic(path, os.str());
}

}  // namespace singlestrip
