// singlestrip — recognisers for the known OPEN fuzz findings (docs/reliability.md, fuzz/repro/),
// shared by the fuzz targets and tests/test_mutation.cpp so that both skip exactly these inputs
// (and count them) until the findings are fixed. Delete a recogniser when its finding is fixed.
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>

#include "singlestrip/soup.hpp"

namespace singlestrip::fuzzcheck {

/// F1 (crash) and F2 (hang) in CGAL's PLY reader: a `property` line before any `element`, or
/// (in a complete header) an element without properties.
inline bool ply_header_known_finding(std::string_view s) {
    if (s.substr(0, 3) != "ply") return false;
    // The header ends at a line whose first word is end_header (as CGAL reads it).
    size_t end = std::string_view::npos;
    for (size_t pos = 0; pos < s.size() && pos < 65536;) {
        size_t eol = s.find('\n', pos);
        if (eol == std::string_view::npos) eol = s.size();
        std::string_view line = s.substr(pos, eol - pos);
        const size_t first = line.find_first_not_of(" \t\r");
        if (first != std::string_view::npos && line.substr(first, line.find_first_of(" \t\r", first) - first) == "end_header") {
            end = pos;
            break;
        }
        pos = eol + 1;
    }
    const std::string_view header = s.substr(0, end);
    bool in_element = false, has_property = true;
    size_t pos = 0;
    while (pos < header.size()) {
        size_t eol = header.find('\n', pos);
        if (eol == std::string_view::npos) eol = header.size();
        std::string_view line = header.substr(pos, eol - pos);
        pos = eol + 1;
        const size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string_view::npos) continue;
        line = line.substr(first);
        const std::string_view word = line.substr(0, line.find_first_of(" \t\r"));
        if (word == "element") {
            if (in_element && !has_property && end != std::string_view::npos) return true;
            in_element = true;
            has_property = false;
        } else if (word == "property") {
            if (!in_element) return true;
            has_property = true;
        }
    }
    return in_element && !has_property && end != std::string_view::npos;
}

/// F4: OFF header counts that cannot fit in the file (CGAL allocates for them first); only
/// counts large enough for the allocation to matter (> 10^6 elements, 24 MB).
/// F8: an OFF line starting with an integer >= 10^6 (a face's corner count: CGAL resizes the
/// polygon to it before reading the indices).
inline bool off_counts_known_finding(std::string_view s) {
    for (size_t pos = 0; pos < s.size();) {
        size_t eol = s.find('\n', pos);
        if (eol == std::string_view::npos) eol = s.size();
        const std::string line(s.substr(pos, std::min<size_t>(eol - pos, 64)));
        pos = eol + 1;
        const char* p = line.c_str();
        while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\v' || *p == '\f') ++p;
        char* e = nullptr;
        const double first = std::strtod(p, &e);
        if (e != p && first >= 1e6) return true;
    }
    std::string text(s.substr(0, 4096));
    for (size_t h = text.find('#'); h != std::string::npos; h = text.find('#', h)) {
        const size_t eol = text.find('\n', h);
        text.erase(h, eol == std::string::npos ? std::string::npos : eol - h);
    }
    const size_t k = text.find("OFF");
    const char* p = text.c_str() + (k == std::string::npos ? 0 : k + 3);
    char* e1 = nullptr;
    char* e2 = nullptr;
    const double nv = std::strtod(p, &e1);
    const double nf = std::strtod(e1, &e2);
    if (e1 == p || e2 == e1) return false;
    return nv + nf > 1e6 && 6.0 * nv + 8.0 * nf > static_cast<double>(s.size()) + 16.0;
}

/// F5: verify() rejects correct strips of zero-area or nearly degenerate faces.
inline bool has_degenerate_face(const TriangleSoup& soup) {
    for (const auto& t : soup.triangles) {
        const auto& a = soup.points[t[0]];
        const auto& b = soup.points[t[1]];
        const auto& c = soup.points[t[2]];
        double u[3], v[3], w[3], n[3];
        for (int k = 0; k < 3; ++k) u[k] = b[k] - a[k], v[k] = c[k] - a[k], w[k] = c[k] - b[k];
        n[0] = u[1] * v[2] - u[2] * v[1];
        n[1] = u[2] * v[0] - u[0] * v[2];
        n[2] = u[0] * v[1] - u[1] * v[0];
        const double area2 = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double longest = 0;
        for (const double* d : {u, v, w}) longest = std::max(longest, d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (!(area2 > 1e-6 * longest) || !std::isfinite(area2) || !std::isfinite(longest)) return true;
    }
    return false;
}

}  // namespace singlestrip::fuzzcheck
