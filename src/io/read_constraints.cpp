// Constraint files: one polyline of input vertex indices per line, '#' comments.
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <unordered_set>

#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"

namespace singlestrip {

std::vector<std::pair<uint32_t, uint32_t>> read_constraints(const std::string& path, uint32_t num_vertices,
                                                            std::vector<uint32_t>* line_of_pair) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot open constraint file (" + std::strerror(errno) + ")");
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    std::string line;
    std::size_t lineno = 0;
    while (std::getline(in, line)) {
        ++lineno;
        if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        std::istringstream ss(line);
        std::vector<uint32_t> poly;
        for (std::string tok; ss >> tok;) {
            const std::string where = path + ": line " + std::to_string(lineno) + ": ";
            char* end = nullptr;
            errno = 0;
            const bool digits = tok.find_first_not_of("0123456789") == std::string::npos;
            unsigned long long v = digits ? std::strtoull(tok.c_str(), &end, 10) : 0;
            if (!digits || errno == ERANGE) throw InputError(where + "'" + tok + "' is not a vertex index (a non-negative integer)");
            if (v >= num_vertices)
                throw InputError(where + "vertex " + tok + " is out of range (the mesh has " + std::to_string(num_vertices) + " vertices)");
            poly.push_back(static_cast<uint32_t>(v));
        }
        if (poly.size() == 1)
            throw InputError(path + ": line " + std::to_string(lineno) + ": a constraint polyline needs at least 2 vertices");
        for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
            pairs.emplace_back(poly[i], poly[i + 1]);
            if (line_of_pair) line_of_pair->push_back(static_cast<uint32_t>(lineno));
        }
    }
    if (in.bad()) throw InputError(path + ": read error");
    return pairs;
}

void check_constraint_edges(const std::string& path, const std::vector<std::pair<uint32_t, uint32_t>>& pairs,
                            const std::vector<uint32_t>& line_of_pair, const TriangleSoup& soup) {
    std::unordered_set<uint64_t> edges;
    edges.reserve(3 * soup.triangles.size());
    auto key = [](uint64_t a, uint64_t b) { return a < b ? a << 32 | b : b << 32 | a; };
    for (const Triangle& t : soup.triangles)
        for (int k = 0; k < 3; ++k) edges.insert(key(t[k], t[(k + 1) % 3]));
    for (size_t i = 0; i < pairs.size(); ++i)
        if (!edges.count(key(pairs[i].first, pairs[i].second)))
            throw RequestError(path + ": " + (i < line_of_pair.size() ? "line " + std::to_string(line_of_pair[i]) + ": " : std::string()) +
                               "(" + std::to_string(pairs[i].first) + ", " + std::to_string(pairs[i].second) +
                               ") is not an edge of the mesh");
}

}  // namespace singlestrip
