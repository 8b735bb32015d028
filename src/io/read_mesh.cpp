// Mesh file reading: CGAL's polygon-soup readers do the parsing; the checks around them turn
// CGAL's bare true/false into messages naming the file, the element and the problem.
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
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

std::string read_all(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
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
std::optional<std::string> diagnose_off(const std::string& path) {
    std::ifstream in(path);
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
std::optional<std::string> diagnose_obj(const std::string& path) {
    std::ifstream in(path);
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
std::optional<std::string> diagnose_ply(const std::string& path) {
    std::string data = read_all(path);
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
        long long need = 0;
        for (const auto& e : elements) need += e.count;
        if (static_cast<long long>(lines) < need)
            return "truncated PLY file: the header declares " + std::to_string(need) + " element lines but only " + std::to_string(lines) + " were found";
    } else {
        std::size_t need = 0;
        for (const auto& e : elements)
            need += static_cast<std::size_t>(e.count) * (e.fixed + (e.has_list ? e.list_min : 0));
        if (have < need)
            return "truncated PLY file: " + std::to_string(nv) + " vertices and " + std::to_string(nf) + " triangles need " + std::to_string(need) +
                   " bytes of data but the file has only " + std::to_string(have);
    }
    return std::nullopt;
}

/// STL: binary size check (84-byte header + 50 bytes per triangle).
std::optional<std::string> diagnose_stl(const std::string& path) {
    std::string data = read_all(path);
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

}  // namespace

TriangleSoup read_mesh_file(const std::string& path) {
    const std::string ext = lower_extension(path);
    InFormat fmt;
    if (ext == ".obj") fmt = InFormat::Obj;
    else if (ext == ".off") fmt = InFormat::Off;
    else if (ext == ".ply") fmt = InFormat::Ply;
    else if (ext == ".stl") fmt = InFormat::Stl;
    else fail(path, "unknown input format '" + ext + "' (expected .obj, .off, .ply or .stl)");

    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) fail(path, "no such file");
    if (std::filesystem::is_directory(status)) fail(path, "is a directory, not a mesh file");
    {
        std::ifstream probe(path, std::ios::binary);
        if (!probe) fail(path, std::string("cannot open file for reading (") + std::strerror(errno) + ")");
        char c;
        bool any_content = false;
        // Empty means no bytes, or only whitespace.
        while (probe.get(c))
            if (!std::isspace(static_cast<unsigned char>(c))) {
                any_content = true;
                break;
            }
        if (!any_content) fail(path, "empty file");
    }

    std::vector<CgalPoint> points;
    std::vector<std::vector<std::size_t>> polygons;
    bool ok = false;
    try {
        ok = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false));
    } catch (const std::exception& e) {
        ok = false;  // CGAL's PLY reader may throw on malformed input; our diagnosis follows
    }
    if (!ok) {
        std::optional<std::string> why;
        switch (fmt) {
            case InFormat::Off: why = diagnose_off(path); break;
            case InFormat::Obj: why = diagnose_obj(path); break;
            case InFormat::Ply: why = diagnose_ply(path); break;
            case InFormat::Stl: why = diagnose_stl(path); break;
        }
        fail(path, why ? *why : std::string("malformed or truncated ") + format_name(fmt) + " file");
    }

    // Checks CGAL does not make (or makes with an off-by-one, as its OBJ reader does).
    TriangleSoup soup;
    soup.points.reserve(points.size());
    for (std::size_t v = 0; v < points.size(); ++v) {
        const auto& p = points[v];
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
            fail(path, "vertex " + std::to_string(v) + " has a non-finite coordinate (NaN or infinity)");
        soup.points.push_back({p.x(), p.y(), p.z()});
    }
    if (points.size() >= 0xffffffffu) fail(path, "too many vertices (more than 2^32-1)");
    if (polygons.empty()) fail(path, "no faces (the file has " + std::to_string(points.size()) + " vertices and 0 faces)");
    std::size_t tris = 0;
    for (std::size_t f = 0; f < polygons.size(); ++f) {
        const auto& poly = polygons[f];
        if (poly.size() < 3)
            fail(path, "face " + std::to_string(f) + " has only " + std::to_string(poly.size()) + " vertices (at least 3 needed)");
        for (std::size_t idx : poly)
            if (idx >= points.size())
                // CGAL stores OBJ's negative/relative indices wrapped; print them signed.
                fail(path, index_problem(f, static_cast<long long>(static_cast<std::ptrdiff_t>(idx)), points.size()));
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
