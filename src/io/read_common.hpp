// singlestrip — what the mesh readers (read_obj.cpp, read_off.cpp, read_ply.cpp, read_stl.cpp)
// share: loading the bytes once within the limits, strict number parsing, a text cursor that
// counts lines, and the soup builder that fan-triangulates polygons.
//
// Contract shared by every reader: it parses the file's bytes once, front to back, in O(size);
// it never allocates from a count the file declares unless the bytes left can hold that many
// items (memory O(file size)); every refusal is an InputError "<path>: <where>: <problem>" where
// <where> is a line (text) or an element and item number (binary), and face numbers are the
// file's polygon numbers.
#pragma once

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "singlestrip/io.hpp"
#include "singlestrip/soup.hpp"

namespace singlestrip::io_detail {

[[noreturn]] void fail(const std::string& path, const std::string& what);

/// A file's bytes: an uninitialised buffer (zero-filling hundreds of MB first would be wasted).
struct Bytes {
    std::unique_ptr<char[]> data;
    std::size_t size = 0;
    std::string_view view() const { return {data.get(), size}; }
};

/// Every byte of `path` (a regular file or a pipe, read to its end), refused past
/// `options.max_input_bytes`, for a missing file, a directory, a device or a socket.
Bytes load_bytes(const std::string& path, const ReadOptions& options);

inline bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

/// from_chars reports underflow and overflow alike: strtod tells them apart (underflow gives
/// 0 or a subnormal, overflow infinity, refused).
bool parse_out_of_range(const char* b, const char* e, double& v);

/// A finite decimal number, [+-]?(d+(.d*)?|.d+)([eE][+-]?d+)?, and nothing else ("nan", "inf",
/// hex and "+-0" are not numbers here). An underflow reads as 0 (or a subnormal); an overflow
/// is refused like a non-finite value.
inline bool parse_real(std::string_view t, double& v) {
    const char* b = t.data();
    const char* e = b + t.size();
    const char* digits = b != e && (*b == '+' || *b == '-') ? b + 1 : b;
    if (digits == e || !((*digits >= '0' && *digits <= '9') || *digits == '.')) return false;
    if (*b == '+') ++b;  // from_chars takes no '+'; "+-0" was refused above
    const auto r = std::from_chars(b, e, v);
    if (r.ptr != e) return false;
    if (r.ec == std::errc::result_out_of_range) return parse_out_of_range(b, e, v);
    return r.ec == std::errc();
}

/// A decimal integer, [+-]?d+ (any number of leading zeros), in [-2^63, 2^63). Hand-written:
/// indices are most of a text mesh, and this is faster than from_chars.
inline bool parse_integer(std::string_view t, long long& v) {
    const char* b = t.data();
    const char* e = b + t.size();
    const bool negative = b != e && *b == '-';
    if (b != e && (*b == '+' || *b == '-')) ++b;
    if (b == e) return false;
    while (e - b > 1 && *b == '0') ++b;
    if (e - b > 19) return false;
    unsigned long long u = 0;
    for (const char* p = b; p != e; ++p) {
        const unsigned d = static_cast<unsigned char>(*p) - unsigned{'0'};
        if (d > 9) return false;
        u = u * 10 + d;  // 19 digits fit in 64 bits
    }
    if (u > (negative ? 1ull << 63 : (1ull << 63) - 1)) return false;
    v = negative ? static_cast<long long>(0 - u) : static_cast<long long>(u);
    return true;
}

/// Why `t` is not a coordinate: "has a non-finite coordinate 'nan'" for what strtod reads as
/// NaN or infinity (including overflows), else "cannot parse coordinate 'x'".
std::string coordinate_problem(std::string_view t);

/// `t` in quotes, cut to 40 characters, for messages.
std::string quoted(std::string_view t);

/// Whitespace-separated tokens of a text file, with the line number of the current position.
struct TextCursor {
    const char* p;
    const char* end;
    std::size_t line = 1;

    explicit TextCursor(std::string_view d) : p(d.data()), end(d.data() + d.size()) {}
    bool at_end() const { return p == end; }
    /// Skips whitespace (counting newlines) and returns the next token, empty at the end.
    std::string_view token() {
        while (p != end && is_space(*p)) line += *p++ == '\n';
        const char* b = p;
        while (p != end && !is_space(*p)) ++p;
        return {b, static_cast<std::size_t>(p - b)};
    }
    /// Like token(), but stops at the end of the current line (empty there).
    std::string_view token_on_line() {
        while (p != end && is_space(*p) && *p != '\n') ++p;
        const char* b = p;
        while (p != end && !is_space(*p)) ++p;
        return {b, static_cast<std::size_t>(p - b)};
    }
    /// Moves past the next newline.
    void next_line();
};

/// Collects a reader's output: points, and polygons fan-triangulated (v0, vi, vi+1) in file order.
class SoupBuilder {
public:
    explicit SoupBuilder(const std::string& path) : path_(path) {}
    TriangleSoup soup;

    /// Appends polygon `corners` (k >= 3, indices checked by the caller) as k-2 triangles.
    void add_polygon(const uint32_t* corners, std::size_t k) {
        check_room(k - 2);
        for (std::size_t i = 1; i + 1 < k; ++i) {
            soup.triangles.push_back({corners[0], corners[i], corners[i + 1]});
            soup.source_polygon.push_back(polygon_);
        }
        ++polygon_;
    }
    void add_triangle(uint32_t a, uint32_t b, uint32_t c) {
        check_room(1);
        soup.triangles.push_back({a, b, c});
        soup.source_polygon.push_back(polygon_++);
    }
    /// Reserves for at most `triangles` more (callers bound it by the bytes left).
    void reserve_triangles(std::size_t triangles) {
        soup.triangles.reserve(soup.triangles.size() + triangles);
        soup.source_polygon.reserve(soup.source_polygon.size() + triangles);
    }
    uint32_t polygons() const { return polygon_; }
    /// Refuses an empty soup: "no faces (<why>)".
    TriangleSoup finish(const std::string& no_faces_detail);

private:
    void check_room(std::size_t more) {
        if (soup.triangles.size() + more >= 0xffffffffu) fail(path_, "too many triangles (more than 2^32-2)");
    }
    const std::string& path_;
    uint32_t polygon_ = 0;
};

/// Upper bound on how many items `bytes` can hold at `min_bytes` each: what a reader may reserve.
inline std::size_t fit(std::size_t bytes, std::size_t min_bytes, unsigned long long declared) {
    const std::size_t most = bytes / min_bytes + 1;
    return declared < most ? static_cast<std::size_t>(declared) : most;
}

// The four readers: `d` is the whole file.
TriangleSoup read_obj(const std::string& path, std::string_view d);
TriangleSoup read_off(const std::string& path, std::string_view d);
TriangleSoup read_ply(const std::string& path, std::string_view d);
TriangleSoup read_stl(const std::string& path, std::string_view d);

}  // namespace singlestrip::io_detail
