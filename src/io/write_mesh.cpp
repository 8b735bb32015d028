// Output writers. Every file is written to a temporary next to the target and renamed into
// place only after a successful flush and close, so a failure never leaves a partial output.
#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "float32_range.hpp"
#include "singlestrip/attributes.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"

namespace singlestrip {
namespace {

/// Writes through `fill(std::ofstream&)` into "<path>.tmp-XXXX" and renames it to `path`.
template <class Fill>
void write_atomically(const std::string& path, Fill&& fill) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    if (fs::is_directory(target)) throw OutputError(path + ": is a directory");
    std::random_device rd;
    const fs::path tmp = target.string() + ".tmp-" + std::to_string(rd() % 1000000u);
    try {
        {
            std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
            if (!out) throw OutputError(path + ": cannot create output file (" + std::strerror(errno) + ")");
            fill(out);
            out.flush();
            if (!out) throw OutputError(path + ": write failed (" + std::strerror(errno) + ")");
            out.close();
            if (out.fail()) throw OutputError(path + ": write failed on close");
        }
        std::error_code ec;
        fs::rename(tmp, target, ec);
        if (ec) throw OutputError(path + ": cannot move the finished file into place (" + ec.message() + ")");
    } catch (...) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw;
    }
}

/// Binary records gathered and handed to the stream in 1 MB blocks: one ostream::write per
/// value cost more than everything else the writer does (1M-face binary PLY: 0.15 s).
class Blocks {
public:
    explicit Blocks(std::ostream& out) : out_(out) { buf_.reserve(kBlock); }
    Blocks(const Blocks&) = delete;
    Blocks& operator=(const Blocks&) = delete;
    ~Blocks() { flush(); }
    void put(const char* p, std::size_t n) {
        if (buf_.size() + n > kBlock) flush();
        buf_.insert(buf_.end(), p, p + n);
    }
    void put(const unsigned char* p, std::size_t n) { put(reinterpret_cast<const char*>(p), n); }
    // Text as an ostream would write it (decimal integers), for the OBJ and OFF writers.
    Blocks& operator<<(const char* s) { return put(s, std::strlen(s)), *this; }
    Blocks& operator<<(char c) { return put(&c, 1), *this; }
    template <class T>
    requires std::is_integral_v<T> &&(!std::is_same_v<T, char>)&&(!std::is_same_v<T, bool>)Blocks& operator<<(T v) {
        char b[24];
        const auto r = std::to_chars(b, b + sizeof b, v);
        return put(b, static_cast<std::size_t>(r.ptr - b)), *this;
    }
    void flush() {
        out_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
        buf_.clear();
    }

private:
    static constexpr std::size_t kBlock = std::size_t{1} << 20;
    std::ostream& out_;
    std::vector<char> buf_;
};

void put_double(Blocks& out, double v) {
    char buf[64];
    // Shortest round-trip representation: the coordinates read back bit-exact.
    auto res = std::to_chars(buf, buf + sizeof buf, v);
    out.put(buf, static_cast<std::size_t>(res.ptr - buf));
}

template <class T>
void put_le(Blocks& out, T v) {
    static_assert(std::is_trivially_copyable_v<T>);
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + sizeof(T));
    out.put(b, sizeof(T));
}

/// Binary STL: 80-byte header, facet count, then per face its float32 unit normal (zero for a
/// degenerate face), three float32 corners and a zero attribute word.
void write_binary_stl(std::ostream& stream, const std::vector<Point3>& points, const std::vector<Triangle>& faces) {
    char header[80] = "singlestrip: faces in strip order (binary STL, float32)";
    stream.write(header, sizeof header);
    Blocks out(stream);
    put_le(out, static_cast<uint32_t>(faces.size()));
    for (const Triangle& t : faces) {
        const Point3 &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (double& x : n) x = len > 0 ? x / len : 0.0;
        for (double x : n) put_le(out, static_cast<float>(x));
        for (uint32_t k : t)
            for (double x : points[k]) put_le(out, static_cast<float>(x));
        put_le<uint16_t>(out, 0);
    }
}

}  // namespace

OutputFormat output_format_for(const std::string& path) {
    const std::string ext = lower_extension(path);
    if (ext == ".ply") return OutputFormat::Ply;
    if (ext == ".obj") return OutputFormat::Obj;
    if (ext == ".off") return OutputFormat::Off;
    if (ext == ".stl") return OutputFormat::Stl;
    throw RequestError(path + ": unknown output format '" + ext + "' (expected .ply, .obj, .off, .stl, .glb or .gltf)");
}

namespace {

/// PLY properties of one attribute: (name, type) per component.
std::vector<std::pair<std::string, const char*>> ply_properties(const VertexAttribute& a) {
    auto named = [&](std::initializer_list<const char*> names, const char* type) {
        std::vector<std::pair<std::string, const char*>> p;
        for (const char* n : names) p.emplace_back(n, type);
        p.resize(a.components, {"", type});
        return p;
    };
    if (a.name == "NORMAL" && a.components == 3) return named({"nx", "ny", "nz"}, "float");
    if (a.name == "TEXCOORD_0" && a.components == 2) return named({"s", "t"}, "float");
    if (a.name == "COLOR_0" && (a.components == 3 || a.components == 4)) return named({"red", "green", "blue", "alpha"}, "uchar");
    const char* type = a.blend == AttributeBlend::Nearest ? "int" : "double";
    std::vector<std::pair<std::string, const char*>> p;
    for (uint32_t c = 0; c < a.components; ++c) p.emplace_back(a.components == 1 ? a.name : a.name + "_" + std::to_string(c), type);
    return p;
}

/// One attribute value as its PLY property type.
void put_ply_value(Blocks& out, const char* type, double x) {
    if (type[0] == 'u')
        put_le<uint8_t>(out, static_cast<uint8_t>(std::lround(std::clamp(x, 0.0, 1.0) * 255)));
    else if (type[0] == 'f')
        put_le(out, static_cast<float>(x));
    else if (type[0] == 'i')
        put_le(out, static_cast<int32_t>(std::clamp(std::round(x), -2147483648.0, 2147483647.0)));
    else
        put_le(out, x);
}

void write_ply_body(std::ostream& stream, const std::vector<Point3>& points, const std::vector<Triangle>& faces,
                    const std::vector<uint32_t>& parent, const std::vector<VertexAttribute>& attrs,
                    const std::vector<std::vector<std::pair<std::string, const char*>>>& props) {
    Blocks out(stream);
    for (std::size_t v = 0; v < points.size(); ++v) {
        for (double c : points[v]) put_le(out, c);
        for (std::size_t i = 0; i < attrs.size(); ++i)
            for (uint32_t c = 0; c < attrs[i].components; ++c)
                put_ply_value(out, props[i][c].second, attrs[i].values[v * attrs[i].components + c]);
    }
    for (std::size_t f = 0; f < faces.size(); ++f) {
        put_le<uint8_t>(out, 3);
        for (uint32_t v : faces[f]) put_le(out, v);
        put_le(out, parent[f]);
    }
}

void write_ply(std::ostream& out, const std::vector<Point3>& points, const std::vector<Triangle>& faces,
               const std::vector<uint32_t>& parent, const std::vector<VertexAttribute>& attrs) {
    std::vector<std::vector<std::pair<std::string, const char*>>> props;
    out << "ply\nformat binary_little_endian 1.0\ncomment singlestrip: faces in strip order; parent = input triangle\n"
        << "element vertex " << points.size() << "\nproperty double x\nproperty double y\nproperty double z\n";
    for (const VertexAttribute& a : attrs) {
        props.push_back(ply_properties(a));
        for (const auto& [name, type] : props.back()) out << "property " << type << ' ' << name << '\n';
    }
    out << "element face " << faces.size() << "\nproperty list uchar uint vertex_indices\nproperty uint parent\nend_header\n";
    write_ply_body(out, points, faces, parent, attrs, props);
}

void put_numbers(Blocks& out, const char* record, const double* x, std::size_t k) {
    out << record;
    for (std::size_t i = 0; i < k; ++i) {
        out << ' ';
        put_double(out, x[i]);
    }
    out << '\n';
}

/// OBJ holds texture coordinates and normals: one vt / vn per vertex, so every index stream of
/// a face is the vertex number ("f a/a/a"); colours go after the coordinates ("v x y z r g b").
void write_obj(std::ostream& stream, const std::vector<Point3>& points, const std::vector<Triangle>& faces,
               const std::vector<VertexAttribute>& attrs) {
    Blocks out(stream);
    const VertexAttribute* uv = find_attribute(attrs, "TEXCOORD_0");
    const VertexAttribute* n = find_attribute(attrs, "NORMAL");
    if (uv && uv->components != 2) uv = nullptr;
    if (n && n->components != 3) n = nullptr;
    out << "# singlestrip: faces in strip order\n";
    const VertexAttribute* rgb = find_attribute(attrs, "COLOR_0");  // "v x y z r g b", the common extension
    if (rgb && rgb->components < 3) rgb = nullptr;
    for (std::size_t v = 0; v < points.size(); ++v) {
        if (!rgb) {
            put_numbers(out, "v", points[v].data(), 3);
            continue;
        }
        const double x[6] = {points[v][0],
                             points[v][1],
                             points[v][2],
                             rgb->values[v * rgb->components],
                             rgb->values[v * rgb->components + 1],
                             rgb->values[v * rgb->components + 2]};
        put_numbers(out, "v", x, 6);
    }
    if (uv)
        for (std::size_t v = 0; v < points.size(); ++v) put_numbers(out, "vt", &uv->values[2 * v], 2);
    if (n)
        for (std::size_t v = 0; v < points.size(); ++v) put_numbers(out, "vn", &n->values[3 * v], 3);
    for (const auto& t : faces) {
        out << 'f';
        for (uint32_t v : t) {
            out << ' ' << v + 1ull;
            if (uv) out << '/' << v + 1ull;
            if (n) out << (uv ? "/" : "//") << v + 1ull;
        }
        out << '\n';
    }
}

/// [ST][C][N]OFF: a vertex line is x y z [nx ny nz] [r g b [a]] [s t] (Geomview's order), colours
/// as fractions clamped into [0, 1] (the reader takes integers above 1 for bytes).
void write_off(std::ostream& stream, const std::vector<Point3>& points, const std::vector<Triangle>& faces,
               const std::vector<VertexAttribute>& attrs) {
    Blocks out(stream);
    const VertexAttribute* n = find_attribute(attrs, "NORMAL");
    const VertexAttribute* rgb = find_attribute(attrs, "COLOR_0");
    const VertexAttribute* st = find_attribute(attrs, "TEXCOORD_0");
    if (n && n->components != 3) n = nullptr;
    if (rgb && rgb->components != 3 && rgb->components != 4) rgb = nullptr;
    if (st && st->components != 2) st = nullptr;
    out << (st ? "ST" : "") << (rgb ? "C" : "") << (n ? "N" : "") << "OFF\n" << points.size() << ' ' << faces.size() << " 0\n";
    for (std::size_t v = 0; v < points.size(); ++v) {
        double x[12];
        std::size_t k = 0;
        for (double c : points[v]) x[k++] = c;
        if (n)
            for (std::size_t c = 0; c < 3; ++c) x[k++] = n->values[3 * v + c];
        if (rgb)
            for (std::size_t c = 0; c < rgb->components; ++c) x[k++] = std::clamp(rgb->values[rgb->components * v + c], 0.0, 1.0);
        if (st)
            for (std::size_t c = 0; c < 2; ++c) x[k++] = st->values[2 * v + c];
        for (std::size_t i = 0; i < k; ++i) {
            if (i) out << ' ';
            put_double(out, x[i]);
        }
        out << '\n';
    }
    for (const auto& t : faces) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

}  // namespace

void write_strip_mesh(const std::string& path, const std::vector<Point3>& points, const std::vector<Triangle>& faces,
                      const std::vector<uint32_t>& parent, const std::vector<VertexAttribute>& attributes) {
    const OutputFormat fmt = output_format_for(path);
    if (parent.size() != faces.size())
        throw InternalError("write_strip_mesh: " + std::to_string(faces.size()) + " faces but " + std::to_string(parent.size()) +
                            " parents");
    for (std::size_t f = 0; f < faces.size(); ++f)
        for (uint32_t v : faces[f])
            if (v >= points.size())
                throw InternalError("write_strip_mesh: face " + std::to_string(f) + " references vertex " + std::to_string(v) + " of " +
                                    std::to_string(points.size()));
    if (const std::string bad = attribute_problem(attributes, points.size()); !bad.empty()) throw InternalError("write_strip_mesh: " + bad);
    if (fmt == OutputFormat::Stl) check_float32_range(path, points, "binary STL");
    write_atomically(path, [&](std::ofstream& out) {
        switch (fmt) {
            case OutputFormat::Ply:
                write_ply(out, points, faces, parent, attributes);
                break;
            case OutputFormat::Obj:
                write_obj(out, points, faces, attributes);
                break;
            case OutputFormat::Stl:
                write_binary_stl(out, points, faces);
                break;
            case OutputFormat::Off:
                write_off(out, points, faces, attributes);
                break;
        }
    });
}

void write_indices(const std::string& path, const std::vector<uint32_t>& indices) {
    write_atomically(path, [&](std::ofstream& stream) {
        Blocks out(stream);
        for (std::size_t i = 0; i < indices.size(); ++i) {
            out << indices[i];
            out << ((i % 16 == 15 || i + 1 == indices.size()) ? '\n' : ' ');
        }
    });
}

void write_text_atomic(const std::string& path, std::string_view text) {
    write_atomically(path, [&](std::ofstream& out) { out.write(text.data(), static_cast<std::streamsize>(text.size())); });
}

}  // namespace singlestrip
