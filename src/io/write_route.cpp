// Route files: CSV, JSON, OBJ polyline, GeoJSON LineString (route.hpp).
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <string>

#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/route.hpp"

namespace singlestrip {
namespace {

/// Shortest decimal that reads back exactly (JSON has no NaN: coordinates are finite here).
std::string num(double v) {
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, res.ptr);
}
/// For JSON, which has no infinity: a length beyond double's range (a route over coordinates
/// near 1e308) is null.
std::string jnum(double v) {
    return std::isfinite(v) ? num(v) : "null";
}

const char* kind(const RoutePoint& p) {
    return p.jump ? "start" : p.centroid ? "centroid" : "edge";
}

std::string csv(const Route& r) {
    std::string s = "x,y,z,face,parent,kind,distance\n";
    for (const RoutePoint& p : r.points)
        s += num(p.position[0]) + ',' + num(p.position[1]) + ',' + num(p.position[2]) + ',' + std::to_string(p.face) + ',' +
             std::to_string(p.parent) + ',' + kind(p) + ',' + num(p.distance) + '\n';
    return s;
}

std::string json(const Route& r) {
    std::string s = "{\"length\": " + jnum(r.length) + ", \"planar_z\": " + (r.planar_z ? "true" : "false") + ", \"points\": [";
    for (size_t i = 0; i < r.points.size(); ++i) {
        const RoutePoint& p = r.points[i];
        s += std::string(i ? ",\n  " : "\n  ") + "{\"x\": " + num(p.position[0]) + ", \"y\": " + num(p.position[1]) +
             ", \"z\": " + num(p.position[2]) + ", \"face\": " + std::to_string(p.face) + ", \"parent\": " + std::to_string(p.parent) +
             ", \"kind\": \"" + kind(p) + "\", \"distance\": " + jnum(p.distance) + "}";
    }
    return s + (r.points.empty() ? "]}\n" : "\n]}\n");
}

std::string obj(const Route& r) {
    std::string s = "# singlestrip route: " + std::to_string(r.points.size()) + " points through face centroids and shared-edge " +
                    "midpoints, length " + num(r.length) + "\n";
    for (const RoutePoint& p : r.points) s += "v " + num(p.position[0]) + ' ' + num(p.position[1]) + ' ' + num(p.position[2]) + '\n';
    // One `l` record per strip (jumps start a new one); a single point is not a polyline.
    for (size_t b = 0, strip = 0; b < r.points.size(); ++strip) {
        size_t e = b + 1;
        while (e < r.points.size() && !r.points[e].jump) ++e;
        if (e - b >= 2) {
            s += strip == 0 ? "o route\nl" : "o route_" + std::to_string(strip) + "\nl";
            for (size_t i = b + 1; i <= e; ++i) s += ' ' + std::to_string(i);
            s += '\n';
        }
        b = e;
    }
    return s;
}

/// One LineString Feature for points [b, e) of the route.
std::string geojson_feature(const Route& r, size_t b, size_t e, size_t strip) {
    std::string coords, faces;
    for (size_t i = b; i < e; ++i) {
        const RoutePoint& p = r.points[i];
        coords += std::string(i > b ? ", " : "") + '[' + num(p.position[0]) + ", " + num(p.position[1]) + ']';
        faces += std::string(i > b ? ", " : "") + std::to_string(p.face);
    }
    // A LineString needs two positions: a one-face strip repeats its point.
    if (e - b == 1) coords += ", " + coords;
    const double length = (e < r.points.size() ? r.points[e - 1].distance : r.length) - r.points[b].distance;
    return "{\"type\": \"Feature\",\n \"geometry\": {\"type\": \"LineString\", \"coordinates\": [" + coords +
           "]},\n \"properties\": {\"name\": \"singlestrip route" + (strip ? " " + std::to_string(strip) : std::string()) +
           "\", \"length\": " + jnum(length) + ", \"z\": " + num(r.points[b].position[2]) + ", \"faces\": [" + faces + "]}}";
}

std::string geojson(const Route& r) {
    if (!r.planar_z)
        throw RequestError("route: GeoJSON needs a mesh that is planar in z (a floor plan); write .csv, .json or .obj for a 3D surface");
    if (r.points.empty())
        return "{\"type\": \"FeatureCollection\", \"features\": [{\"type\": \"Feature\",\n \"geometry\": {\"type\": "
               "\"LineString\", \"coordinates\": []},\n \"properties\": {\"name\": \"singlestrip route\", \"length\": 0, "
               "\"z\": 0, \"faces\": []}}]}\n";
    std::string features;
    for (size_t b = 0, strip = 0; b < r.points.size(); ++strip) {  // one Feature per strip
        size_t e = b + 1;
        while (e < r.points.size() && !r.points[e].jump) ++e;
        features += (strip ? ",\n" : "") + geojson_feature(r, b, e, strip);
        b = e;
    }
    return "{\"type\": \"FeatureCollection\", \"features\": [" + features + "]}\n";
}

}  // namespace

RouteFormat parse_route_format(const std::string& name) {
    const std::string n = ascii_lower(name);
    if (n == "csv") return RouteFormat::Csv;
    if (n == "json") return RouteFormat::Json;
    if (n == "obj") return RouteFormat::Obj;
    if (n == "geojson") return RouteFormat::GeoJson;
    throw RequestError("unknown route format '" + name + "' (csv, json, obj or geojson)");
}

RouteFormat route_format_for(const std::string& path) {
    const std::string ext = lower_extension(path);
    if (ext.size() > 1) {
        try {
            return parse_route_format(ext.substr(1));
        } catch (const RequestError&) {
        }
    }
    throw RequestError(path + ": unknown route file extension '" + ext + "' (expected .csv, .json, .obj or .geojson)");
}

std::string route_text(const Route& route, RouteFormat format) {
    switch (format) {
        case RouteFormat::Csv:
            return csv(route);
        case RouteFormat::Json:
            return json(route);
        case RouteFormat::Obj:
            return obj(route);
        case RouteFormat::GeoJson:
            return geojson(route);
    }
    throw InternalError("route_text: unknown format");
}

void write_route(const std::string& path, const Route& route) {
    write_text_atomic(path, route_text(route, route_format_for(path)));
}

}  // namespace singlestrip
