// User vertex numbering (--index-base) and the refusal of outputs that overwrite inputs or each
// other (io.hpp).
#include <filesystem>
#include <limits>
#include <string>

#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"

namespace singlestrip {

uint32_t from_index_base(uint32_t number, uint32_t base, const std::string& what) {
    if (base > 1) throw RequestError("index base " + std::to_string(base) + " is not 0 or 1");
    if (number < base) throw RequestError(what + " 0 is not a vertex number when numbering starts at 1 (--index-base 1)");
    return number - base;
}

std::vector<ConstraintEdge> read_constraints_based(const std::string& path, uint32_t num_vertices, uint32_t index_base) {
    if (index_base == 0) return read_constraints(path, num_vertices);
    if (index_base != 1) throw RequestError("index base " + std::to_string(index_base) + " is not 0 or 1");
    // Read without a bound, then check 1..num_vertices here so that messages use the user's numbers.
    auto edges = read_constraints(path, std::numeric_limits<uint32_t>::max());
    for (ConstraintEdge& e : edges)
        for (uint32_t* v : {&e.a, &e.b}) {
            const std::string where = path + ": line " + std::to_string(e.line) + ": ";
            if (*v == 0) throw InputError(where + "vertex 0 does not exist when numbering starts at 1 (--index-base 1)");
            if (*v > num_vertices)
                throw InputError(where + "vertex " + std::to_string(*v) + " is out of range (the mesh has " + std::to_string(num_vertices) +
                                 " vertices, numbered from 1)");
            --*v;
        }
    return edges;
}

namespace {

namespace fs = std::filesystem;

/// Same file: equal normalised absolute paths, or (both existing) the same inode.
bool same_file(const std::string& a, const std::string& b) {
    std::error_code ec;
    if (fs::weakly_canonical(fs::absolute(a), ec) == fs::weakly_canonical(fs::absolute(b), ec) && !ec) return true;
    ec.clear();
    return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec) && !ec;
}

}  // namespace

void refuse_overwrites(const std::vector<std::pair<std::string, std::string>>& inputs,
                       const std::vector<std::pair<std::string, std::string>>& outputs) {
    for (size_t i = 0; i < outputs.size(); ++i) {
        const auto& [what, path] = outputs[i];
        if (path.empty()) continue;
        for (size_t j = 0; j < i; ++j) {
            if (outputs[j].second.empty()) continue;
            if (path == "-" ? outputs[j].second == "-" : outputs[j].second != "-" && same_file(path, outputs[j].second))
                throw RequestError(what + " " + path + " and " + outputs[j].first + " " + outputs[j].second +
                                   " are the same file: each output needs its own name");
        }
        if (path == "-") continue;
        for (const auto& [in_what, in_path] : inputs)
            if (!in_path.empty() && in_path != "-" && same_file(path, in_path))
                throw RequestError(what + " " + path + " would overwrite the " + in_what + " " + in_path);
    }
}

}  // namespace singlestrip
