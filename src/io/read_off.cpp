// singlestrip — OFF reader (Geomview OFF, ASCII and BINARY).
//
// Contract. Header: optional '#' comment lines, the keyword [ST][C][N]OFF (OFF, COFF, NOFF,
// CNOFF, STOFF, STCOFF, STNOFF, STCNOFF; the 4 and n variants and SKEL are refused by name),
// then the vertex, face and edge counts (edges ignored) on the same or following lines. ASCII
// body: one vertex per line, x y z first, then as the keyword says, in this order: N: nx ny nz;
// C: r g b [a], all integers in [0, 255] or all fractions in [0, 1]; ST: s t (plain OFF: the
// rest of the line is ignored; otherwise the count must match); then one face per line,
// k v1..vk (0-based; a COFF face may end with a colour: 1 colour-map index, or 3 or 4 numbers,
// checked as vertex colours; plain OFF ignores what follows the indices). '#' ends a line.
// Blank and comment lines may come anywhere. Indices and corner counts are integers (an integral
// decimal such as 3.0 is accepted, as CGAL did). BINARY ("OFF BINARY"): big-endian int32 counts,
// float32 x y z (and nx ny nz for NOFF; colours are never stored; ST is refused), faces as int32
// k then k int32 indices. Errors name the line (ASCII) or the face/vertex number (binary).
//
// Attributes kept (TriangleSoup::attributes, the names the PLY and OBJ readers use): normals
// as NORMAL (unit blend), vertex colours as COLOR_0 in [0, 1] (a file with an all-integer colour
// above 1 is in bytes: its all-integer colours are divided by 255; alpha, 1 when absent, is
// scaled alike and clamped into [0, 1]; 4 components if any vertex has alpha), texture
// coordinates as TEXCOORD_0. Face colours are checked but not kept: a strip has no faces of the
// file's to carry them to.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "read_common.hpp"

namespace singlestrip::io_detail {
namespace {

struct Variant {
    bool colours = false, normals = false, textures = false;
    std::string keyword;
};

/// One vertex colour as written: r g b [a] and whether alpha was there.
struct RawColour {
    double c[4] = {0, 0, 0, 1};
    bool alpha = false;
};

bool integral(double x) {
    return std::floor(x) == x;
}

std::string number_text(double x) {
    std::ostringstream o;
    o << x;
    return o.str();
}

/// A non-negative integral index or count: an integer, or a decimal with an integral value.
bool parse_index(std::string_view t, unsigned long long& v) {
    long long i = 0;
    if (parse_integer(t, i)) {
        v = static_cast<unsigned long long>(i);
        return i >= 0;
    }
    double x = 0;
    if (!parse_real(t, x) || x < 0 || x >= 9.0e18 || std::floor(x) != x) return false;
    v = static_cast<unsigned long long>(x);
    return true;
}

/// Colours are three integers in [0, 255] or three fractions in [0, 1] (a fourth, alpha, is not checked).
std::string colour_problem(const double rgb[3]) {
    const bool integers = std::floor(rgb[0]) == rgb[0] && std::floor(rgb[1]) == rgb[1] && std::floor(rgb[2]) == rgb[2];
    for (int i = 0; i < 3; ++i)
        if (!(integers ? rgb[i] >= 0 && rgb[i] <= 255 : rgb[i] >= 0 && rgb[i] <= 1))
            return "colour component " + number_text(rgb[i]) +
                   " out of range (colours are three integers in [0, 255] or three fractions in [0, 1])";
    return {};
}

/// One line of an ASCII body: tokens up to the newline or a '#'.
struct Line {
    const char* p;
    const char* end;
    std::string_view token() {
        while (p != end && is_space(*p)) ++p;
        const char* b = p;
        while (p != end && !is_space(*p)) ++p;
        return {b, static_cast<std::size_t>(p - b)};
    }
};

class OffReader {
public:
    OffReader(const std::string& path, std::string_view d) : path_(path), d_(d), c_(d), out_(path) {}
    TriangleSoup run();

private:
    void skip_comments() {
        for (;;) {
            while (!c_.at_end() && is_space(*c_.p)) c_.line += *c_.p++ == '\n';
            if (c_.at_end() || *c_.p != '#') return;
            c_.next_line();
        }
    }
    /// The next line holding data (comments and blank lines skipped), '#' cut off; false at the end.
    bool data_line(Line& l) {
        skip_comments();
        if (c_.at_end()) return false;
        const char* nl = static_cast<const char*>(std::memchr(c_.p, '\n', static_cast<std::size_t>(c_.end - c_.p)));
        const char* end = nl ? nl : c_.end;
        const char* hash = static_cast<const char*>(std::memchr(c_.p, '#', static_cast<std::size_t>(end - c_.p)));
        l = {c_.p, hash ? hash : end};
        line_ = c_.line;
        c_.p = end;
        return true;
    }
    [[noreturn]] void fail_line(const std::string& what) { fail(path_, "line " + std::to_string(line_) + ": " + what); }
    unsigned long long header_count(const char* what);
    void ascii_vertices(unsigned long long nv);
    void ascii_faces(unsigned long long nf);
    void face_colour(Line& l, uint64_t f);
    void binary_body();
    void keep_attributes();

    const std::string& path_;
    std::string_view d_;
    TextCursor c_;
    SoupBuilder out_;
    Variant v_;
    std::size_t line_ = 0;
    std::vector<uint32_t> corners_;
    std::vector<RawColour> colours_;
    VertexAttribute normals_{"NORMAL", 3, AttributeBlend::Unit, {}};
    VertexAttribute texcoords_{"TEXCOORD_0", 2, AttributeBlend::Linear, {}};
};

unsigned long long OffReader::header_count(const char* what) {
    skip_comments();
    const std::size_t line = c_.line;
    const std::string_view t = c_.token();
    long long n = 0;
    if (!parse_integer(t, n) || n < 0)
        fail(path_, "line " + std::to_string(line) + ": malformed OFF header: the " + what + " count must be a non-negative integer, not " +
                        quoted(t));
    return static_cast<unsigned long long>(n);
}

TriangleSoup OffReader::run() {
    skip_comments();
    const std::string kw(c_.token());
    std::size_t j = kw.substr(0, 2) == "ST" ? 2 : 0;
    v_.textures = j == 2;
    v_.colours = j < kw.size() && kw[j] == 'C';
    j += v_.colours;
    v_.normals = j < kw.size() && kw[j] == 'N';
    j += v_.normals;
    const bool homogeneous = j < kw.size() && kw[j] == '4';
    j += homogeneous;
    const bool dimensional = j < kw.size() && kw[j] == 'n';
    j += dimensional;
    v_.keyword = kw;
    if (kw.substr(j) != "OFF")
        fail(path_, "not an OFF file (it starts with " + quoted(kw) + ", not OFF or one of its [ST][C][N]OFF variants)");
    if (homogeneous || dimensional)
        fail(path_, "unsupported OFF variant '" + kw + "' (homogeneous or n-dimensional coordinates); [ST][C][N]OFF is read");
    skip_comments();
    if (c_.end - c_.p >= 6 && std::string_view(c_.p, 6) == "BINARY") {
        if (v_.textures)
            fail(path_, "unsupported OFF variant '" + kw + " BINARY' (texture coordinates in a binary OFF); ASCII " + kw + " is read");
        c_.p += 6;
        c_.next_line();
        binary_body();
        keep_attributes();
        return out_.finish("the file has " + std::to_string(out_.soup.points.size()) + " vertices and 0 faces");
    }
    const unsigned long long nv = header_count("vertex");
    const unsigned long long nf = header_count("face");
    (void)header_count("edge");
    if (nv >= 0xffffffffull) fail(path_, "too many vertices (the header declares " + std::to_string(nv) + "; at most 2^32-2)");
    ascii_vertices(nv);
    ascii_faces(nf);
    keep_attributes();
    return out_.finish("the file has " + std::to_string(nv) + " vertices and 0 faces");
}

void OffReader::ascii_vertices(unsigned long long nv) {
    // A vertex line holds at least "0 0 0" (6 bytes with its newline).
    out_.soup.points.reserve(fit(d_.size(), 6, nv));
    const std::size_t base = v_.normals ? 6 : 3, texture_numbers = v_.textures ? 2 : 0;
    for (unsigned long long v = 0; v < nv; ++v) {
        Line l{};
        if (!data_line(l))
            fail(path_,
                 "truncated OFF file: header declares " + std::to_string(nv) + " vertices but only " + std::to_string(v) + " were found");
        double x[12] = {};  // x y z, nx ny nz, r g b a, s t: the most a vertex line holds
        std::size_t n = 0;
        const std::size_t want = v_.colours || v_.normals || v_.textures ? SIZE_MAX : 3;
        for (std::string_view t; n < want && !(t = l.token()).empty(); ++n) {
            double y = 0;
            if (!parse_real(t, y)) fail_line("vertex " + std::to_string(v) + " " + coordinate_problem(t));
            if (n < 12) x[n] = y;
        }
        if (n < 3) fail_line("vertex " + std::to_string(v) + " has fewer than 3 coordinates");
        const std::size_t colour_numbers = n - base - texture_numbers;  // wraps around when n is too small: refused below
        const bool counted = v_.colours ? n >= base + texture_numbers && (colour_numbers == 3 || colour_numbers == 4)
                                        : (want == 3 || n == base + texture_numbers);
        if (!counted)
            fail_line("vertex " + std::to_string(v) + " has " + std::to_string(n) + " numbers; a " + v_.keyword + " vertex needs " +
                      std::to_string(base) + (v_.colours ? " plus 3 or 4 colour components" : "") +
                      (v_.textures ? " plus 2 texture coordinates" : ""));
        if (v_.colours) {
            if (const std::string why = colour_problem(x + base); !why.empty()) fail_line("vertex " + std::to_string(v) + ": " + why);
            RawColour c;
            std::copy(x + base, x + base + colour_numbers, c.c);
            c.alpha = colour_numbers == 4;
            colours_.push_back(c);
        }
        if (v_.normals) normals_.values.insert(normals_.values.end(), x + 3, x + 6);
        if (v_.textures) texcoords_.values.insert(texcoords_.values.end(), x + n - 2, x + n);
        out_.soup.points.push_back({x[0], x[1], x[2]});
    }
}

/// The attributes read, in the PLY reader's order (NORMAL, COLOR_0, TEXCOORD_0); colours scaled
/// to [0, 1] by the file-wide rule of the header comment.
void OffReader::keep_attributes() {
    if (v_.normals) out_.soup.attributes.push_back(std::move(normals_));
    if (v_.colours) {
        auto whole = [](const RawColour& c) { return integral(c.c[0]) && integral(c.c[1]) && integral(c.c[2]); };
        bool bytes = false, alpha = false;
        for (const RawColour& c : colours_) {
            bytes = bytes || (whole(c) && std::max({c.c[0], c.c[1], c.c[2]}) > 1);
            alpha = alpha || c.alpha;
        }
        VertexAttribute a{"COLOR_0", alpha ? 4u : 3u, AttributeBlend::Linear, {}};
        a.values.reserve(colours_.size() * a.components);
        for (const RawColour& c : colours_) {
            const double scale = bytes && whole(c) ? 1.0 / 255 : 1.0;
            for (uint32_t k = 0; k < a.components; ++k)
                a.values.push_back(k < 3 ? c.c[k] * scale : std::clamp(c.alpha ? c.c[3] * scale : 1.0, 0.0, 1.0));
        }
        out_.soup.attributes.push_back(std::move(a));
    }
    if (v_.textures) out_.soup.attributes.push_back(std::move(texcoords_));
}

void OffReader::ascii_faces(unsigned long long nf) {
    const std::size_t nv = out_.soup.points.size();
    // A face line holds at least "3 0 1 2" (8 bytes).
    out_.reserve_triangles(fit(d_.size() - static_cast<std::size_t>(c_.p - d_.data()), 8, nf));
    for (uint64_t f = 0; f < nf; ++f) {
        Line l{};
        if (!data_line(l))
            fail(path_,
                 "truncated OFF file: header declares " + std::to_string(nf) + " faces but only " + std::to_string(f) + " were found");
        auto face = [f] { return "face " + std::to_string(f); };
        const std::string_view first = l.token();
        unsigned long long k = 0;
        if (!parse_index(first, k)) fail_line(face() + ": bad vertex count " + quoted(first));
        if (k < 3) fail_line(face() + " has only " + std::to_string(k) + " vertices (at least 3 needed)");
        corners_.clear();
        for (unsigned long long i = 0; i < k; ++i) {
            const std::string_view t = l.token();
            if (t.empty()) fail_line(face() + " declares " + std::to_string(k) + " vertices but lists " + std::to_string(i));
            unsigned long long idx = 0;
            if (!parse_index(t, idx)) fail_line(face() + ": bad vertex index " + quoted(t));
            if (idx >= nv)
                fail_line(face() + " references vertex " + std::to_string(idx) + " but the file has only " + std::to_string(nv) +
                          " vertices");
            corners_.push_back(static_cast<uint32_t>(idx));
        }
        if (v_.colours) face_colour(l, f);
        out_.add_polygon(corners_.data(), corners_.size());
    }
}

void OffReader::face_colour(Line& l, uint64_t f) {
    auto face = [f] { return "face " + std::to_string(f); };
    double c[4] = {0, 0, 0, 0};
    std::size_t count = 0;
    for (std::string_view t = l.token(); !t.empty(); t = l.token()) {
        double x = 0;
        if (!parse_real(t, x)) fail_line(face() + ": bad colour number " + quoted(t));
        if (count < 4) c[count] = x;
        ++count;
    }
    if (count == 1 && !(c[0] >= 0 && c[0] <= 2147483647.0 && std::floor(c[0]) == c[0]))
        fail_line(face() + ": colour-map index " + number_text(c[0]) + " is not an integer in [0, 2^31)");
    if (count == 2 || count > 4)
        fail_line(face() + " has " + std::to_string(count) + " colour numbers; a COFF face colour is 1 (colour-map index), 3 or 4 numbers");
    if (count >= 3)
        if (const std::string why = colour_problem(c); !why.empty()) fail_line(face() + ": " + why);
}

uint32_t be32(const char* p) {
    const auto* u = reinterpret_cast<const unsigned char*>(p);
    return static_cast<uint32_t>(u[0]) << 24 | static_cast<uint32_t>(u[1]) << 16 | static_cast<uint32_t>(u[2]) << 8 | u[3];
}

void OffReader::binary_body() {
    const char* p = c_.p;
    const char* end = c_.end;
    auto left = [&] { return static_cast<std::size_t>(end - p); };
    if (left() < 12) fail(path_, "truncated binary OFF file: the header ends before its three counts");
    const auto nv = static_cast<int32_t>(be32(p)), nf = static_cast<int32_t>(be32(p + 4));
    p += 12;
    if (nv < 0 || nf < 0)
        fail(path_, "malformed binary OFF header: negative count (" + std::to_string(nv) + " vertices, " + std::to_string(nf) + " faces)");
    const std::size_t stride = v_.normals ? 24 : 12;
    // A vertex is at least 12 bytes, a face at least 16.
    if (static_cast<std::size_t>(nv) * stride + static_cast<std::size_t>(nf) * 16 > left())
        fail(path_, "truncated binary OFF file: the header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                        " faces, which need at least " +
                        std::to_string(static_cast<std::size_t>(nv) * stride + static_cast<std::size_t>(nf) * 16) + " bytes, but only " +
                        std::to_string(left()) + " follow the header");
    auto& pts = out_.soup.points;
    pts.resize(static_cast<std::size_t>(nv));
    for (int32_t v = 0; v < nv; ++v, p += stride)
        for (int k = 0; k < 3; ++k) {
            const uint32_t u = be32(p + 4 * k);
            float x = 0;
            std::memcpy(&x, &u, 4);
            if (!std::isfinite(x)) fail(path_, "binary OFF vertex " + std::to_string(v) + " has a non-finite coordinate (NaN or infinity)");
            pts[static_cast<std::size_t>(v)][static_cast<std::size_t>(k)] = x;
        }
    if (v_.normals) {
        normals_.values.resize(3 * static_cast<std::size_t>(nv));
        for (std::size_t i = 0; i < normals_.values.size(); ++i) {
            const uint32_t u = be32(c_.p + 12 + (i / 3) * stride + 12 + 4 * (i % 3));
            float x = 0;
            std::memcpy(&x, &u, 4);
            if (!std::isfinite(x)) fail(path_, "binary OFF vertex " + std::to_string(i / 3) + " has a non-finite normal (NaN or infinity)");
            normals_.values[i] = x;
        }
    }
    out_.reserve_triangles(static_cast<std::size_t>(nf));
    for (int32_t f = 0; f < nf; ++f) {
        auto face = [f] { return "binary OFF face " + std::to_string(f); };
        if (left() < 4)
            fail(path_, "truncated binary OFF file: the header declares " + std::to_string(nf) + " faces but only " + std::to_string(f) +
                            " were found");
        const auto k = static_cast<int32_t>(be32(p));
        p += 4;
        if (k < 3) fail(path_, face() + " has only " + std::to_string(k) + " vertices (at least 3 needed)");
        if (static_cast<std::size_t>(k) > left() / 4)
            fail(path_, face() + " declares " + std::to_string(k) + " vertices but only " + std::to_string(left() / 4) +
                            " indices fit in the rest of the file");
        corners_.clear();
        for (int32_t i = 0; i < k; ++i, p += 4) {
            const auto idx = static_cast<int32_t>(be32(p));
            if (idx < 0 || idx >= nv)
                fail(path_,
                     face() + " references vertex " + std::to_string(idx) + " but the file has only " + std::to_string(nv) + " vertices");
            corners_.push_back(static_cast<uint32_t>(idx));
        }
        out_.add_polygon(corners_.data(), corners_.size());
    }
}

}  // namespace

TriangleSoup read_off(const std::string& path, std::string_view d) {
    return OffReader(path, d).run();
}

}  // namespace singlestrip::io_detail
