// singlestrip — STL reader (ASCII and binary).
//
// Contract. Binary: an 80-byte header, a little-endian uint32 triangle count N, then N records
// of 50 bytes (normal, three float32 corners, a 2-byte attribute); bytes after them are ignored.
// ASCII: one or more "solid [name] ... endsolid [name]" blocks of facets, each exactly
// "facet normal nx ny nz outer loop vertex x y z (three times) endloop endfacet" (the normal is
// not read; "normal nx ny nz" may be left out); a UTF-8 byte-order mark is skipped. Which one:
// a file whose size is exactly 84 + 50 N is binary (an ASCII file cannot have that size below
// 7.5 GB: its count bytes are text); otherwise a file starting with "solid" and a separator is
// ASCII, falling back to binary when it fails as ASCII but holds N records; anything else is
// binary. STL has no shared vertices: corners are welded when their coordinates are equal as
// doubles (so -0 == +0; no tolerance) and numbered in order of first appearance. Coordinates
// must be finite. Errors name the line and facet (ASCII) or the triangle (binary).
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "read_common.hpp"
#include "singlestrip/errors.hpp"

namespace singlestrip::io_detail {
namespace {

/// Corner welding: an open-addressing table of vertex numbers keyed by exact coordinates.
class Welder {
public:
    Welder(std::vector<Point3>& points, std::size_t expected) : points_(points) { rehash(expected); }
    uint32_t index(const Point3& p) {
        std::size_t h = hash(p) & mask_;
        for (;; h = (h + 1) & mask_) {
            const uint32_t v = table_[h];
            if (v == kEmpty) break;
            if (points_[v] == p) return v;  // == : -0 and +0 are one vertex
        }
        const auto v = static_cast<uint32_t>(points_.size());
        points_.push_back(p);
        table_[h] = v;
        if (points_.size() * 2 > table_.size()) rehash(points_.size());
        return v;
    }

private:
    static constexpr uint32_t kEmpty = 0xffffffffu;
    static std::size_t hash(const Point3& p) {
        uint64_t h = 0x9e3779b97f4a7c15ull;
        for (double c : p) {
            uint64_t b = 0;
            const double z = c + 0.0;  // -0 hashes as +0
            std::memcpy(&b, &z, 8);
            h = (h ^ b) * 0xff51afd7ed558ccdull;
            h ^= h >> 32;
        }
        return static_cast<std::size_t>(h);
    }
    void rehash(std::size_t vertices) {
        std::size_t size = 1024;
        while (size < 2 * vertices + 2) size *= 2;
        table_.assign(size, kEmpty);
        mask_ = size - 1;
        for (uint32_t v = 0; v < points_.size(); ++v) {
            std::size_t h = hash(points_[v]) & mask_;
            while (table_[h] != kEmpty) h = (h + 1) & mask_;
            table_[h] = v;
        }
    }
    std::vector<Point3>& points_;
    std::vector<uint32_t> table_;
    std::size_t mask_ = 0;
};

uint32_t le32(const char* p) {
    const auto* u = reinterpret_cast<const unsigned char*>(p);
    return static_cast<uint32_t>(u[0]) | static_cast<uint32_t>(u[1]) << 8 | static_cast<uint32_t>(u[2]) << 16 |
           static_cast<uint32_t>(u[3]) << 24;
}

TriangleSoup read_binary(const std::string& path, std::string_view d, uint32_t n) {
    SoupBuilder out(path);
    out.reserve_triangles(n);
    Welder weld(out.soup.points, n / 2);
    for (uint32_t t = 0; t < n; ++t) {
        const char* rec = d.data() + 84 + 50 * static_cast<std::size_t>(t) + 12;
        uint32_t v[3];
        for (int k = 0; k < 3; ++k) {
            Point3 p;
            for (int j = 0; j < 3; ++j) {
                const uint32_t u = le32(rec + 12 * k + 4 * j);
                float x = 0;
                std::memcpy(&x, &u, 4);
                if (!std::isfinite(x))
                    fail(path, "binary STL triangle " + std::to_string(t) + ": vertex " + std::to_string(k) +
                                   " has a non-finite coordinate (NaN or infinity)");
                p[static_cast<std::size_t>(j)] = x;
            }
            v[k] = weld.index(p);
        }
        out.add_triangle(v[0], v[1], v[2]);
    }
    return out.finish("the binary STL header declares 0 triangles");
}

class AsciiStl {
public:
    AsciiStl(const std::string& path, std::string_view d) : path_(path), c_(d), out_(path) {}
    TriangleSoup run();

private:
    [[noreturn]] void bad(const std::string& what) const {
        fail(path_, "line " + std::to_string(c_.line) + ": facet " + std::to_string(facet_) + ": " + what);
    }
    void expect(std::string_view word) {
        const std::string_view t = c_.token();
        if (t.empty()) truncated();
        if (t != word) bad("expected '" + std::string(word) + "' but found " + quoted(t));
    }
    [[noreturn]] void truncated() const {
        fail(path_, "truncated ASCII STL file: it ends inside facet " + std::to_string(facet_) + " (no 'endsolid')");
    }
    void facet(Welder& weld);

    const std::string& path_;
    TextCursor c_;
    SoupBuilder out_;
    uint32_t facet_ = 0;
};

TriangleSoup AsciiStl::run() {
    // A facet takes at least about 100 bytes of text: a hint only.
    out_.reserve_triangles((c_.end - c_.p) / 100);
    Welder weld(out_.soup.points, static_cast<std::size_t>(c_.end - c_.p) / 200);
    if (c_.end - c_.p >= 3 && std::memcmp(c_.p, "\xEF\xBB\xBF", 3) == 0) c_.p += 3;
    for (std::string_view t = c_.token(); !t.empty(); t = c_.token()) {
        if (t != "solid") fail(path_, "line " + std::to_string(c_.line) + ": expected 'solid' but found " + quoted(t));
        c_.next_line();  // the solid's name
        for (;;) {
            t = c_.token();
            if (t.empty())
                fail(path_, "truncated ASCII STL file: no 'endsolid' after facet " + std::to_string(facet_) + " (line " +
                                std::to_string(c_.line) + ")");
            if (t == "endsolid") break;
            if (t != "facet") bad("expected 'facet' or 'endsolid' but found " + quoted(t));
            facet(weld);
        }
        c_.next_line();  // the name after endsolid
    }
    return out_.finish("the file has " + std::to_string(out_.soup.points.size()) + " vertices and 0 faces");
}

void AsciiStl::facet(Welder& weld) {
    std::string_view t = c_.token();
    if (t == "normal") {
        for (int k = 0; k < 3; ++k)
            if (c_.token().empty()) truncated();  // not read: some writers put nan here
        t = c_.token();
    }
    if (t.empty()) truncated();
    if (t != "outer") bad("expected 'outer' but found " + quoted(t));
    expect("loop");
    uint32_t v[3];
    for (int k = 0; k < 3; ++k) {
        t = c_.token();
        if (t.empty()) truncated();
        if (t != "vertex") bad("expected 'vertex' (a facet has 3) but found " + quoted(t));
        Point3 p;
        for (int j = 0; j < 3; ++j) {
            t = c_.token();
            if (t.empty()) truncated();
            if (!parse_real(t, p[static_cast<std::size_t>(j)])) bad("vertex " + std::to_string(k) + " " + coordinate_problem(t));
        }
        v[k] = weld.index(p);
    }
    expect("endloop");
    expect("endfacet");
    if (out_.soup.triangles.size() >= 0xfffffffeu) bad("too many triangles");
    out_.add_triangle(v[0], v[1], v[2]);
    ++facet_;
}

/// Whether the file starts (after a byte-order mark and whitespace) with "solid" and a separator.
bool starts_with_solid(std::string_view d) {
    std::size_t a = d.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
    while (a < d.size() && is_space(d[a])) ++a;
    return d.substr(a, 5) == "solid" && (a + 5 == d.size() || is_space(d[a + 5]));
}

}  // namespace

TriangleSoup read_stl(const std::string& path, std::string_view d) {
    const uint32_t n = d.size() >= 84 ? le32(d.data() + 80) : 0;
    const std::size_t need = 84 + 50 * static_cast<std::size_t>(n);
    const bool binary_fits = d.size() >= 84 && need <= d.size();
    if (binary_fits && need == d.size()) return read_binary(path, d, n);
    if (starts_with_solid(d)) {
        try {
            return AsciiStl(path, d).run();
        } catch (const InputError&) {
            if (!binary_fits) throw;
        }
        return read_binary(path, d, n);
    }
    if (binary_fits) return read_binary(path, d, n);
    if (d.size() < 84) fail(path, "truncated binary STL file: " + std::to_string(d.size()) + " bytes, less than the 84-byte header");
    fail(path, "truncated binary STL file: the header declares " + std::to_string(n) + " triangles (" + std::to_string(need) +
                   " bytes) but the file has " + std::to_string(d.size()) + " bytes");
}

}  // namespace singlestrip::io_detail
