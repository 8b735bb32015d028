// singlestrip — the whole pipeline with every result checked, shared by the fuzz targets and
// tests/test_mutation.cpp (header-only; compiles with gcc and clang).
//
// check_pipeline() runs stripify() (pipeline.hpp: prepare_soup -> Mesh::from_soup ->
// build_strip -> strip_arrays -> encode_triangle_strip -> compute_fundamental_cycles, with its
// self checks) plus tree_cotree_cycles and passes every successful result to the independent
// verifier. Expected refusals (InputError for a bad mesh,
// RequestError for an impossible request) are not findings; anything else is:
//   * an InternalError or any other exception,
//   * a verify() failure (a wrong strip, wrong indices, broken constraints, wrong cycles),
//   * more splits than input faces, or a face count that does not match the splits,
//   * a soup that prepare_soup() accepted but Mesh::from_soup() rejected.
// It returns "" when there is no finding, else a description (callers abort or fail a test).
#pragma once

#include <algorithm>
#include <cstdint>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

#include "singlestrip/cycles.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/soup.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/tree_cotree.hpp"
#include "singlestrip/verify.hpp"

namespace singlestrip::fuzzcheck {

enum class Outcome { Refused, Stripped };

/// A reader's result must be a usable soup: indices in range, finite coordinates,
/// source_polygon empty or one entry per triangle. Returns "" or the problem.
inline std::string check_soup(const TriangleSoup& s) {
    for (size_t v = 0; v < s.points.size(); ++v)
        for (double c : s.points[v])
            if (!(c - c == 0.0)) return "reader returned a non-finite coordinate at vertex " + std::to_string(v);
    for (size_t t = 0; t < s.triangles.size(); ++t)
        for (uint32_t i : s.triangles[t])
            if (i >= s.points.size())
                return "reader returned triangle " + std::to_string(t) + " with vertex " + std::to_string(i) +
                       " >= " + std::to_string(s.points.size());
    if (!s.source_polygon.empty() && s.source_polygon.size() != s.triangles.size())
        return "reader returned source_polygon of size " + std::to_string(s.source_polygon.size()) + " for " +
               std::to_string(s.triangles.size()) + " triangles";
    if (s.triangles.empty()) return "reader returned no triangles without throwing";
    return {};
}

struct Request {
    bool orient = false;
    StripOptions strip;
    bool cycles = true;   ///< run compute_fundamental_cycles and tree_cotree_cycles
    bool repair = false;  ///< PipelineOptions::repair (then only "no faces" may be refused)
};

/// The stats of a stripped result must agree with the input and the strip order.
inline std::string check_counts(const PipelineResult& r) {
    const auto& st = r.strip.stats;
    if (st.input_triangles != r.input.triangles.size())
        return "stats.input_triangles " + std::to_string(st.input_triangles) + " != " + std::to_string(r.input.triangles.size());
    if (st.splits > st.input_triangles) return "more splits (" + std::to_string(st.splits) + ") than input faces";
    if (st.output_triangles != st.input_triangles + 2 * st.splits || r.arrays.faces.size() != st.output_triangles)
        return "face count " + std::to_string(r.arrays.faces.size()) + " / " + std::to_string(st.output_triangles) + " does not match " +
               std::to_string(st.input_triangles) + " + 2 * " + std::to_string(st.splits) + " splits";
    if (r.indices.size() > joined_strip_bound(r.arrays.faces.size(), r.components.size()))
        return "encoded strips longer than joined_strip_bound";
    if (r.cycles && r.cycles->sources.size() != r.cycles->cycles.size())
        return std::to_string(r.cycles->sources.size()) + " cycle sources for " + std::to_string(r.cycles->cycles.size()) + " cycles";
    return {};
}

/// verify() on the result; with cycles, also on the tree-cotree cycles of the same strip.
inline std::string check_result(const PipelineResult& r, const Request& req, const char*& where) {
    where = "verify";
    VerifyInput vi = verify_input(r.input, r.arrays, r.indices);
    if (!r.face_origin.empty()) {  // parents name input faces; verify against the repaired soup
        std::vector<uint32_t> of_input(r.face_origin.empty() ? 0 : *std::max_element(r.face_origin.begin(), r.face_origin.end()) + 1,
                                       0xffffffffu);
        for (uint32_t t = 0; t < r.face_origin.size(); ++t) of_input[r.face_origin[t]] = t;
        for (uint32_t& p : vi.out_parent) p = p < of_input.size() ? of_input[p] : 0xffffffffu - 1;
    }
    vi.constraints = vertex_pairs(req.strip.constraint_edges);
    vi.source = index_of(req.strip.source);
    vi.target = index_of(req.strip.target);
    // cycles.hpp guarantees a basis of H1 (2g+h-1 independent closed chains) for any seed,
    // constraints and source/target: verify() checks count and independence.
    if (r.cycles) vi.cycles = r.cycles->cycles;
    if (VerifyReport rep = verify(vi); !rep.ok()) return "verify failed:\n" + rep.to_string();
    if (r.face_origin.empty()) {  // as for an OBJ/OFF output: parents inferred (verify.hpp)
        where = "verify_inferred_parents";
        const std::vector<uint32_t> given = std::move(vi.out_parent);
        vi.out_parent.clear();
        if (VerifyReport rep = verify(vi); !rep.ok()) return "verify failed with inferred parents:\n" + rep.to_string();
        vi.out_parent = given;
    }
    // Several components: r.strip holds only the totals (pipeline.hpp), and verify() checks
    // cycles on one-component outputs only.
    if (!req.cycles || r.components.size() != 1) return {};
    where = "tree_cotree_cycles";
    vi.indices.reset();
    vi.constraints.clear();
    vi.source.reset();
    vi.target.reset();
    vi.cycles = tree_cotree_cycles(r.strip).cycles;
    if (VerifyReport rep = verify(vi); !rep.ok()) return "verify failed on tree-cotree cycles:\n" + rep.to_string();
    return {};
}

/// Runs the pipeline on `soup` (see top of file). `outcome` (optional) tells whether the input
/// was refused or stripped.
inline std::string check_pipeline(TriangleSoup soup, const Request& req, Outcome* outcome = nullptr) {
    if (outcome) *outcome = Outcome::Refused;
    PipelineStage stage = PipelineStage::Checks;
    const char* after = nullptr;  // a check after the pipeline, when it is the one that threw
    auto where = [&] { return std::string(after ? after : stage_name(stage)); };
    try {
        PipelineOptions o;
        o.strip = req.strip;
        o.orient = req.orient;
        o.repair = req.repair;
        o.cycles = req.cycles;
        o.name = "fuzz";
        o.self_check = true;
        PipelineResult r;
        try {
            r = stripify(std::move(soup), o, &stage);
        } catch (const InputError&) {
            if (stage == PipelineStage::Checks) return {};
            throw;
        } catch (const RequestError&) {
            // A constraint pair that is not an edge is refused while the constraints are checked.
            if (stage == PipelineStage::Strip || stage == PipelineStage::Constraints) return {};
            throw;
        }
        if (outcome) *outcome = Outcome::Stripped;
        if (std::string p = check_counts(r); !p.empty()) return p;
        return check_result(r, req, after);
    } catch (const InternalError& e) {
        return "InternalError in " + where() + ": " + e.what();
    } catch (const Error& e) {
        return "unexpected " + std::string(typeid(e).name()) + " in " + where() + ": " + e.what();
    } catch (const std::exception& e) {
        return "unexpected std::exception in " + where() + ": " + e.what();
    }
}

}  // namespace singlestrip::fuzzcheck
