// Vertex attributes carried to the strip's vertices (attributes.hpp).
#include "singlestrip/attributes.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace singlestrip {
namespace {

double dot(const Point3& x, const Point3& y) {
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

/// Barycentric coordinates of p's projection into triangle abc, clamped into it (a midpoint lies
/// on an edge; clamping absorbs rounding). A degenerate triangle gives its first corner.
std::array<double, 3> barycentric(const Point3& p, const Point3& a, const Point3& b, const Point3& c) {
    const Point3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]},
        q{p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    const double uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), qu = dot(q, u), qv = dot(q, v), det = uu * vv - uv * uv;
    if (!(std::abs(det) > 0)) return {1, 0, 0};
    double s = (vv * qu - uv * qv) / det, t = (uu * qv - uv * qu) / det;
    s = std::clamp(s, 0.0, 1.0);
    t = std::clamp(t, 0.0, 1.0 - s);
    return {1 - s - t, s, t};
}

}  // namespace

std::vector<AttributeSource> attribute_sources(const std::vector<Point3>& in_points, const std::vector<Triangle>& in_faces,
                                               const std::vector<Point3>& out_points, const std::vector<Triangle>& out_faces,
                                               const std::vector<uint32_t>& parent) {
    const std::size_t n = in_points.size(), N = out_points.size();
    std::vector<AttributeSource> src(N);
    std::vector<char> done(N, 0);
    for (std::size_t v = 0; v < std::min(n, N); ++v) {
        src[v].v[0] = src[v].nearest = static_cast<uint32_t>(v);
        done[v] = 1;
    }
    for (std::size_t f = 0; f < out_faces.size() && f < parent.size(); ++f)
        for (uint32_t v : out_faces[f]) {
            if (v >= N || done[v]) continue;
            const Triangle& t = in_faces[parent[f]];
            src[v].v = t;
            src[v].w = barycentric(out_points[v], in_points[t[0]], in_points[t[1]], in_points[t[2]]);
            src[v].nearest = t[static_cast<std::size_t>(std::max_element(src[v].w.begin(), src[v].w.end()) - src[v].w.begin())];
            done[v] = 1;
        }
    return src;
}

VertexAttribute blend_attribute(const VertexAttribute& in, const std::vector<AttributeSource>& sources) {
    VertexAttribute out{in.name, in.components, in.blend, {}};
    const std::size_t k = in.components;
    out.values.resize(sources.size() * k);
    for (std::size_t i = 0; i < sources.size(); ++i) {
        const AttributeSource& s = sources[i];
        double* val = &out.values[i * k];
        for (std::size_t c = 0; c < k; ++c) {
            if (in.blend == AttributeBlend::Nearest) {
                val[c] = in.values[s.nearest * k + c];
                continue;
            }
            double x = 0;
            for (std::size_t j = 0; j < 3; ++j)
                if (s.w[j] != 0) x += s.w[j] * in.values[s.v[j] * k + c];
            val[c] = x;
        }
        // A vertex that is an input vertex keeps its values exactly (even a file's non-unit normal).
        if (in.blend != AttributeBlend::Unit || k < 3 || (s.w[1] == 0 && s.w[2] == 0)) continue;
        const double len = std::sqrt(val[0] * val[0] + val[1] * val[1] + val[2] * val[2]);
        for (std::size_t c = 0; c < 3; ++c) val[c] = len > 0 ? val[c] / len : (c == 2 ? 1.0 : 0.0);
        if (k == 4) val[3] = in.values[s.nearest * k + 3];  // TANGENT's handedness is a sign, not a quantity
    }
    return out;
}

AttributeBlend blend_for(const std::string& name) {
    if (name == "NORMAL" || name == "TANGENT") return AttributeBlend::Unit;
    if (name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0) return AttributeBlend::Nearest;
    return AttributeBlend::Linear;
}

void append_copies(std::vector<VertexAttribute>& attrs, const std::vector<uint32_t>& copied_from) {
    for (VertexAttribute& a : attrs) {
        const std::size_t k = a.components;
        for (uint32_t v : copied_from)
            for (std::size_t c = 0; c < k; ++c) a.values.push_back(a.values[v * k + c]);
    }
}

std::string attribute_problem(const std::vector<VertexAttribute>& attrs, std::size_t points) {
    for (const VertexAttribute& a : attrs) {
        if (a.components == 0 || a.values.size() != points * a.components)
            return "attribute '" + a.name + "' has " + std::to_string(a.values.size()) + " values for " + std::to_string(points) +
                   " vertices of " + std::to_string(a.components) + " components";
        for (std::size_t i = 0; i < a.values.size(); ++i)
            if (!std::isfinite(a.values[i]))
                return "attribute '" + a.name + "' of vertex " + std::to_string(i / a.components) + " is not finite";
    }
    return {};
}

}  // namespace singlestrip
