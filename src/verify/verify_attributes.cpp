// verify(): every output vertex's attribute values against the input's (verify_attributes.hpp).
#include "verify_attributes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace singlestrip::verify_detail {
namespace {

constexpr uint32_t kNo = 0xffffffffu;

/// Barycentric weights of q's projection into triangle abc (least squares in its plane),
/// negatives (rounding on an edge) set to 0 and the rest rescaled to sum 1; empty when the
/// triangle has no area.
std::vector<double> weights(const Point3& q, const Point3& a, const Point3& b, const Point3& c) {
    std::array<double, 3> u{}, v{}, w{};
    for (size_t d = 0; d < 3; ++d) u[d] = b[d] - a[d], v[d] = c[d] - a[d], w[d] = q[d] - a[d];
    auto dot = [](const std::array<double, 3>& x, const std::array<double, 3>& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
    const double uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), wu = dot(w, u), wv = dot(w, v), det = uu * vv - uv * uv;
    if (!(det > 1e-300)) return {};
    std::array<double, 3> l{0, (vv * wu - uv * wv) / det, (uu * wv - uv * wu) / det};
    l[0] = 1 - l[1] - l[2];
    double sum = 0;
    for (double& x : l) sum += (x = std::max(x, 0.0));
    return {l[0] / sum, l[1] / sum, l[2] / sum};
}

std::string number(double x) {
    std::ostringstream o;
    o.precision(3);
    o << x;
    return o.str();
}

std::string values_str(const double* x, size_t k) {
    std::ostringstream o;
    o.precision(9);
    o << '(';
    for (size_t i = 0; i < k; ++i) o << (i ? ", " : "") << x[i];
    o << ')';
    return o.str();
}

/// Where an output vertex's expected values come from.
struct Expected {
    std::array<uint32_t, 3> corner{};
    std::vector<double> w;  ///< empty: an input vertex, corner[0]
    uint32_t parent = kNo;
    bool skip = false;  ///< unreferenced, or its parent is unknown or has no area (reported by the geometry checks)
};

/// Expected values of `in` (blend rule `blend`) at `e`; `alternatives` gets every corner of
/// largest weight for the values taken from one corner (Nearest; TANGENT's w).
std::vector<double> blend(const VertexAttribute& a, size_t k, const Expected& e, std::vector<uint32_t>& alternatives) {
    alternatives.clear();
    std::vector<double> x(k, 0.0);
    if (e.w.empty()) {
        for (size_t c = 0; c < k; ++c) x[c] = a.values[e.corner[0] * a.components + c];
        alternatives.push_back(e.corner[0]);
        return x;
    }
    const double top = std::max({e.w[0], e.w[1], e.w[2]});
    for (size_t j = 0; j < 3; ++j)
        if (e.w[j] >= top - 1e-6) alternatives.push_back(e.corner[j]);
    for (size_t j = 0; j < 3; ++j)
        for (size_t c = 0; c < k; ++c) x[c] += e.w[j] * a.values[e.corner[j] * a.components + c];
    if (a.blend == AttributeBlend::Unit && k >= 3) {
        const double len = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        for (size_t c = 0; c < 3; ++c) x[c] = len > 0 ? x[c] / len : (c == 2 ? 1.0 : 0.0);
    }
    return x;
}

/// Per output vertex: an input vertex, or the parent face it lies in (of the first face using it).
std::vector<Expected> sources(const VerifyInput& in, const std::vector<uint32_t>& parent) {
    const size_t n = in.in_points.size();
    std::vector<Expected> src(in.out_points.size());
    std::vector<char> known(src.size(), 0);
    for (size_t v = 0; v < std::min(n, src.size()); ++v) src[v].corner[0] = static_cast<uint32_t>(v), known[v] = 1;
    for (size_t f = 0; f < in.out_faces.size() && f < parent.size(); ++f)
        for (uint32_t v : in.out_faces[f]) {
            if (v >= src.size() || known[v] || parent[f] >= in.in_faces.size()) continue;
            const Triangle& t = in.in_faces[parent[f]];
            if (std::max({t[0], t[1], t[2]}) >= n) continue;
            src[v] = {t, weights(in.out_points[v], in.in_points[t[0]], in.in_points[t[1]], in.in_points[t[2]]), parent[f]};
            src[v].skip = src[v].w.empty();  // a parent without area: no position inside it to blend at
            known[v] = 1;
        }
    for (size_t v = n; v < src.size(); ++v) src[v].skip = src[v].skip || !known[v];
    return src;
}

/// Checks one attribute; returns the number of mismatching vertices (the first few described).
size_t check_one(const VertexAttribute& a, const OutputAttribute& o, const std::vector<Expected>& src, std::vector<char>& referenced,
                 std::vector<std::string>& failures) {
    const size_t k = std::min(a.components, o.components);
    size_t bad = 0;
    std::vector<uint32_t> alts;
    for (size_t v = 0; v < src.size(); ++v) {
        if (!referenced[v] || src[v].skip) continue;
        const bool pick = a.blend == AttributeBlend::Nearest;
        const std::vector<double> want = blend(a, k, src[v], alts);
        const double* got = &o.values[v * o.components];
        auto close = [&](double g, double w) { return std::abs(g - w) <= o.abs_tol + o.rel_tol * std::abs(w); };
        bool ok = true;
        for (size_t c = 0; c < k; ++c) {
            const bool from_corner = pick || (a.blend == AttributeBlend::Unit && c == 3);
            bool match = !from_corner && close(got[c], want[c]);
            for (uint32_t alt : alts) match = match || (from_corner && close(got[c], a.values[alt * a.components + c]));
            ok = ok && match;
        }
        if (ok || ++bad > 5) continue;
        std::string how = "input vertex " + std::to_string(v) + "'s";
        if (!src[v].w.empty())
            how = std::string(pick ? "one of the largest-weight corners'" : "the blend") + " of parent face " +
                  std::to_string(src[v].parent) + ", input vertices " + std::to_string(src[v].corner[0]) + ", " +
                  std::to_string(src[v].corner[1]) + ", " + std::to_string(src[v].corner[2]) + " with weights " +
                  values_str(src[v].w.data(), 3) + (a.blend == AttributeBlend::Unit ? ", renormalised" : "");
        failures.push_back("vertex " + std::to_string(v) + " " + a.name + " = " + values_str(got, k) + ", expected " +
                           values_str(want.data(), k) + " (" + how + ") within " + number(o.abs_tol) + " + " + number(o.rel_tol) +
                           " * |expected| (" + o.storage + " in the output)");
    }
    return bad;
}

}  // namespace

void check_attributes(const VerifyInput& in, const std::vector<uint32_t>& parent, std::vector<std::string>& failures,
                      std::vector<std::string>& notes) {
    if (in.in_attributes.empty() || in.out_attributes.empty()) {
        if (!in.in_attributes.empty()) notes.push_back("attributes: none of the input's read back from the output; not checked");
        return;
    }
    const std::vector<Expected> src = sources(in, parent);
    std::vector<char> referenced(in.out_points.size(), 0);
    for (const Triangle& t : in.out_faces)
        for (uint32_t v : t)
            if (v < referenced.size()) referenced[v] = 1;
    std::string checked;
    for (const VertexAttribute& a : in.in_attributes) {
        const auto o =
            std::find_if(in.out_attributes.begin(), in.out_attributes.end(), [&](const OutputAttribute& x) { return x.name == a.name; });
        if (o == in.out_attributes.end()) {
            notes.push_back("attributes: the input's " + a.name + " is not in the output (not checked)");
            continue;
        }
        if (o->values.size() != in.out_points.size() * o->components || a.values.size() != in.in_points.size() * a.components) {
            failures.push_back(a.name + ": " + std::to_string(o->values.size()) + " output values for " +
                               std::to_string(in.out_points.size()) + " vertices of " + std::to_string(o->components) + " components");
            continue;
        }
        if (o->components < a.components)
            notes.push_back("attributes: the output holds " + std::to_string(o->components) + " of " + a.name + "'s " +
                            std::to_string(a.components) + " components; those are checked");
        if (const size_t bad = check_one(a, *o, src, referenced, failures); bad > 5)
            failures.push_back(a.name + ": " + std::to_string(bad - 5) + " more vertices differ");
        checked += (checked.empty() ? "" : ", ") + a.name + " (" + o->storage + ")";
    }
    if (!checked.empty()) notes.push_back("attributes checked at every output vertex: " + checked);
}

}  // namespace singlestrip::verify_detail
