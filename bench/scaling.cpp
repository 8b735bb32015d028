// singlestrip bench — geodesic sphere and a plain binary PLY writer for the scaling series.
#include "scaling.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "singlestrip/errors.hpp"

namespace singlestrip::bench {

TriangleSoup make_geodesic_sphere(uint32_t n) {
    if (n == 0) throw RequestError("geodesic sphere needs n >= 1");
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    const std::vector<Point3> corner = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                        {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    const std::vector<Triangle> ico = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                       {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                                       {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    TriangleSoup s;
    s.points = corner;
    s.points.reserve(size_t{10} * n * n + 2);
    s.triangles.reserve(size_t{20} * n * n);
    auto lerp = [](const Point3& a, const Point3& b, double u) {
        return Point3{a[0] + (b[0] - a[0]) * u, a[1] + (b[1] - a[1]) * u, a[2] + (b[2] - a[2]) * u};
    };
    // n-1 vertices per icosahedron edge, numbered from its lower corner, shared by both faces.
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> edge_base;
    for (const Triangle& f : ico) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = std::min(f[k], f[(k + 1) % 3]), b = std::max(f[k], f[(k + 1) % 3]);
            if (edge_base.count({a, b})) continue;
            edge_base[{a, b}] = static_cast<uint32_t>(s.points.size());
            for (uint32_t i = 1; i < n; ++i) s.points.push_back(lerp(corner[a], corner[b], double(i) / n));
        }
    }
    // Vertex k steps from x toward y on edge (x, y), 0 < k < n.
    auto on_edge = [&](uint32_t x, uint32_t y, uint32_t k) {
        return x < y ? edge_base.at({x, y}) + k - 1 : edge_base.at({y, x}) + (n - k) - 1;
    };
    std::vector<uint32_t> local;  // (i, j) -> vertex of the current face, row-major over j
    for (const Triangle& f : ico) {
        const uint32_t A = f[0], B = f[1], C = f[2];
        // P(i, j) = A + (B - A) i/n + (C - A) j/n, i, j >= 0, i + j <= n.
        auto idx = [n](uint32_t i, uint32_t j) { return size_t{j} * (n + 1) + i; };
        local.assign(size_t{n + 1} * (n + 1), 0);
        for (uint32_t j = 0; j <= n; ++j) {
            for (uint32_t i = 0; i + j <= n; ++i) {
                uint32_t v;
                if (i == 0 && j == 0)
                    v = A;
                else if (i == n)
                    v = B;
                else if (j == n)
                    v = C;
                else if (j == 0)
                    v = on_edge(A, B, i);
                else if (i == 0)
                    v = on_edge(A, C, j);
                else if (i + j == n)
                    v = on_edge(B, C, j);
                else {
                    v = static_cast<uint32_t>(s.points.size());
                    const Point3 p = lerp(corner[A], corner[B], double(i) / n);
                    const Point3 q = lerp(corner[A], corner[C], double(j) / n);
                    s.points.push_back({p[0] + q[0] - corner[A][0], p[1] + q[1] - corner[A][1], p[2] + q[2] - corner[A][2]});
                }
                local[idx(i, j)] = v;
            }
        }
        for (uint32_t j = 0; j < n; ++j) {
            for (uint32_t i = 0; i + j < n; ++i) {
                s.triangles.push_back({local[idx(i, j)], local[idx(i + 1, j)], local[idx(i, j + 1)]});
                if (i + j + 1 < n) s.triangles.push_back({local[idx(i + 1, j)], local[idx(i + 1, j + 1)], local[idx(i, j + 1)]});
            }
        }
    }
    for (Point3& p : s.points) {
        const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (double& c : p) c /= len;
    }
    return s;
}

void write_binary_ply(const std::string& path, const TriangleSoup& soup) {
    struct Closer {
        void operator()(std::FILE* f) const { std::fclose(f); }
    };
    std::unique_ptr<std::FILE, Closer> f(std::fopen(path.c_str(), "wb"));
    if (!f) throw OutputError(path + ": cannot open for writing");
    const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(soup.points.size()) +
                               "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                               std::to_string(soup.triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
    bool ok = std::fwrite(header.data(), 1, header.size(), f.get()) == header.size();
    // Buffered in blocks: one fwrite per element would dominate the time at 10M faces.
    std::vector<char> buf;
    buf.reserve(1 << 20);
    auto flush = [&] {
        ok = ok && std::fwrite(buf.data(), 1, buf.size(), f.get()) == buf.size();
        buf.clear();
    };
    for (const Point3& p : soup.points) {
        const float xyz[3] = {float(p[0]), float(p[1]), float(p[2])};
        const char* b = reinterpret_cast<const char*>(xyz);
        buf.insert(buf.end(), b, b + sizeof xyz);
        if (buf.size() > (1 << 20) - 64) flush();
    }
    for (const Triangle& t : soup.triangles) {
        buf.push_back(3);
        const int32_t v[3] = {int32_t(t[0]), int32_t(t[1]), int32_t(t[2])};
        const char* b = reinterpret_cast<const char*>(v);
        buf.insert(buf.end(), b, b + sizeof v);
        if (buf.size() > (1 << 20) - 64) flush();
    }
    flush();
    if (std::fclose(f.release()) != 0) ok = false;
    if (!ok) throw OutputError(path + ": write failed");
}

}  // namespace singlestrip::bench
