// singlestrip — the whole pipeline with every result checked, shared by the fuzz targets and
// tests/test_mutation.cpp (header-only; compiles with gcc and clang).
//
// check_pipeline() runs prepare_soup -> Mesh::from_soup -> build_strip -> strip_arrays ->
// encode_triangle_strip -> compute_fundamental_cycles (+ tree_cotree_cycles) and passes every
// successful result to the independent verifier. Expected refusals (InputError for a bad mesh,
// RequestError for an impossible request) are not findings; anything else is:
//   * an InternalError or any other exception,
//   * a verify() failure (a wrong strip, wrong indices, broken constraints, wrong cycles),
//   * more splits than input faces, or a face count that does not match the splits,
//   * a soup that prepare_soup() accepted but Mesh::from_soup() rejected.
// It returns "" when there is no finding, else a description (callers abort or fail a test).
#pragma once

#include <cstdint>
#include <exception>
#include <map>
#include <optional>
#include <typeinfo>
#include <string>
#include <utility>
#include <vector>

#include "singlestrip/cycles.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/soup.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/tree_cotree.hpp"
#include "singlestrip/validate.hpp"
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
                return "reader returned triangle " + std::to_string(t) + " with vertex " + std::to_string(i) + " >= " +
                       std::to_string(s.points.size());
    if (!s.source_polygon.empty() && s.source_polygon.size() != s.triangles.size())
        return "reader returned source_polygon of size " + std::to_string(s.source_polygon.size()) + " for " +
               std::to_string(s.triangles.size()) + " triangles";
    if (s.triangles.empty()) return "reader returned no triangles without throwing";
    return {};
}

struct Request {
    bool orient = false;
    StripOptions strip;
    bool cycles = true;       ///< run compute_fundamental_cycles and tree_cotree_cycles
};

/// Runs the pipeline on `soup` (see top of file). `outcome` (optional) tells whether the input
/// was refused or stripped.
inline std::string check_pipeline(TriangleSoup soup, const Request& req, Outcome* outcome = nullptr) {
    if (outcome) *outcome = Outcome::Refused;
    std::string stage = "prepare_soup";
    try {
        TriangleSoup in;
        try {
            in = prepare_soup(std::move(soup), PrepareOptions{req.orient}, "fuzz");
        } catch (const InputError&) {
            return {};
        }
        stage = "Mesh::from_soup";
        Mesh mesh;
        try {
            mesh = Mesh::from_soup(in);
        } catch (const InputError& e) {
            return std::string("prepare_soup accepted a soup that Mesh::from_soup rejects: ") + e.what();
        }
        if (mesh.num_components() != 1) return "prepare_soup accepted a mesh with " + std::to_string(mesh.num_components()) + " components";

        stage = "build_strip";
        StripResult r;
        try {
            r = build_strip(mesh, req.strip);
        } catch (const RequestError&) {
            return {};
        }
        if (outcome) *outcome = Outcome::Stripped;
        const auto& st = r.stats;
        if (st.input_triangles != in.triangles.size())
            return "stats.input_triangles " + std::to_string(st.input_triangles) + " != " + std::to_string(in.triangles.size());
        if (st.splits > st.input_triangles) return "more splits (" + std::to_string(st.splits) + ") than input faces";
        if (st.output_triangles != st.input_triangles + 2 * st.splits || r.order.size() != st.output_triangles)
            return "face count " + std::to_string(r.order.size()) + " / " + std::to_string(st.output_triangles) + " does not match " +
                   std::to_string(st.input_triangles) + " + 2 * " + std::to_string(st.splits) + " splits";

        stage = "strip_arrays";
        StripArrays a = strip_arrays(r);
        stage = "encode_triangle_strip";
        std::vector<uint32_t> indices = encode_triangle_strip(a.faces);
        if (indices.size() > triangle_strip_bound(a.faces.size())) return "encoded strip longer than triangle_strip_bound";

        VerifyInput vi;
        vi.in_points = in.points;
        vi.in_faces = in.triangles;
        vi.out_points = a.points;
        vi.out_faces = a.faces;
        vi.out_parent = a.parent;
        vi.indices = std::move(indices);
        vi.constraints = req.strip.constraint_edges;
        vi.source = req.strip.source;
        vi.target = req.strip.target;

        if (req.cycles) {
            stage = "compute_fundamental_cycles";
            Cycles cy = compute_fundamental_cycles(r);
            if (cy.sources.size() != cy.cycles.size())
                return std::to_string(cy.sources.size()) + " cycle sources for " + std::to_string(cy.cycles.size()) + " cycles";
            // cycles.hpp guarantees a basis of H1 (2g+h-1 independent closed chains) for any
            // seed, constraints and source/target: verify() checks count and independence.
            vi.cycles = cy.cycles;
        }
        stage = "verify";
        VerifyReport rep = verify(vi);
        if (!rep.ok()) return "verify failed:\n" + rep.to_string();

        if (req.cycles) {
            stage = "tree_cotree_cycles";
            Cycles tc = tree_cotree_cycles(r);
            VerifyInput v2;
            v2.in_points = std::move(vi.in_points);
            v2.in_faces = std::move(vi.in_faces);
            v2.out_points = std::move(vi.out_points);
            v2.out_faces = std::move(vi.out_faces);
            v2.out_parent = std::move(vi.out_parent);
            v2.cycles = tc.cycles;
            VerifyReport rep2 = verify(v2);
            if (!rep2.ok()) return "verify failed on tree-cotree cycles:\n" + rep2.to_string();
        }
        return {};
    } catch (const InternalError& e) {
        return "InternalError in " + stage + ": " + e.what();
    } catch (const Error& e) {
        return "unexpected " + std::string(typeid(e).name()) + " in " + stage + ": " + e.what();
    } catch (const std::exception& e) {
        return "unexpected std::exception in " + stage + ": " + e.what();
    }
}

}  // namespace singlestrip::fuzzcheck
