// singlestrip — the strip's route as a path: for robots, printers and anyone who wants a line,
// not triangles.
//
// The route visits the output faces in strip order. It is the polyline
//   c0, m01, c1, m12, c2, ..., c_{n-1}
// through each face's centroid c_i and the midpoint m_{i,i+1} of the edge it shares with the next
// face, so every segment lies inside one face and the route never crosses a constraint edge
// (consecutive strip faces never share one). A one-face strip is the single point c0.
// An output with several strips (one per component, pipeline.hpp) gives one such polyline per
// strip, one after the other: the first centroid of each later strip has `jump` set (kind
// "start"), the move to it leaves the surface and is not counted in `length` or `distance`; the
// OBJ file has one `l` record and the GeoJSON one LineString Feature per strip.
//
// Files (write_route, chosen by extension or by `format`):
//   .csv      header "x,y,z,face,parent,kind,distance", one row per point;
//   .json     {"length": L, "planar_z": bool, "points": [{"x","y","z","face","parent","kind",
//             "distance"}, ...]};
//   .obj      the points as `v` records and one `l` record through them (any mesh viewer);
//   .geojson  a FeatureCollection with one LineString Feature ([x, y] in the mesh's own units,
//             not longitude/latitude) whose properties hold the length and the per-point faces;
//             only when the mesh is planar in z (a floor plan), otherwise RequestError.
// `face` is the output face (= position in the strip), `parent` the input triangle it lies in,
// `kind` "centroid" or "edge" (an edge midpoint carries the face it leaves), `distance` the length
// of the route up to the point.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip {

struct RoutePoint {
    Point3 position{};
    uint32_t face = 0;      ///< output face (strip position)
    uint32_t parent = 0;    ///< input triangle that face lies in
    bool centroid = true;   ///< false: midpoint of the edge shared with face + 1
    double distance = 0.0;  ///< route length from the first point to this one (jumps not counted)
    bool jump = false;      ///< first point of a later strip: reached by a move off the surface
};

struct Route {
    std::vector<RoutePoint> points;
    double length = 0.0;    ///< total polyline length
    bool planar_z = false;  ///< every mesh vertex of the strip has the same z (GeoJSON allowed)
};

/// The route of a strip (see the top of this header).
/// \pre `arrays` comes from strip_arrays(): faces in strip order, parent.size() == faces.size().
/// Consecutive faces that share no edge start a new strip (see above).
/// \throw InternalError when the sizes disagree.
/// Complexity O(F).
Route strip_route(const StripArrays& arrays);

enum class RouteFormat { Csv, Json, Obj, GeoJson };

/// Route file format from `path`'s extension (.csv, .json, .obj, .geojson; any case).
/// \throw RequestError naming the path and the accepted extensions.
RouteFormat route_format_for(const std::string& path);

/// Parses "csv", "json", "obj" or "geojson" (any case); \throw RequestError otherwise.
RouteFormat parse_route_format(const std::string& name);

/// The route file's text in `format`. Coordinates are written as the shortest decimal that reads
/// back exactly. \throw RequestError for GeoJSON when !route.planar_z. O(points).
std::string route_text(const Route& route, RouteFormat format);

/// Writes route_text(route, route_format_for(path)) atomically (temporary + rename).
/// \throw RequestError (extension, GeoJSON of a non-planar mesh) before writing; OutputError.
void write_route(const std::string& path, const Route& route);

}  // namespace singlestrip
