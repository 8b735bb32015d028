// Constraint files: one polyline of input vertex indices per line, '#' comments.
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"

namespace singlestrip {

std::vector<ConstraintEdge> read_constraints(const std::string& path, uint32_t num_vertices) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot open constraint file (" + std::strerror(errno) + ")");
    std::vector<ConstraintEdge> edges;
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
            edges.push_back({poly[i], poly[i + 1], static_cast<uint32_t>(lineno)});
        }
    }
    if (in.bad()) throw InputError(path + ": read error");
    return edges;
}

std::vector<std::pair<uint32_t, uint32_t>> vertex_pairs(const std::vector<ConstraintEdge>& edges) {
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    pairs.reserve(edges.size());
    for (const ConstraintEdge& e : edges) pairs.emplace_back(e.a, e.b);
    return pairs;
}

}  // namespace singlestrip
