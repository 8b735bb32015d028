// Mesh file reading: CGAL's polygon-soup readers do the parsing; the checks around them turn
// CGAL's bare true/false into messages naming the file, the element and the problem.
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>
#include <CGAL/IO/STL/STL_reader.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"

namespace singlestrip {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using CgalPoint = Kernel::Point_3;

enum class InFormat { Obj, Off, Ply, Stl };

const char* format_name(InFormat f) {
    switch (f) {
        case InFormat::Obj: return "OBJ";
        case InFormat::Off: return "OFF";
        case InFormat::Ply: return "PLY";
        case InFormat::Stl: return "STL";
    }
    return "?";
}

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw InputError(path + ": " + what); }

/// Every byte of `in`, read to its end (a pipe has no size to ask for in advance); std::nullopt
/// as soon as it holds more than `max_bytes` (a pipe whose writer never stops must not fill the
/// memory).
std::optional<std::string> read_all(std::istream& in, std::size_t expected_size, std::uint64_t max_bytes) {
    std::string data;
    data.reserve(expected_size);
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        if (data.size() + static_cast<std::uint64_t>(in.gcount()) > max_bytes) return std::nullopt;
        data.append(buffer, static_cast<std::size_t>(in.gcount()));
    }
    return data;
}

/// Whitespace-split tokens of one line, '#' comments removed.
std::vector<std::string> tokens_of(std::string line) {
    if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::vector<std::string> out;
    std::istringstream ss(line);
    for (std::string t; ss >> t;) out.push_back(t);
    return out;
}

std::optional<double> parse_double(const std::string& t) {
    errno = 0;
    char* end = nullptr;
    double v = std::strtod(t.c_str(), &end);
    if (end == t.c_str() || *end != '\0') return std::nullopt;
    return v;  // overflow gives +-HUGE_VAL (inf), reported as non-finite by the caller
}

std::optional<long long> parse_int(const std::string& t) {
    errno = 0;
    char* end = nullptr;
    long long v = std::strtoll(t.c_str(), &end, 10);
    if (end == t.c_str() || *end != '\0' || errno == ERANGE) return std::nullopt;
    return v;
}

std::string coord_problem(const std::string& path, size_t line, size_t vertex, const std::string& tok) {
    auto v = parse_double(tok);
    if (!v) return "line " + std::to_string(line) + ": vertex " + std::to_string(vertex) + ": cannot parse coordinate '" + tok + "'";
    if (!std::isfinite(*v))
        return "line " + std::to_string(line) + ": vertex " + std::to_string(vertex) + " has a non-finite coordinate (" + tok + ")";
    (void)path;
    return {};
}

std::string index_problem(size_t face, long long index, size_t num_vertices) {
    return "face " + std::to_string(face) + " references vertex " + std::to_string(index) + " but the file has only " +
           std::to_string(num_vertices) + " vertices";
}

// --- diagnostic scanners, run only when CGAL rejected the file -------------------------------

/// OFF: line based (one vertex / one face per line, as every OFF writer does).
std::optional<std::string> diagnose_off(const std::string& path, const std::string& data) {
    std::istringstream in(data);
    std::string line;
    size_t lineno = 0;
    std::vector<std::string> header;
    // Header keyword line ([ST][C][N][4][n]OFF), counts on the same or a following line.
    while (std::getline(in, line)) {
        ++lineno;
        header = tokens_of(line);
        if (!header.empty()) break;
    }
    if (header.empty()) return "empty OFF file";
    size_t pos = 0;
    if (header[0].find("OFF") != std::string::npos) {
        pos = 1;
    }
    std::vector<std::string> counts(header.begin() + static_cast<std::ptrdiff_t>(pos), header.end());
    while (counts.size() < 2 && std::getline(in, line)) {
        ++lineno;
        auto t = tokens_of(line);
        counts.insert(counts.end(), t.begin(), t.end());
    }
    if (counts.size() < 2) return "malformed OFF header: missing vertex and face counts";
    auto nv = parse_int(counts[0]);
    auto nf = parse_int(counts[1]);
    if (!nv || !nf || *nv < 0 || *nf < 0)
        return "malformed OFF header: bad counts '" + counts[0] + " " + counts[1] + "' (line " + std::to_string(lineno) + ")";
    size_t v = 0;
    while (v < static_cast<size_t>(*nv) && std::getline(in, line)) {
        ++lineno;
        auto t = tokens_of(line);
        if (t.empty()) continue;
        if (t.size() < 3)
            return "line " + std::to_string(lineno) + ": vertex " + std::to_string(v) + " has fewer than 3 coordinates";
        for (int k = 0; k < 3; ++k) {
            auto p = coord_problem(path, lineno, v, t[static_cast<size_t>(k)]);
            if (!p.empty()) return p;
        }
        ++v;
    }
    if (v < static_cast<size_t>(*nv))
        return "truncated OFF file: header declares " + std::to_string(*nv) + " vertices but only " + std::to_string(v) + " were found";
    size_t f = 0;
    while (f < static_cast<size_t>(*nf) && std::getline(in, line)) {
        ++lineno;
        auto t = tokens_of(line);
        if (t.empty()) continue;
        auto k = parse_int(t[0]);
        if (!k || *k < 0) return "line " + std::to_string(lineno) + ": face " + std::to_string(f) + ": bad vertex count '" + t[0] + "'";
        if (*k < 3) return "line " + std::to_string(lineno) + ": face " + std::to_string(f) + " has only " + std::to_string(*k) + " vertices (at least 3 needed)";
        if (t.size() < static_cast<size_t>(*k) + 1)
            return "line " + std::to_string(lineno) + ": face " + std::to_string(f) + " declares " + std::to_string(*k) + " vertices but lists " +
                   std::to_string(t.size() - 1);
        for (long long i = 1; i <= *k; ++i) {
            auto idx = parse_int(t[static_cast<size_t>(i)]);
            if (!idx) return "line " + std::to_string(lineno) + ": face " + std::to_string(f) + ": bad vertex index '" + t[static_cast<size_t>(i)] + "'";
            if (*idx < 0 || *idx >= *nv) return "line " + std::to_string(lineno) + ": " + index_problem(f, *idx, static_cast<size_t>(*nv));
        }
        ++f;
    }
    if (f < static_cast<size_t>(*nf))
        return "truncated OFF file: header declares " + std::to_string(*nf) + " faces but only " + std::to_string(f) + " were found";
    if (*nf == 0) return "no faces (the file has " + std::to_string(*nv) + " vertices and 0 faces)";
    return std::nullopt;
}

/// OBJ: v and f records; indices are 1-based, negative ones are relative to the current count.
std::optional<std::string> diagnose_obj(const std::string& path, const std::string& data) {
    std::istringstream in(data);
    std::string line;
    size_t lineno = 0, nv = 0, nf = 0;
    struct Ref { size_t line, face; long long index; };
    std::vector<Ref> refs;
    while (std::getline(in, line)) {
        ++lineno;
        auto t = tokens_of(line);
        if (t.empty()) continue;
        if (t[0] == "v") {
            if (t.size() < 4) return "line " + std::to_string(lineno) + ": vertex " + std::to_string(nv) + " has fewer than 3 coordinates";
            for (int k = 1; k <= 3; ++k) {
                auto p = coord_problem(path, lineno, nv, t[static_cast<size_t>(k)]);
                if (!p.empty()) return p;
            }
            ++nv;
        } else if (t[0] == "f") {
            if (t.size() < 4)
                return "line " + std::to_string(lineno) + ": face " + std::to_string(nf) + " has only " + std::to_string(t.size() - 1) +
                       " vertices (at least 3 needed)";
            for (size_t k = 1; k < t.size(); ++k) {
                std::string head = t[k].substr(0, t[k].find('/'));
                auto idx = parse_int(head);
                if (!idx || *idx == 0)
                    return "line " + std::to_string(lineno) + ": face " + std::to_string(nf) + ": bad vertex index '" + t[k] + "'";
                long long zero_based = *idx > 0 ? *idx - 1 : static_cast<long long>(nv) + *idx;
                refs.push_back({lineno, nf, zero_based});
            }
            ++nf;
        }
    }
    for (const auto& r : refs)
        if (r.index < 0 || r.index >= static_cast<long long>(nv)) return "line " + std::to_string(r.line) + ": " + index_problem(r.face, r.index, nv);
    if (nf == 0) return "no faces (the file has " + std::to_string(nv) + " vertices and 0 faces)";
    return std::nullopt;
}

std::size_t ply_type_size(const std::string& t) {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
}

/// PLY: checks the header and, for binary files, that the body is long enough.
std::optional<std::string> diagnose_ply(const std::string& data) {
    if (data.rfind("ply", 0) != 0) return "not a PLY file (it does not start with 'ply')";
    auto end = data.find("end_header");
    if (end == std::string::npos) return "malformed PLY header: no 'end_header' line";
    auto body = data.find('\n', end);
    body = body == std::string::npos ? data.size() : body + 1;
    std::istringstream hs(data.substr(0, end));
    std::string line, format;
    struct Element { std::string name; long long count = 0; std::size_t fixed = 0; std::size_t list_min = 0; bool has_list = false; };
    std::vector<Element> elements;
    while (std::getline(hs, line)) {
        auto t = tokens_of(line);
        if (t.empty()) continue;
        if (t[0] == "format" && t.size() > 1) format = t[1];
        if (t[0] == "element" && t.size() > 2) {
            auto c = parse_int(t[2]);
            if (!c || *c < 0) return "malformed PLY header: bad count for element '" + t[1] + "'";
            elements.push_back({t[1], *c});
        }
        if (t[0] == "property" && !elements.empty()) {
            if (t.size() > 3 && t[1] == "list") {
                elements.back().has_list = true;
                // Assume triangles: the count plus three entries.
                elements.back().list_min += ply_type_size(t[2]) + 3 * ply_type_size(t[3]);
            } else if (t.size() > 2) {
                elements.back().fixed += ply_type_size(t[1]);
            }
        }
    }
    long long nv = 0, nf = 0;
    for (const auto& e : elements) {
        if (e.name == "vertex") nv = e.count;
        if (e.name == "face") nf = e.count;
    }
    if (format.empty()) return "malformed PLY header: no 'format' line";
    if (nf == 0) return "no faces (the PLY header declares " + std::to_string(nv) + " vertices and 0 faces)";
    const std::size_t have = data.size() - body;
    if (format == "ascii") {
        std::size_t lines = 0;
        std::istringstream bs(data.substr(body));
        while (std::getline(bs, line))
            if (!tokens_of(line).empty()) ++lines;
        long long need = 0;  // saturates: counts come from the header (up to 10^18 each)
        for (const auto& e : elements) need = e.count > std::numeric_limits<long long>::max() - need ? std::numeric_limits<long long>::max() : need + e.count;
        if (static_cast<long long>(lines) < need)
            return "truncated PLY file: the header declares " +
                   (need == std::numeric_limits<long long>::max() ? std::string("more than 2^63") : std::to_string(need)) + " element lines but only " +
                   std::to_string(lines) + " were found";
    } else {
        std::size_t need = 0;  // saturates, as above
        for (const auto& e : elements) {
            std::size_t bytes = 0;
            if (__builtin_mul_overflow(static_cast<std::size_t>(e.count), e.fixed + (e.has_list ? e.list_min : 0), &bytes) ||
                __builtin_add_overflow(need, bytes, &need))
                need = std::numeric_limits<std::size_t>::max();
        }
        if (have < need)
            return "truncated PLY file: " + std::to_string(nv) + " vertices and " + std::to_string(nf) + " triangles need " + std::to_string(need) +
                   " bytes of data but the file has only " + std::to_string(have);
    }
    return std::nullopt;
}

/// STL: binary size check (84-byte header + 50 bytes per triangle).
std::optional<std::string> diagnose_stl(const std::string& data) {
    std::size_t first = data.find_first_not_of(" \t\r\n");
    const bool ascii = first != std::string::npos && data.compare(first, 5, "solid") == 0 &&
                       data.find("facet", first) != std::string::npos;
    if (ascii) {
        if (data.find("endsolid") == std::string::npos) return "truncated ASCII STL file: no 'endsolid'";
        return std::nullopt;
    }
    if (data.size() < 84) return "truncated binary STL file: " + std::to_string(data.size()) + " bytes, less than the 84-byte header";
    uint32_t n = 0;
    std::memcpy(&n, data.data() + 80, 4);
    const std::size_t need = 84 + 50 * static_cast<std::size_t>(n);
    if (data.size() < need)
        return "truncated binary STL file: the header declares " + std::to_string(n) + " triangles (" + std::to_string(need) +
               " bytes) but the file has " + std::to_string(data.size()) + " bytes";
    if (n == 0) return "no faces (the binary STL header declares 0 triangles)";
    return std::nullopt;
}

// --- pre-scan, run on the file's bytes BEFORE CGAL ------------------------------------------
//
// CGAL's readers resize their arrays to counts read from the file before reading the data (OFF
// header counts, an OFF face's corner count, a PLY list count), crash on a PLY 'property' before
// any 'element', and loop forever over a PLY element without properties. The pre-scan follows
// CGAL's own tokenisation closely enough to refuse those files first. It never refuses a file
// CGAL would read into a soup that read_mesh_file accepts, except malformed files CGAL reads as
// something else: an ASCII PLY list count out of its type's range (CGAL wraps it), PLY vertices
// without x, y, z (CGAL puts them at the origin), PLY faces with fewer than 3 corners (refused
// anyway, but only after CGAL stored them all), and an OBJ '#' glued to an index with text after
// it (CGAL reads the comment as corners). It allocates nothing proportional to declared counts
// and runs in O(file size).

struct Refusal {
    std::string what;
    bool prefer_diagnosis = false;  // a diagnose_* message, when it finds one, is more familiar
};

bool is_ws(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

/// 1-based line number of byte `pos` (only computed for messages).
std::size_t line_of(std::string_view d, std::size_t pos) {
    return 1 + static_cast<std::size_t>(std::count(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(std::min(pos, d.size())), '\n'));
}

std::size_t end_of_line(std::string_view d, std::size_t p) {
    if (p >= d.size()) return d.size();
    const void* nl = std::memchr(d.data() + p, '\n', d.size() - p);
    return nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - d.data()) : d.size();
}

/// A whole token that is a non-negative decimal integer (optional '+'), below 10^18.
bool clean_unsigned(std::string_view t, unsigned long long& v) {
    if (!t.empty() && t[0] == '+') t.remove_prefix(1);
    // Leading zeros are digits CGAL's `>>` reads too (F12: "0000000000000000000003").
    while (t.size() > 1 && t[0] == '0' && t[1] >= '0' && t[1] <= '9') t.remove_prefix(1);
    if (t.empty() || t.size() > 18) return false;
    v = 0;
    for (char c : t) {
        if (c < '0' || c > '9') return false;
        v = v * 10 + static_cast<unsigned>(c - '0');
    }
    return true;
}

/// A whole token that is a decimal integer (optional sign), |v| < 10^18.
bool clean_signed(std::string_view t, long long& v) {
    bool neg = false;
    if (!t.empty() && (t[0] == '-' || t[0] == '+')) {
        neg = t[0] == '-';
        t.remove_prefix(1);
        if (!t.empty() && (t[0] == '-' || t[0] == '+')) return false;
    }
    unsigned long long u = 0;
    if (!clean_unsigned(t, u)) return false;
    v = neg ? -static_cast<long long>(u) : static_cast<long long>(u);
    return true;
}

/// A whole token that is a finite decimal number, [+-]?(d+(.d*)?|.d+)([eE][+-]?d+)?, which
/// `istream >> double` reads as exactly one number. Anything else is refused: from_chars alone
/// also takes "nan", "inf" and (after a stripped '+') "-0" in "+-0", which the stream cannot
/// read, so CGAL's per-line entries came out shorter than counted (F17, F18).
bool clean_double(std::string_view t, double& v) {
    auto digits = [&](std::size_t& i) {
        const std::size_t b = i;
        while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
        return i - b;
    };
    std::size_t i = 0;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    const std::size_t mantissa = i;
    std::size_t whole = digits(i), fraction = 0;
    if (i < t.size() && t[i] == '.') {
        ++i;
        fraction = digits(i);
    }
    if (whole + fraction == 0) return false;
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
        ++i;
        if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
        if (digits(i) == 0) return false;
    }
    if (i != t.size()) return false;
    // from_chars takes no '+'; a leading '-' it reads itself.
    const std::size_t b = t[0] == '+' ? mantissa : 0;
    const auto r = std::from_chars(t.data() + b, t.data() + t.size(), v);
    if (r.ec == std::errc::result_out_of_range) {
        // The stream reads an underflow (1e-400) as 0 and fails on an overflow (1e400);
        // strtod tells the two apart the same way.
        const std::string copy(t);
        v = std::strtod(copy.c_str(), nullptr);
        return std::isfinite(v);
    }
    return r.ec == std::errc() && r.ptr == t.data() + t.size() && std::isfinite(v);
}

/// A non-negative integral index (or corner count) written as an integer or an integral double.
bool clean_index(std::string_view t, unsigned long long& v) {
    if (clean_unsigned(t, v)) return true;
    double x = 0;
    if (!clean_double(t, x) || !std::isfinite(x) || x < 0 || x >= 9.0e18 || std::floor(x) != x) return false;
    v = static_cast<unsigned long long>(x);
    return true;
}

/// Next whitespace-separated token in [p, end); empty at the end.
std::string_view next_token(std::string_view d, std::size_t& p, std::size_t end) {
    while (p < end && is_ws(d[p])) ++p;
    const std::size_t b = p;
    while (p < end && !is_ws(d[p])) ++p;
    return d.substr(b, p - b);
}

// ---- OFF ----

/// Shortest text for a number in a message.
std::string number_text(double x) {
    std::ostringstream o;
    o << x;
    return o.str();
}

/// Why CGAL's File_scanner_OFF::scan_color cannot convert an r g b triple without undefined
/// behaviour (F16), or nothing. It takes integers as 0..255 and, if any component is not an
/// integer, all three as fractions times 255; each result is cast to unsigned char unchecked.
std::optional<std::string> rgb_colour_problem(const double rgb[3]) {
    const bool integers = std::floor(rgb[0]) == rgb[0] && std::floor(rgb[1]) == rgb[1] && std::floor(rgb[2]) == rgb[2];
    for (int i = 0; i < 3; ++i) {
        const bool ok = integers ? rgb[i] >= 0 && rgb[i] <= 255 : rgb[i] >= 0 && rgb[i] <= 1;
        if (!ok)
            return "colour component " + number_text(rgb[i]) + " out of range (colours are three integers in [0, 255] or three fractions in [0, 1])";
    }
    return std::nullopt;
}

std::optional<Refusal> prescan_off(std::string_view d) {
    const std::size_t n = d.size();
    std::size_t p = 0;
    // CGAL's skip_comment_OFF: whitespace and lines starting with '#'.
    auto skip_comment = [&] {
        for (;;) {
            while (p < n && is_ws(d[p])) ++p;
            if (p < n && d[p] == '#') p = end_of_line(d, p) + 1;
            else break;
        }
        p = std::min(p, n);
    };
    // `in >> int` (whitespace only, no comments); false where CGAL's stream fails.
    auto read_int = [&](long long& v) {
        while (p < n && is_ws(d[p])) ++p;
        const std::size_t b = p;
        if (p < n && (d[p] == '-' || d[p] == '+')) ++p;
        while (p < n && d[p] >= '0' && d[p] <= '9') ++p;
        if (!clean_signed(d.substr(b, p - b), v)) return false;
        return v >= -2147483648LL && v <= 2147483647LL;
    };
    skip_comment();
    if (p >= n) return std::nullopt;
    // Keyword: one character, then alphanumerics; the character ending it is consumed (in.get).
    const std::size_t k0 = p++;
    while (p < n && p - k0 < 41 && std::isalnum(static_cast<unsigned char>(d[p]))) ++p;
    const std::string_view kw = d.substr(k0, p - k0);
    if (p < n) ++p;
    std::size_t j = 0;
    const bool textures = kw.substr(0, 2) == "ST";
    if (textures) j += 2;
    const bool colours = j < kw.size() && kw[j] == 'C';
    if (colours) ++j;
    const bool normals = j < kw.size() && kw[j] == 'N';
    if (normals) ++j;
    const bool homogeneous = j < kw.size() && kw[j] == '4';
    if (homogeneous) ++j;
    const bool dimensional = j < kw.size() && kw[j] == 'n';
    if (dimensional) ++j;
    const bool off = kw.substr(j) == "OFF";
    if (!off && kw.substr(j) != "SKEL") return std::nullopt;  // CGAL refuses the header itself
    // CGAL 5.5's scanner crashes on malformed texture-coordinate records (found by fuzzing:
    // File_scanner_OFF::scan_texture) and 4D / n-D vertices are not surfaces we can strip.
    if (textures || homogeneous || dimensional)
        return Refusal{"unsupported OFF variant '" + std::string(kw) +
                           "' (texture, homogeneous or n-dimensional coordinates); plain OFF, COFF, NOFF and CNOFF are read",
                       false};

    skip_comment();
    if (p >= n) return std::nullopt;
    long long nv = 0, nf = 0, nh = 0;
    // CGAL reads the counts into int and computes 2 * edges (F13): anything the scan cannot read
    // as an int, or an edge count of 2^30 or more (2 * 2^30 overflows int: F15), is refused here.
    const Refusal bad_counts{"malformed OFF header: the vertex, face and edge counts must be integers in [0, 2^31)", true};
    constexpr long long kMaxEdges = (1LL << 30) - 1;
    if (d[p] >= '0' && d[p] <= '9') {
        if (!read_int(nv)) return bad_counts;
        if (dimensional && !read_int(nv)) return bad_counts;
        if (!read_int(nf) || nf < 0) return bad_counts;
        if (off && (!read_int(nh) || nh < 0 || nh > kMaxEdges))
            return Refusal{"malformed OFF header: edge count out of range [0, 2^30)", true};
    } else {
        const std::size_t b = p++;
        while (p < n && p - b < 41 && std::isalnum(static_cast<unsigned char>(d[p]))) ++p;
        if (d.substr(b, p - b) != "BINARY") return std::nullopt;
        if (p < n && d[p++] != '\n') p = end_of_line(d, p) + 1;
        auto be32 = [&](long long& v) {
            if (n < 4 || p > n - 4) return false;
            const auto* u = reinterpret_cast<const unsigned char*>(d.data() + p);
            v = static_cast<int32_t>(static_cast<uint32_t>(u[0]) << 24 | static_cast<uint32_t>(u[1]) << 16 | static_cast<uint32_t>(u[2]) << 8 | u[3]);
            p += 4;
            return true;
        };
        if (dimensional && !be32(nv)) return std::nullopt;
        if (!be32(nv) || !be32(nf) || nf < 0) return std::nullopt;
        if (off && (!be32(nh) || nh < 0 || nh > kMaxEdges))
            return Refusal{"malformed binary OFF header: edge count out of range [0, 2^30)", false};
        if (nv < 0) return Refusal{"malformed OFF header: negative vertex count " + std::to_string(nv), false};
        (void)nh;
        // Binary: a vertex is at least 3 floats, a face at least 4 ints.
        const std::size_t left = n - std::min(p, n);
        if (static_cast<std::size_t>(nv) * 12 + static_cast<std::size_t>(nf) * 16 > left)
            return Refusal{"truncated binary OFF file: the header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                               " faces, which need at least " + std::to_string(nv * 12 + nf * 16) + " bytes, but only " + std::to_string(left) +
                               " follow the header",
                           false};
        // CGAL's binary scanner reads x y z and, for N, nx ny nz as big-endian floats; it never
        // reads colours in binary files (m_has_vcolors is set only by the ASCII path), so a
        // COFF or CNOFF vertex is 12 or 24 bytes. (ST, 4 and n were refused above.) Walking
        // the faces is what keeps a corner count of 2^31-1 from reaching CGAL's resize (F19).
        const std::size_t vertex_bytes = static_cast<std::size_t>(nv) * (normals ? 24 : 12);
        if (p > n || vertex_bytes > n - p)
            return Refusal{"truncated binary OFF file: the header declares " + std::to_string(nv) + " vertices but the file ends before them", false};
        p += vertex_bytes;
        for (long long f = 0; f < nf; ++f) {
            long long k = 0;
            if (!be32(k)) return Refusal{"truncated binary OFF file: the header declares " + std::to_string(nf) + " faces but only " + std::to_string(f) + " were found", false};
            if (k < 3) return Refusal{"face " + std::to_string(f) + " has only " + std::to_string(k) + " vertices (at least 3 needed)", false};
            if (static_cast<unsigned long long>(k) > (n - p) / 4)
                return Refusal{"face " + std::to_string(f) + " declares " + std::to_string(k) + " vertices but only " + std::to_string((n - p) / 4) +
                                   " indices fit in the rest of the file",
                               false};
            p += static_cast<std::size_t>(k) * 4;
        }
        return std::nullopt;
    }
    if (nv < 0) return Refusal{"malformed OFF header: negative vertex count " + std::to_string(nv), true};

    // ASCII: a vertex line holds >= 3 numbers ("0 0 0\n", 6 bytes), an acceptable face >= 4
    // ("3 0 1 2\n", 8 bytes); the last line may lack its newline.
    if (6 * static_cast<unsigned long long>(nv) + 8 * static_cast<unsigned long long>(nf) > n + 1)
        return Refusal{"truncated OFF file: the header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                           " faces, which need at least " + std::to_string(6 * nv + 8 * nf) + " bytes, but the file has only " + std::to_string(n),
                       true};
    // CGAL reads one vertex per line, then one face per line (comment lines and blank lines skipped).
    // With colours or normals, CGAL indexes the line's numbers without checking how many there
    // are (heap overflow in File_scanner_OFF::scan_color, found by fuzzing: F14), so those lines
    // must hold exactly x y z [nx ny nz] r g b [a], all numbers.
    const std::size_t base = 3 + (normals ? 3 : 0);
    for (long long v = 0; v < nv; ++v) {
        skip_comment();
        if (p >= n)
            return Refusal{"truncated OFF file: header declares " + std::to_string(nv) + " vertices but only " + std::to_string(v) + " were found", true};
        std::size_t end = end_of_line(d, p);
        const std::size_t next = end + 1;
        if (colours || normals) {
            const std::size_t line_start = p;
            if (const void* hash = std::memchr(d.data() + p, '#', end - p)) end = static_cast<std::size_t>(static_cast<const char*>(hash) - d.data());
            std::size_t tokens = 0;
            double rgb[3] = {0, 0, 0};
            for (std::string_view t = next_token(d, p, end); !t.empty(); t = next_token(d, p, end)) {
                double x = 0;
                if (!clean_double(t, x))
                    return Refusal{"line " + std::to_string(line_of(d, line_start)) + ": vertex " + std::to_string(v) + ": bad number '" + std::string(t) + "'", false};
                if (tokens >= base && tokens < base + 3) rgb[tokens - base] = x;
                ++tokens;
            }
            const bool ok = colours ? (tokens == base + 3 || tokens == base + 4) : tokens == base;
            if (!ok)
                return Refusal{"line " + std::to_string(line_of(d, line_start)) + ": vertex " + std::to_string(v) + " has " + std::to_string(tokens) +
                                   " numbers; a " + std::string(kw) + " vertex needs " + std::to_string(base) + (colours ? " plus 3 or 4 colour components" : ""),
                               false};
            if (colours)
                if (auto why = rgb_colour_problem(rgb))
                    return Refusal{"line " + std::to_string(line_of(d, line_start)) + ": vertex " + std::to_string(v) + ": " + *why, false};
        }
        p = next;
    }
    bool face_colours = false;  // CGAL's sticky has_fcolors
    for (long long f = 0; f < nf; ++f) {
        skip_comment();
        if (p >= n)
            return Refusal{"truncated OFF file: header declares " + std::to_string(nf) + " faces but only " + std::to_string(f) + " were found", true};
        const std::size_t line_start = p;
        std::size_t end = end_of_line(d, p);
        const std::size_t next = end + 1;
        if (const void* hash = std::memchr(d.data() + p, '#', end - p)) end = static_cast<std::size_t>(static_cast<const char*>(hash) - d.data());
        auto where = [&] { return "line " + std::to_string(line_of(d, line_start)) + ": face " + std::to_string(f); };
        const std::string_view first = next_token(d, p, end);
        unsigned long long k = 0;
        if (!clean_index(first, k)) return Refusal{where() + ": bad vertex count '" + std::string(first) + "'", true};
        if (k < 3) return Refusal{where() + " has only " + std::to_string(k) + " vertices (at least 3 needed)", true};
        for (unsigned long long i = 0; i < k; ++i) {
            const std::string_view t = next_token(d, p, end);
            if (t.empty())
                return Refusal{where() + " declares " + std::to_string(k) + " vertices but lists " + std::to_string(i), true};
            unsigned long long idx = 0;
            if (!clean_index(t, idx)) return Refusal{where() + ": bad vertex index '" + std::string(t) + "'", true};
            if (idx >= static_cast<unsigned long long>(nv))
                return Refusal{"line " + std::to_string(line_of(d, line_start)) + ": " + index_problem(static_cast<std::size_t>(f), static_cast<long long>(idx), static_cast<std::size_t>(nv)), true};
        }
        if (colours) {
            // CGAL reads a COFF face's trailing numbers as its colour and, once one face had a
            // colour, reads one for every later face without checking the line holds it; it
            // also converts the numbers to unsigned char or to a colour-map index unchecked
            // (F16: UB on a component of 5e23). Only colours it can read safely get through.
            double c[5] = {0, 0, 0, 0, 0};
            std::size_t count = 0;
            for (std::string_view t = next_token(d, p, end); !t.empty(); t = next_token(d, p, end)) {
                double x = 0;
                if (!clean_double(t, x)) return Refusal{where() + ": bad colour number '" + std::string(t) + "'", false};
                if (count < 5) c[count] = x;
                ++count;
            }
            if (count == 0 && face_colours)
                return Refusal{where() + " has no colour, but an earlier face has one (COFF faces after a coloured face need a colour too)", false};
            if (count == 1 && !(c[0] >= 0 && c[0] <= 2147483647.0))
                return Refusal{where() + ": colour-map index " + std::string(number_text(c[0])) + " is not in [0, 2^31)", false};
            if (count == 2 || count > 4)
                return Refusal{where() + " has " + std::to_string(count) + " colour numbers; a COFF face colour is 1 (colour-map index), 3 or 4 numbers", false};
            if (count >= 3)
                if (auto why = rgb_colour_problem(c)) return Refusal{where() + ": " + *why, false};
            face_colours = face_colours || count > 0;
        }
        p = next;
    }
    return std::nullopt;
}

// ---- PLY ----

struct PlyProperty {
    std::string name;
    std::size_t size = 0;        // scalar size, or the list's entry size
    std::size_t count_size = 0;  // 0 for a scalar
    bool count_signed = false;
    bool integral = true;  // of the scalar / list entries
    std::string type;      // as written (scalar type, or the list's entry type)
};

struct PlyElement {
    std::string name;
    unsigned long long count = 0;
    std::size_t header_line = 0;
    std::vector<PlyProperty> props;  // only those CGAL reads (it ignores unknown types)
};

/// Size of a PLY scalar type as CGAL knows it (0: unknown, CGAL skips the property).
std::size_t ply_scalar(const std::string& t, bool& is_signed, bool& integral) {
    is_signed = t == "char" || t == "int8" || t == "short" || t == "int16" || t == "int" || t == "int32";
    integral = !(t == "float" || t == "float32" || t == "double" || t == "float64");
    return ply_type_size(t);
}

std::optional<Refusal> prescan_ply(std::string_view d) {
    const std::size_t n = d.size();
    std::size_t p = 0, lineno = 0;
    int format = -1;  // 0 ascii, 1 little endian, 2 big endian
    std::vector<PlyElement> elements;
    bool end_header = false;
    while (p < n) {
        const std::size_t end = end_of_line(d, p);
        const std::size_t line = p;
        p = end + 1;
        ++lineno;
        std::size_t q = line;
        std::vector<std::string> t;
        for (std::string_view tok; !(tok = next_token(d, q, end)).empty() && t.size() < 6;) t.emplace_back(tok);
        if (lineno == 1) {
            if (t.empty() || t[0] != "ply") return std::nullopt;  // CGAL refuses; diagnosed after
            continue;
        }
        if (lineno == 2) {
            if (t.size() < 3) return std::nullopt;
            if (t[1] == "ascii") format = 0;
            else if (t[1] == "binary_little_endian") format = 1;
            else if (t[1] == "binary_big_endian") format = 2;
            else return std::nullopt;
            continue;
        }
        if (t.empty()) return std::nullopt;  // CGAL's header parser stops with an error
        const std::string where = "malformed PLY header: line " + std::to_string(lineno) + ": ";
        if (t[0] == "property") {
            if (t.size() < 3) return std::nullopt;
            if (elements.empty()) return Refusal{where + "'property' before any 'element'", false};
            PlyProperty prop;
            bool sgn = false, integral = true;
            if (t[1] == "list") {
                if (t.size() < 5) return std::nullopt;
                prop.name = t[4];
                bool count_integral = true;
                prop.count_size = ply_scalar(t[2], prop.count_signed, count_integral);
                prop.size = ply_scalar(t[3], sgn, integral);
                prop.integral = integral;
                prop.type = "list " + t[3];
                // CGAL knows integer count types only.
                if (!count_integral || prop.count_size == 0 || prop.size == 0) continue;
            } else {
                prop.name = t[2];
                prop.size = ply_scalar(t[1], sgn, integral);
                prop.integral = integral;
                prop.type = t[1];
                if (prop.size == 0) continue;
            }
            elements.back().props.push_back(prop);
        } else if (t[0] == "element") {
            if (t.size() < 3) return std::nullopt;
            // `istream >> size_t`: leading digits; a sign or overflow makes CGAL fail or wrap.
            std::size_t q2 = 0;
            const std::string& c = t[2];
            if (c[0] == '+') q2 = 1;
            std::size_t e = q2;
            while (e < c.size() && c[e] >= '0' && c[e] <= '9') ++e;
            unsigned long long count = 0;
            if (c[0] == '-' || !clean_unsigned(std::string_view(c).substr(q2, e - q2), count))
                return Refusal{where + "bad count '" + c + "' for element '" + t[1] + "'", false};
            elements.push_back({t[1], count, lineno, {}});
        } else if (t[0] == "end_header") {
            end_header = true;
            break;
        }
    }
    if (format < 0) return std::nullopt;
    for (const auto& e : elements)
        if (e.count > 0 && e.props.empty())
            return Refusal{"malformed PLY header: line " + std::to_string(e.header_line) + ": element '" + e.name + "' declares " + std::to_string(e.count) +
                               " items but has no properties of a known type",
                           false};
    // CGAL fetches some properties with a fixed C++ type and dereferences a null pointer when the
    // file's type differs: vertex coordinates must be float or double, halfedge ends uint. It
    // looks a name up as the FIRST property of that name: later namesakes are never read.
    for (const auto& e : elements) {
        const bool vertex = e.name == "vertex" || e.name == "vertices";
        for (std::size_t k = 0; k < e.props.size(); ++k) {
            const PlyProperty& pr = e.props[k];
            if (std::any_of(e.props.begin(), e.props.begin() + static_cast<std::ptrdiff_t>(k), [&](const PlyProperty& o) { return o.name == pr.name; }))
                continue;
            const bool coord = vertex && (pr.name == "x" || pr.name == "y" || pr.name == "z");
            const bool end = e.name == "halfedge" && (pr.name == "source" || pr.name == "target");
            if ((coord && (pr.count_size != 0 || pr.integral)) || (end && pr.count_size == 0 && pr.type != "uint" && pr.type != "uint32") ||
                (end && pr.count_size != 0))
                return Refusal{"unsupported PLY file: line " + std::to_string(e.header_line) + ": property '" + pr.name + "' of element '" + e.name +
                                   "' has type '" + pr.type + "' (" + (coord ? "coordinates must be float or double" : "halfedge ends must be uint") + ")",
                               false};
        }
    }
    // Colours (F20): CGAL reads r g b when each of them exists as a scalar uchar under either
    // name (red|r, green|g, blue|b), then fetches red/green/blue if 'red' is a uchar, else
    // r/g/b, as uchar without checking those chosen names' types: a 'green' that is a float
    // next to a uchar 'g' is a null dereference. Such headers are refused; float colours
    // that CGAL simply does not read as colours are fine.
    for (const auto& e : elements) {
        if (e.name != "vertex" && e.name != "vertices" && e.name != "face" && e.name != "faces") continue;
        auto first = [&](const char* name) -> const PlyProperty* {
            for (const auto& pr : e.props)
                if (pr.name == name) return &pr;
            return nullptr;
        };
        auto is_uchar = [](const PlyProperty* pr) { return pr && pr->count_size == 0 && (pr->type == "uchar" || pr->type == "uint8"); };
        auto uchar = [&](const char* name) { return is_uchar(first(name)); };
        if (!((uchar("red") || uchar("r")) && (uchar("green") || uchar("g")) && (uchar("blue") || uchar("b")))) continue;
        static constexpr const char* kLong[3] = {"red", "green", "blue"};
        static constexpr const char* kShort[3] = {"r", "g", "b"};
        for (const char* tag : uchar("red") ? kLong : kShort) {
            const PlyProperty* pr = first(tag);
            if (pr && !is_uchar(pr))
                return Refusal{"unsupported PLY file: line " + std::to_string(e.header_line) + ": element '" + e.name + "' has uchar colours, but its property '" +
                                   tag + "' has type '" + pr->type + (pr->count_size ? " list" : "") + "' (colour components must all be uchar)",
                               false};
        }
    }
    // Vertices without coordinates would all be read as the origin, and CGAL reads faces only
    // from a 'vertex_indices' (or else 'vertex_index') list of int or uint.
    std::vector<const PlyProperty*> face_list(elements.size(), nullptr);  // the list CGAL reads, per element
    for (std::size_t ei = 0; ei < elements.size(); ++ei) {
        const PlyElement& e = elements[ei];
        if (e.count == 0) continue;
        auto first = [&](const char* name) -> const PlyProperty* {
            for (const auto& pr : e.props)
                if (pr.name == name) return &pr;
            return nullptr;
        };
        if (e.name == "vertex" || e.name == "vertices") {
            for (const char* c : {"x", "y", "z"})
                if (!first(c))
                    return Refusal{"unsupported PLY file: line " + std::to_string(e.header_line) + ": element '" + e.name + "' has no property '" + c +
                                       "' (vertex coordinates x, y, z must be float or double)",
                                   false};
        } else if (e.name == "face" || e.name == "faces") {
            auto int_list = [](const PlyProperty* pr) {
                return pr && pr->count_size != 0 && (pr->type == "list int" || pr->type == "list int32" || pr->type == "list uint" || pr->type == "list uint32");
            };
            const PlyProperty* list = int_list(first("vertex_indices")) ? first("vertex_indices") : int_list(first("vertex_index")) ? first("vertex_index") : nullptr;
            if (!list)
                return Refusal{"unsupported PLY file: line " + std::to_string(e.header_line) + ": element '" + e.name +
                                   "' has no 'vertex_indices' (or 'vertex_index') list of int or uint",
                               false};
            face_list[ei] = list;
        }
    }
    const std::size_t body = end_header ? std::min(p, n) : n;
    const std::size_t have = n - body;
    auto truncated = [&](const PlyElement& e, unsigned long long i) {
        return Refusal{"truncated PLY file: element '" + e.name + "' declares " + std::to_string(e.count) + " items but the data ends at item " + std::to_string(i), true};
    };
    if (format == 0) {
        // Every property of every item is at least one token of >= 1 byte plus a separator.
        unsigned long long tokens = 0;
        for (const auto& e : elements) {
            if (e.count > have + 1 || (tokens += e.count * e.props.size()) > (have + 1) / 2)
                return Refusal{"truncated PLY file: the header declares more element data than the " + std::to_string(have) + " bytes after 'end_header' can hold", true};
        }
        // Walk the body the way CGAL reads it (whitespace-separated numbers, only the properties
        // it knows): a list with a 32-bit count could make it allocate up to 32 GB (F7), and a
        // count or number it tries to read past the end is left uninitialised and then used
        // (found by code audit with MSan). A narrow list count is cast to its type by CGAL (a
        // uchar count of 259 reads 3 entries), so one out of its type's range is refused.
        std::size_t q = body;
        for (const auto& e : elements) {
            for (unsigned long long i = 0; i < e.count; ++i) {
                for (const auto& pr : e.props) {
                    auto bad = [&](std::string_view tok, const std::string& what) {
                        return Refusal{"line " + std::to_string(line_of(d, q)) + ": element '" + e.name + "' item " + std::to_string(i) + ": " + what +
                                           " '" + std::string(tok.substr(0, 40)) + "'",
                                       false};
                    };
                    auto number_ok = [&](std::string_view tok, bool integral) {
                        long long iv = 0;
                        double dv = 0;
                        return integral ? clean_signed(tok, iv) : clean_double(tok, dv);
                    };
                    std::string_view tok = next_token(d, q, n);
                    if (tok.empty()) return truncated(e, i);
                    if (pr.count_size == 0) {
                        if (!number_ok(tok, pr.integral)) return bad(tok, "cannot parse property '" + pr.name + "'");
                        continue;
                    }
                    long long c = 0;
                    if (!clean_signed(tok, c) || c < 0) return bad(tok, "bad count for list '" + pr.name + "'");
                    if (pr.count_size < 4 && c > (1LL << (8 * pr.count_size - (pr.count_signed ? 1 : 0))) - 1)
                        return bad(tok, "count of list '" + pr.name + "' out of range for its " + std::to_string(8 * pr.count_size) + "-bit " +
                                            (pr.count_signed ? "signed" : "unsigned") + " type:");
                    if (&pr == face_list[static_cast<std::size_t>(&e - elements.data())] && c < 3)
                        return Refusal{"line " + std::to_string(line_of(d, q)) + ": face " + std::to_string(i) + " has only " + std::to_string(c) +
                                           " vertices (at least 3 needed)",
                                       false};
                    if (static_cast<unsigned long long>(c) > (n - q) / 2 + 1) {
                        Refusal r = bad(tok, "list '" + pr.name + "' declares more entries than the rest of the file can hold:");
                        r.what = "truncated PLY file: " + r.what;
                        r.prefer_diagnosis = true;
                        return r;
                    }
                    for (long long k = 0; k < c; ++k) {
                        tok = next_token(d, q, n);
                        if (tok.empty()) return truncated(e, i);
                        if (!number_ok(tok, pr.integral)) return bad(tok, "cannot parse an entry of list '" + pr.name + "'");
                    }
                }
            }
        }
        return std::nullopt;
    }
    // Binary: walk the records (O(items) only for elements with lists).
    std::size_t q = body;
    for (const auto& e : elements) {
        if (e.count == 0) continue;
        bool has_list = false;
        std::size_t fixed = 0;
        for (const auto& pr : e.props) {
            has_list = has_list || pr.count_size != 0;
            fixed += pr.count_size ? pr.count_size : pr.size;
        }
        if (!has_list) {
            if (e.count > (n - q) / fixed) return truncated(e, (n - q) / fixed);
            q += static_cast<std::size_t>(e.count) * fixed;
            continue;
        }
        for (unsigned long long i = 0; i < e.count; ++i) {
            for (const auto& pr : e.props) {
                if (pr.count_size == 0) {
                    if (n - q < pr.size) return truncated(e, i);
                    q += pr.size;
                    continue;
                }
                if (n - q < pr.count_size) return truncated(e, i);
                unsigned char b[4] = {0, 0, 0, 0};
                for (std::size_t k = 0; k < pr.count_size; ++k)
                    b[format == 1 ? k : pr.count_size - 1 - k] = static_cast<unsigned char>(d[q + k]);
                q += pr.count_size;
                uint64_t c = 0;
                for (std::size_t k = pr.count_size; k-- > 0;) c = c << 8 | b[k];
                const bool negative = pr.count_signed && (b[pr.count_size - 1] & 0x80);
                if (!negative && &pr == face_list[static_cast<std::size_t>(&e - elements.data())] && c < 3)
                    return Refusal{"face " + std::to_string(i) + " has only " + std::to_string(c) + " vertices (at least 3 needed)", false};
                if (negative || c > (n - q) / pr.size)
                    return Refusal{std::string(negative ? "corrupt" : "truncated") + " PLY file: element '" + e.name + "' item " + std::to_string(i) +
                                       ": list '" + pr.name + "' declares " + (negative ? std::string("a negative number of") : std::to_string(c)) +
                                       " entries but only " + std::to_string((n - q) / pr.size) + " fit in the rest of the file",
                                   !negative};
                q += static_cast<std::size_t>(c) * pr.size;
            }
        }
    }
    return std::nullopt;
}

// ---- OBJ ----

/// CGAL's OBJ reader grows its arrays line by line (no declared counts), but it reads a face with
/// `while (iss >> int) { ...; iss.ignore(256, ' '); }`: a token that is not an int (or overflows)
/// silently ends the face, and a tab after a token swallows the next one. Refuse those faces
/// instead of reading a different polygon than the file's.
std::optional<Refusal> prescan_obj(std::string_view d) {
    const std::size_t n = d.size();
    std::size_t p = 0, lineno = 0, face = 0;
    while (p < n) {
        const std::size_t line = p;
        std::size_t end = end_of_line(d, p);
        p = end + 1;
        ++lineno;
        std::size_t q = line;
        if (next_token(d, q, end) != "f") continue;
        if (const void* hash = std::memchr(d.data() + q, '#', end - q)) {
            const std::size_t h = static_cast<std::size_t>(static_cast<const char*>(hash) - d.data());
            // CGAL reads an index, then skips to the next space: a '#' glued to an index does not
            // end its line, and the "comment" after it is read as more corners (F25).
            if (!is_ws(d[h - 1])) {
                std::size_t after = h;
                while (after < end && !is_ws(d[after])) ++after;
                if (d.substr(after, end - after).find_first_not_of(" \t\r\f\v") != std::string_view::npos)
                    return Refusal{"line " + std::to_string(lineno) + ": face " + std::to_string(face) +
                                       ": '#' right after a vertex reference with more text after it (a comment needs a space before '#')",
                                   false};
            }
            end = h;
        }
        for (std::string_view t; !(t = next_token(d, q, end)).empty();) {
            auto where = [&] { return "line " + std::to_string(lineno) + ": face " + std::to_string(face) + ": "; };
            const std::string_view head = t.substr(0, t.find('/'));
            long long v = 0;
            if (!clean_signed(head, v) || v == 0 || v < -2147483648LL || v > 2147483647LL)
                return Refusal{where() + "bad vertex index '" + std::string(t.substr(0, 40)) + "'", false};
            const std::string_view rest = d.substr(q, end - q);
            const bool last = rest.find_first_not_of(" \t\r\f\v") == std::string_view::npos;
            if (!last && (d[q] != ' ' || t.size() > 250))
                return Refusal{where() + "vertex references must be separated by spaces (after '" + std::string(t.substr(0, 40)) + "')", false};
        }
        ++face;
    }
    return std::nullopt;
}

// ---- STL ----

std::optional<Refusal> prescan_stl(std::string_view d) {
    // CGAL reads a file as binary unless its first word is "solid" followed by a separator.
    std::size_t p = 0;
    while (p < d.size() && std::isspace(static_cast<unsigned char>(d[p]))) ++p;
    if (d.size() - p >= 6 && d.substr(p, 5) == "solid" && (d[p + 5] == '\n' || d[p + 5] == '\r' || d[p + 5] == ' ')) return std::nullopt;
    if (d.size() < 84) return std::nullopt;  // CGAL fails at once; diagnosed after
    uint32_t count = 0;
    std::memcpy(&count, d.data() + 80, 4);
    if (84 + 50 * static_cast<std::size_t>(count) <= d.size()) return std::nullopt;
    // CGAL then retries the file as ASCII. That is what an ASCII file whose "solid" CGAL did not
    // recognise needs (a tab after it, a UTF-8 byte-order mark before it); anything else is a
    // truncated binary file, and reading it as text would pick words out of binary data.
    std::size_t a = d.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
    while (a < d.size() && is_ws(d[a])) ++a;
    if (d.substr(a, 5) == "solid" && a + 5 < d.size() && is_ws(d[a + 5])) return std::nullopt;
    return Refusal{"truncated binary STL file: the header declares " + std::to_string(count) + " triangles (" +
                       std::to_string(84 + 50 * static_cast<std::size_t>(count)) + " bytes) but the file has " + std::to_string(d.size()) + " bytes",
                   true};
}

/// Why CGAL's binary STL parser must not see `d`, or nothing: a vertex coordinate that is NaN
/// would be merged into an arbitrary vertex by its std::map (NaN compares equal to everything;
/// F23), so every non-finite vertex coordinate of a complete binary file is refused here.
std::optional<std::string> binary_stl_problem(std::string_view d) {
    if (d.size() < 84) return std::nullopt;
    uint32_t count = 0;
    std::memcpy(&count, d.data() + 80, 4);
    if (84 + 50 * static_cast<std::size_t>(count) > d.size()) return std::nullopt;  // the parser fails on it
    for (std::size_t t = 0; t < count; ++t)
        for (std::size_t k = 0; k < 9; ++k) {
            float x = 0;
            std::memcpy(&x, d.data() + 84 + 50 * t + 12 + 4 * k, 4);  // little-endian, as CGAL reads it
            if (!std::isfinite(x))
                return "binary STL triangle " + std::to_string(t) + ": vertex " + std::to_string(k / 3) + " has a non-finite coordinate (NaN or infinity)";
        }
    return std::nullopt;
}

/// CGAL's STL dispatch (STL.h, read_STL(istream&)): a file whose first word is "solid" is
/// parsed as ASCII, then as binary if that fails; any other file as binary, then as ASCII. CGAL
/// keeps the first attempt's points and triangles when it makes the second, whose indices then
/// point at the wrong points (F24: a binary file with a "solid" header read with three vertices
/// from the header). Here the soup is cleared before each attempt.
bool read_stl(std::istringstream& in, std::vector<CgalPoint>& points, std::vector<std::vector<std::size_t>>& polygons,
              std::optional<std::string>& problem) {
    const std::string_view d = in.view();
    std::size_t p = 0;
    while (p < d.size() && std::isspace(static_cast<unsigned char>(d[p]))) ++p;
    if (d.size() - p < 6) return true;  // CGAL reads an empty soup
    const bool solid = d.substr(p, 5) == "solid" && (d[p + 5] == '\n' || d[p + 5] == '\r' || d[p + 5] == ' ');
    auto attempt = [&](bool ascii) {
        points.clear();
        polygons.clear();
        in.clear();
        in.seekg(0);
        if (ascii) return CGAL::IO::internal::parse_ASCII_STL(in, points, polygons, false);
        problem = binary_stl_problem(d);
        return !problem && CGAL::IO::internal::parse_binary_STL(in, points, polygons, false);
    };
    const bool ok = solid ? attempt(true) || attempt(false) : attempt(false) || (!problem && attempt(true));
    if (!ok) {
        points.clear();
        polygons.clear();
    }
    return ok;
}

}  // namespace

TriangleSoup read_mesh_file(const std::string& path, const ReadOptions& options) {
    std::string named = options.format;
    std::transform(named.begin(), named.end(), named.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const std::string ext = named.empty() ? lower_extension(path) : "." + named;
    InFormat fmt;
    if (ext == ".obj") fmt = InFormat::Obj;
    else if (ext == ".off") fmt = InFormat::Off;
    else if (ext == ".ply") fmt = InFormat::Ply;
    else if (ext == ".stl") fmt = InFormat::Stl;
    else if (!named.empty()) fail(path, "unknown input format '" + options.format + "' (expected obj, off, ply or stl)");
    else fail(path, "unknown input format '" + ext + "' (expected .obj, .off, .ply or .stl, or a format named with --input-format)");

    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) fail(path, "no such file");
    if (std::filesystem::is_directory(status)) fail(path, "is a directory, not a mesh file");
    // A device (/dev/urandom) never ends; a pipe does, and is read like a file.
    if (!std::filesystem::is_regular_file(status) && !std::filesystem::is_fifo(status))
        fail(path, "is not a regular file or a pipe (devices and sockets are not read)");

    // The bytes are read once: the pre-scan, CGAL and the diagnosis all see the same ones, even
    // if the file changes meanwhile or is a pipe (F22: CGAL used to reopen the path).
    std::string data;
    {
        std::ifstream in(path, std::ios::binary);
        if (!in) fail(path, std::string("cannot open file for reading (") + std::strerror(errno) + ")");
        const std::uint64_t size = std::filesystem::is_regular_file(status) ? std::filesystem::file_size(path, ec) : 0;
        const std::string too_large = "larger than the input limit of " + std::to_string(options.max_input_bytes) + " bytes (ReadOptions::max_input_bytes)";
        if (!ec && size > options.max_input_bytes) fail(path, too_large);
        auto bytes = read_all(in, ec ? 0 : static_cast<std::size_t>(size), options.max_input_bytes);
        if (!bytes) fail(path, too_large);
        if (in.bad()) fail(path, "read error");
        data = std::move(*bytes);
    }
    // Empty means no bytes, or only whitespace.
    if (std::all_of(data.begin(), data.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; })) fail(path, "empty file");

    auto diagnose = [&](bool cgal_failed) -> std::optional<std::string> {
        switch (fmt) {
            case InFormat::Off: return diagnose_off(path, data);
            case InFormat::Ply: return diagnose_ply(data);
            case InFormat::Stl: return diagnose_stl(data);
            case InFormat::Obj: return cgal_failed ? diagnose_obj(path, data) : std::nullopt;
        }
        return std::nullopt;
    };

    // CGAL trusts declared counts (it resizes to them before reading) and crashes or hangs on some
    // malformed PLY headers: refuse those files from the bytes before CGAL sees them.
    {
        std::optional<Refusal> refusal;
        switch (fmt) {
            case InFormat::Off: refusal = prescan_off(data); break;
            case InFormat::Ply: refusal = prescan_ply(data); break;
            case InFormat::Stl: refusal = prescan_stl(data); break;
            case InFormat::Obj: refusal = prescan_obj(data); break;
        }
        if (refusal) {
            // The line-based diagnosers give the messages users already know (truncation, face
            // sizes, indices); they allocate nothing proportional to declared counts.
            const std::optional<std::string> why = refusal->prefer_diagnosis ? diagnose(false) : std::nullopt;
            fail(path, why ? *why : refusal->what);
        }
    }

    std::vector<CgalPoint> points;
    std::vector<std::vector<std::size_t>> polygons;
    bool ok = false;
    std::optional<std::string> stl_problem;
    // The stream is built on the bytes (moved in and out, not copied).
    std::istringstream in(std::move(data));
    try {
        const auto np = CGAL::parameters::verbose(false);
        switch (fmt) {
            case InFormat::Obj:
                CGAL::IO::set_mode(in, CGAL::IO::ASCII);
                ok = CGAL::IO::read_OBJ(in, points, polygons, np);
                break;
            case InFormat::Off: ok = CGAL::IO::read_OFF(in, points, polygons, np); break;
            case InFormat::Ply:
                CGAL::IO::set_mode(in, CGAL::IO::BINARY);
                ok = CGAL::IO::read_PLY(in, points, polygons, np);
                break;
            case InFormat::Stl: ok = read_stl(in, points, polygons, stl_problem); break;
        }
    } catch (const std::exception& e) {
        ok = false;  // CGAL's PLY reader may throw on malformed input; our diagnosis follows
    }
    data = std::move(in).str();
    if (stl_problem) fail(path, *stl_problem);
    if (!ok) {
        const std::optional<std::string> why = diagnose(true);
        fail(path, why ? *why : std::string("malformed or truncated ") + format_name(fmt) + " file");
    }
    // Peak memory: the bytes, CGAL's arrays and the soup are never all held at once.
    std::string().swap(data);

    // Checks CGAL does not make (or makes with an off-by-one, as its OBJ reader does).
    TriangleSoup soup;
    soup.points.reserve(points.size());
    for (std::size_t v = 0; v < points.size(); ++v) {
        const auto& p = points[v];
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
            fail(path, "vertex " + std::to_string(v) + " has a non-finite coordinate (NaN or infinity)");
        soup.points.push_back({p.x(), p.y(), p.z()});
    }
    const std::size_t num_points = points.size();
    std::vector<CgalPoint>().swap(points);
    if (num_points >= 0xffffffffu) fail(path, "too many vertices (more than 2^32-1)");
    if (polygons.empty()) fail(path, "no faces (the file has " + std::to_string(num_points) + " vertices and 0 faces)");
    std::size_t tris = 0;
    for (std::size_t f = 0; f < polygons.size(); ++f) {
        const auto& poly = polygons[f];
        if (poly.size() < 3)
            fail(path, "face " + std::to_string(f) + " has only " + std::to_string(poly.size()) + " vertices (at least 3 needed)");
        for (std::size_t idx : poly)
            if (idx >= num_points)
                // CGAL stores OBJ's negative/relative indices wrapped; print them signed.
                fail(path, index_problem(f, static_cast<long long>(static_cast<std::ptrdiff_t>(idx)), num_points));
        tris += poly.size() - 2;
    }
    soup.triangles.reserve(tris);
    soup.source_polygon.reserve(tris);
    for (std::size_t f = 0; f < polygons.size(); ++f) {
        const auto& poly = polygons[f];
        for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
            soup.triangles.push_back({static_cast<uint32_t>(poly[0]), static_cast<uint32_t>(poly[i]), static_cast<uint32_t>(poly[i + 1])});
            soup.source_polygon.push_back(static_cast<uint32_t>(f));
        }
    }
    return soup;
}

}  // namespace singlestrip
