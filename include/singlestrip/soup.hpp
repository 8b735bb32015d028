// singlestrip — the plain arrays between the layers: the triangle soup every reader produces and
// every algorithm takes, and the strip's output arrays and cycles every writer takes.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace singlestrip {

using Point3 = std::array<double, 3>;
using Triangle = std::array<uint32_t, 3>;

/// How a vertex attribute is carried to a new vertex (a split midpoint) inside a face.
enum class AttributeBlend : uint8_t {
    Linear,  ///< barycentric average (texture coordinates, colours, plain scalars)
    Unit,    ///< barycentric average of xyz, renormalised (NORMAL; TANGENT keeps w of the nearest corner)
    Nearest  ///< copied from the nearest corner (ids, skin joints and their weights)
};

/// One per-vertex attribute beside the positions. Names follow glTF: NORMAL, TANGENT,
/// TEXCOORD_n, COLOR_n (RGBA in [0, 1]), JOINTS_n, WEIGHTS_n; any other name is a custom
/// attribute (a PLY property name, a glTF "_NAME"). `values` holds `components` numbers per
/// vertex of the soup, vertex after vertex.
struct VertexAttribute {
    std::string name;
    uint32_t components = 1;
    AttributeBlend blend = AttributeBlend::Linear;
    std::vector<double> values;
};

/// Vertices in file order and triangles (indices into `points`), after fan triangulation of
/// polygons. `source_polygon[t]` is the index of the file polygon triangle t came from.
/// A vertex is a position plus its attributes: where a file gives one position several
/// attribute values (an OBJ `vt`/`vn` seam), the soup holds one vertex per combination, so the
/// seam is an edge between different vertices (a boundary for the strip).
struct TriangleSoup {
    std::vector<Point3> points;
    std::vector<Triangle> triangles;
    std::vector<uint32_t> source_polygon;          ///< same size as triangles (may be empty if 1:1)
    std::vector<VertexAttribute> attributes = {};  ///< each with points.size() * components values
};

/// One constraint edge (an edge the strip never crosses): two input vertex numbers, 0-based, and
/// the line of the constraint file it was read from, or 0 when it was given as a pair. The line
/// lets every message about the edge name the place the user wrote it.
struct ConstraintEdge {
    uint32_t a = 0, b = 0;
    uint32_t line = 0;
    friend bool operator==(const ConstraintEdge&, const ConstraintEdge&) = default;
};

/// Output arrays in strip order: faces as vertex triples (orientation kept) and the input
/// triangle each lies in (strip_arrays(), strip.hpp).
struct StripArrays {
    std::vector<Point3> points;
    std::vector<Triangle> faces;
    std::vector<uint32_t> parent;
    /// Per output vertex, when the input had attributes (stripify() fills them, attributes.hpp);
    /// strip_arrays() leaves them empty.
    std::vector<VertexAttribute> attributes = {};
};

/// Where a cycle came from (see the top of this header).
enum class CycleSource : uint8_t { SteepestAscent, SteepestDescent, StripSegment, ShortestPath, TreeCotree, ParallelPath };

struct Cycles {
    /// Face indices into the OUTPUT (strip order), one closed chain per cycle.
    std::vector<std::vector<uint32_t>> cycles;
    /// Geometric length of each cycle (see cycle_length()), same order as `cycles`.
    std::vector<double> lengths;
    /// How each cycle was obtained (empty for cycles not made by compute_fundamental_cycles()).
    std::vector<CycleSource> sources;
};

/// The attribute named `name`, or nullptr.
inline const VertexAttribute* find_attribute(const std::vector<VertexAttribute>& attrs, const std::string& name) {
    for (const VertexAttribute& a : attrs)
        if (a.name == name) return &a;
    return nullptr;
}

}  // namespace singlestrip
