// singlestrip — vertex attributes (soup.hpp VertexAttribute) carried from the input soup to the
// strip's vertices: input vertices keep theirs, a new vertex (a split midpoint) gets its parent
// face's corners blended at its barycentric coordinates (AttributeBlend). One implementation for
// every format: OBJ vt/vn, PLY vertex properties, glTF accessors.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip {

/// Where an output vertex takes its attributes from: up to three input vertices and weights
/// (summing to 1), and the corner of largest weight.
struct AttributeSource {
    std::array<uint32_t, 3> v{0, 0, 0};
    std::array<double, 3> w{1, 0, 0};
    uint32_t nearest = 0;
};

/// Sources of the `out_points.size()` output vertices: vertex v < in_points.size() is input
/// vertex v; any other vertex used by output face f is located in input face parent[f]
/// (barycentric coordinates of its position, clamped into the face); unused ones take vertex 0.
/// \pre every parent < in_faces.size(), every input face index < in_points.size(). O(V + F).
std::vector<AttributeSource> attribute_sources(const std::vector<Point3>& in_points, const std::vector<Triangle>& in_faces,
                                               const std::vector<Point3>& out_points, const std::vector<Triangle>& out_faces,
                                               const std::vector<uint32_t>& parent);

/// `in` evaluated at every source (blend rule of `in.blend`; Unit renormalises the first three
/// components, a zero sum gives (0, 0, 1); TANGENT's w is the nearest corner's). O(V).
VertexAttribute blend_attribute(const VertexAttribute& in, const std::vector<AttributeSource>& sources);

/// The blend rule glTF attribute `name` gets: Unit for NORMAL and TANGENT, Nearest for JOINTS_n
/// and WEIGHTS_n (influences stay paired), Linear otherwise.
AttributeBlend blend_for(const std::string& name);

/// `attrs` with the values of vertex copied_from[j] appended for each j (repair's copies).
void append_copies(std::vector<VertexAttribute>& attrs, const std::vector<uint32_t>& copied_from);

/// Empty when every attribute holds `points` * components finite values, else what is wrong
/// ("attribute 'NORMAL' has 5 values for 3 vertices"). O(values).
std::string attribute_problem(const std::vector<VertexAttribute>& attrs, std::size_t points);

}  // namespace singlestrip
