// The strip's route (route.hpp): geometry, length, formats.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "singlestrip/errors.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/route.hpp"

using namespace singlestrip;

namespace {

/// An n x n grid of unit squares in the plane z = `z`, two triangles each.
TriangleSoup grid(int n, double z = 0.0) {
    TriangleSoup s;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) s.points.push_back({double(x), double(y), z});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const uint32_t a = y * (n + 1) + x;
            s.triangles.push_back({a, a + 1, a + n + 2});
            s.triangles.push_back({a, a + n + 2, a + n + 1});
        }
    return s;
}

double dist(const Point3& p, const Point3& q) {
    return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
}

}  // namespace

TEST(Route, CentroidsAndSharedEdgeMidpointsInStripOrder) {
    const PipelineResult r = stripify(grid(4), PipelineOptions{});
    const Route route = strip_route(r.arrays);
    const size_t n = r.arrays.faces.size();
    ASSERT_EQ(route.points.size(), 2 * n - 1);
    double length = 0;
    for (size_t i = 0; i < route.points.size(); ++i) {
        const RoutePoint& p = route.points[i];
        EXPECT_EQ(p.face, i / 2);
        EXPECT_EQ(p.centroid, i % 2 == 0);
        EXPECT_EQ(p.parent, r.arrays.parent[p.face]);
        if (i) length += dist(route.points[i - 1].position, p.position);
        EXPECT_NEAR(p.distance, length, 1e-9);
        if (p.centroid) {
            const Triangle& t = r.arrays.faces[p.face];
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(p.position[k], (r.arrays.points[t[0]][k] + r.arrays.points[t[1]][k] + r.arrays.points[t[2]][k]) / 3, 1e-12);
        }
    }
    EXPECT_NEAR(route.length, length, 1e-9);
    EXPECT_TRUE(route.planar_z);
}

TEST(Route, PlanarOnlyWhenFlatInZ) {
    EXPECT_TRUE(strip_route(stripify(grid(2, 0.1), PipelineOptions{}).arrays).planar_z);
    TriangleSoup bent = grid(2);
    bent.points[4][2] = 0.5;
    const Route route = strip_route(stripify(bent, PipelineOptions{}).arrays);
    EXPECT_FALSE(route.planar_z);
    EXPECT_THROW(route_text(route, RouteFormat::GeoJson), RequestError);
    EXPECT_NO_THROW(route_text(route, RouteFormat::Obj));
}

TEST(Route, OneFaceIsOnePoint) {
    TriangleSoup one;
    one.points = {{0, 0, 0}, {3, 0, 0}, {0, 3, 0}};
    one.triangles = {{0, 1, 2}};
    const Route route = strip_route(stripify(one, PipelineOptions{}).arrays);
    ASSERT_EQ(route.points.size(), 1u);
    EXPECT_EQ(route.length, 0.0);
    // A LineString needs two positions.
    const auto g = nlohmann::json::parse(route_text(route, RouteFormat::GeoJson));
    EXPECT_EQ(g["features"][0]["geometry"]["coordinates"].size(), 2u);
    EXPECT_EQ(route_text(route, RouteFormat::Obj).find("\nl "), std::string::npos);
}

TEST(Route, FacesThatShareNoEdgeStartANewStrip) {
    // Several components give several strips: the route jumps between them (kind "start"),
    // the jump is not counted in the length, and OBJ / GeoJSON get one polyline per strip.
    StripArrays a;
    a.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {5, 5, 0}, {6, 5, 0}, {5, 6, 0}};
    a.faces = {{0, 1, 2}, {2, 1, 3}, {4, 5, 6}};
    a.parent = {0, 1, 2};
    const Route r = strip_route(a);
    ASSERT_EQ(r.points.size(), 4u);  // c0, m01, c1, then c2 (no midpoint across the gap)
    EXPECT_FALSE(r.points[2].jump);
    EXPECT_TRUE(r.points[3].jump);
    EXPECT_EQ(r.points[3].distance, r.points[2].distance);
    EXPECT_EQ(r.length, r.points[2].distance);
    EXPECT_NE(route_text(r, RouteFormat::Csv).find(",start,"), std::string::npos);
    const std::string obj = route_text(r, RouteFormat::Obj);
    EXPECT_NE(obj.find("\nl 1 2 3\n"), std::string::npos) << obj;
    EXPECT_EQ(obj.find("route_1"), std::string::npos) << obj;  // a one-point strip is no polyline
    const auto g = nlohmann::json::parse(route_text(r, RouteFormat::GeoJson));
    EXPECT_EQ(g["features"].size(), 2u);
    StripArrays bad = a;
    bad.parent.pop_back();
    EXPECT_THROW(strip_route(bad), InternalError);
}

TEST(Route, FormatsByExtensionAndName) {
    EXPECT_EQ(route_format_for("a/b.CSV"), RouteFormat::Csv);
    EXPECT_EQ(route_format_for("r.json"), RouteFormat::Json);
    EXPECT_EQ(route_format_for("r.obj"), RouteFormat::Obj);
    EXPECT_EQ(route_format_for("r.geojson"), RouteFormat::GeoJson);
    EXPECT_THROW(route_format_for("r.txt"), RequestError);
    EXPECT_THROW(route_format_for("route"), RequestError);
    EXPECT_EQ(parse_route_format("GeoJSON"), RouteFormat::GeoJson);
    EXPECT_THROW(parse_route_format("kml"), RequestError);
}

TEST(Route, JsonAndCsvAgree) {
    const Route route = strip_route(stripify(grid(3), PipelineOptions{}).arrays);
    const auto j = nlohmann::json::parse(route_text(route, RouteFormat::Json));
    ASSERT_EQ(j["points"].size(), route.points.size());
    EXPECT_DOUBLE_EQ(j["length"].get<double>(), route.length);
    const std::string csv = route_text(route, RouteFormat::Csv);
    EXPECT_EQ(static_cast<size_t>(std::count(csv.begin(), csv.end(), '\n')), route.points.size() + 1);
}
