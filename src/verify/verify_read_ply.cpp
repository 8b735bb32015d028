// singlestrip — the verifier's own PLY reader for OUTPUT files: header, ASCII and binary
// bodies of any element layout, the parent column and attribute properties (verify_read.cpp has
// the other formats).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "singlestrip/errors.hpp"
#include "singlestrip/verify.hpp"
#include "verify_read_common.hpp"

namespace singlestrip::verify_read_detail {
namespace {

enum class PlyType { I8, U8, I16, U16, I32, U32, F32, F64 };

bool ply_type(std::string_view s, PlyType& t) {
    if (s == "char" || s == "int8")
        t = PlyType::I8;
    else if (s == "uchar" || s == "uint8")
        t = PlyType::U8;
    else if (s == "short" || s == "int16")
        t = PlyType::I16;
    else if (s == "ushort" || s == "uint16")
        t = PlyType::U16;
    else if (s == "int" || s == "int32")
        t = PlyType::I32;
    else if (s == "uint" || s == "uint32")
        t = PlyType::U32;
    else if (s == "float" || s == "float32")
        t = PlyType::F32;
    else if (s == "double" || s == "float64")
        t = PlyType::F64;
    else
        return false;
    return true;
}

size_t ply_size(PlyType t) {
    switch (t) {
        case PlyType::I8:
        case PlyType::U8:
            return 1;
        case PlyType::I16:
        case PlyType::U16:
            return 2;
        case PlyType::I32:
        case PlyType::U32:
        case PlyType::F32:
            return 4;
        case PlyType::F64:
            return 8;
    }
    return 1;
}

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::F64;
    bool is_list = false;
    PlyType count_type = PlyType::U8;
};

struct PlyElement {
    std::string name;
    size_t count = 0;
    std::vector<PlyProperty> props;
};

/// Sequential value source over either ASCII tokens or binary bytes.
class PlySource {
public:
    PlySource(const std::string& path, std::string_view data, int format) : path_(path), data_(data), format_(format) {}

    double next(PlyType t, const std::string& where) {
        if (format_ == 0) return next_ascii(where);
        const size_t n = ply_size(t);
        if (pos_ + n > data_.size()) fail(path_, "truncated binary data (" + where + ")");
        unsigned char b[8];
        std::memcpy(b, data_.data() + pos_, n);
        pos_ += n;
        const bool file_le = format_ == 1;
        if (file_le != (std::endian::native == std::endian::little)) std::reverse(b, b + n);
        switch (t) {
            case PlyType::I8:
                return load<int8_t>(b);
            case PlyType::U8:
                return load<uint8_t>(b);
            case PlyType::I16:
                return load<int16_t>(b);
            case PlyType::U16:
                return load<uint16_t>(b);
            case PlyType::I32:
                return load<int32_t>(b);
            case PlyType::U32:
                return load<uint32_t>(b);
            case PlyType::F32:
                return load<float>(b);
            case PlyType::F64:
                return load<double>(b);
        }
        return 0;
    }

private:
    template <class T>
    static double load(const unsigned char* b) {
        T x;
        std::memcpy(&x, b, sizeof x);
        return static_cast<double>(x);
    }

    double next_ascii(const std::string& where) {
        while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
        if (pos_ >= data_.size()) fail(path_, "truncated ASCII data (" + where + ")");
        size_t end = pos_;
        while (end < data_.size() && !std::isspace(static_cast<unsigned char>(data_[end]))) ++end;
        const std::string_view tok = data_.substr(pos_, end - pos_);
        pos_ = end;
        double v = 0;
        if (!parse_double(tok, v)) fail(path_, "bad number '" + std::string(tok) + "' (" + where + ")");
        return v;
    }

    const std::string& path_;
    std::string_view data_;
    int format_;  // 0 ascii, 1 binary little endian, 2 binary big endian
    size_t pos_ = 0;
};

uint32_t as_index(const std::string& path, double v, const std::string& where) {
    if (!(v >= 0) || v > 4294967295.0 || v != std::floor(v)) fail(path, "bad index value (" + where + ")");
    return static_cast<uint32_t>(v);
}

/// How exactly a PLY property of type `t` holds a value (a colour in integers is a fraction of
/// the type's largest value).
void set_storage(OutputAttribute& a, PlyType t, bool colour) {
    if (t == PlyType::F64) return;
    if (t == PlyType::F32) {
        a.abs_tol = 1e-7, a.rel_tol = 1e-6, a.storage = "float32";
        return;
    }
    a.rel_tol = 0;
    a.abs_tol = colour ? 0.5 / (t == PlyType::U16 ? 65535 : 255) + 1e-12 : 0.5;
    a.storage = colour ? (t == PlyType::U16 ? "16-bit" : "8-bit") : "integer";
}

/// The vertex properties besides x y z as attributes, grouped under the names the PLY writer
/// uses: nx ny nz (NORMAL), red green blue [alpha] (COLOR_0), s t / u v (TEXCOORD_0), n_0 n_1 ...
/// (n, several components); any other property is an attribute of its own.
std::vector<OutputAttribute> ply_attributes(const std::vector<PlyProperty>& props, std::vector<std::vector<double>>& columns,
                                            const std::array<int, 3>& xyz) {
    std::vector<char> used(props.size(), 0);
    for (int i : xyz) used[static_cast<size_t>(i)] = 1;
    for (size_t i = 0; i < props.size(); ++i) used[i] = used[i] || props[i].is_list;
    auto column = [&](const std::string& name) -> int {
        for (size_t i = 0; i < props.size(); ++i)
            if (!used[i] && props[i].name == name) return static_cast<int>(i);
        return -1;
    };
    std::vector<OutputAttribute> out;
    auto take = [&](const std::string& name, const std::vector<int>& cols) {
        OutputAttribute a{name, static_cast<uint32_t>(cols.size()), {}};
        const PlyType t = props[static_cast<size_t>(cols[0])].type;
        const bool colour = name == "COLOR_0" && t != PlyType::F32 && t != PlyType::F64;
        const double scale = !colour ? 1.0 : t == PlyType::U16 ? 1.0 / 65535 : 1.0 / 255;
        set_storage(a, t, colour);
        const size_t n = columns[static_cast<size_t>(cols[0])].size();
        a.values.resize(n * cols.size());
        for (size_t v = 0; v < n; ++v)
            for (size_t c = 0; c < cols.size(); ++c) a.values[v * cols.size() + c] = columns[static_cast<size_t>(cols[c])][v] * scale;
        for (int c : cols) used[static_cast<size_t>(c)] = 1;
        out.push_back(std::move(a));
    };
    const std::vector<std::pair<std::string, std::vector<std::string>>> groups{{"NORMAL", {"nx", "ny", "nz"}},
                                                                               {"COLOR_0", {"red", "green", "blue", "alpha"}},
                                                                               {"COLOR_0", {"red", "green", "blue"}},
                                                                               {"TEXCOORD_0", {"s", "t"}},
                                                                               {"TEXCOORD_0", {"u", "v"}},
                                                                               {"TEXCOORD_0", {"texture_u", "texture_v"}},
                                                                               {"TEXCOORD_0", {"texture_s", "texture_t"}}};
    for (const auto& [name, names] : groups) {
        std::vector<int> cols;
        for (const std::string& n : names) cols.push_back(column(n));
        if (std::find(cols.begin(), cols.end(), -1) == cols.end() && !find_output_attribute(out, name)) take(name, cols);
    }
    for (size_t i = 0; i < props.size(); ++i) {
        if (used[i]) continue;
        const std::string& n = props[i].name;
        std::vector<int> cols{static_cast<int>(i)};
        if (n.size() > 2 && n.compare(n.size() - 2, 2, "_0") == 0) {  // name_0 name_1 ...: one attribute of several components
            const std::string base = n.substr(0, n.size() - 2);
            for (int c = 1; column(base + "_" + std::to_string(c)) >= 0; ++c) cols.push_back(column(base + "_" + std::to_string(c)));
            if (cols.size() > 1) {
                take(base, cols);
                continue;
            }
        }
        take(n, cols);
    }
    return out;
}

struct PlyHeader {
    int format = -1;  // 0 ascii, 1 binary little endian, 2 binary big endian
    std::vector<PlyElement> elements;
};

int ply_format(const std::string& path, const std::vector<std::string_view>& tok) {
    if (tok.size() < 2) fail(path, "bad format line");
    if (tok[1] == "ascii") return 0;
    if (tok[1] == "binary_little_endian") return 1;
    if (tok[1] == "binary_big_endian") return 2;
    fail(path, "unknown PLY format '" + std::string(tok[1]) + "'");
}

PlyProperty ply_property(const std::string& path, const std::vector<std::string_view>& tok, const std::string& where) {
    PlyProperty p;
    if (tok.size() == 5 && tok[1] == "list") {
        p.is_list = true;
        if (!ply_type(tok[2], p.count_type) || !ply_type(tok[3], p.type)) fail(path, "bad property type (" + where + ")");
        p.name = std::string(tok[4]);
    } else if (tok.size() == 3) {
        if (!ply_type(tok[1], p.type)) fail(path, "bad property type (" + where + ")");
        p.name = std::string(tok[2]);
    } else {
        fail(path, "bad property line (" + where + ")");
    }
    return p;
}

PlyHeader parse_ply_header(const std::string& path, std::string_view header) {
    PlyHeader h;
    const auto header_lines = split_lines(header);
    for (size_t li = 1; li < header_lines.size(); ++li) {
        const auto tok = split_ws(header_lines[li]);
        if (tok.empty() || tok[0] == "comment" || tok[0] == "obj_info") continue;
        const std::string where = "header line " + std::to_string(li + 1);
        if (tok[0] == "format") {
            h.format = ply_format(path, tok);
        } else if (tok[0] == "element") {
            long long count = 0;
            if (tok.size() != 3 || !parse_long(tok[2], count) || count < 0) fail(path, "bad element line (" + where + ")");
            h.elements.push_back({std::string(tok[1]), static_cast<size_t>(count), {}});
        } else if (tok[0] == "property") {
            if (h.elements.empty()) fail(path, "property before any element (" + where + ")");
            h.elements.back().props.push_back(ply_property(path, tok, where));
        } else {
            fail(path, "unexpected header keyword '" + std::string(tok[0]) + "' (" + where + ")");
        }
    }
    if (h.format < 0) fail(path, "missing format line");
    return h;
}

/// Reads and discards one list property's values.
void skip_ply_list(const std::string& path, PlySource& src, const PlyProperty& p, const std::string& where) {
    const uint32_t k = as_index(path, src.next(p.count_type, where), where);
    for (uint32_t j = 0; j < k; ++j) src.next(p.type, where);
}

/// The `vertex` element: positions, and every other scalar property as an attribute.
void read_ply_vertices(const std::string& path, const PlyElement& el, size_t data_size, PlySource& src, OutputMesh& m) {
    int ix = -1, iy = -1, iz = -1;
    for (size_t i = 0; i < el.props.size(); ++i) {
        if (el.props[i].is_list) continue;
        if (el.props[i].name == "x") ix = static_cast<int>(i);
        if (el.props[i].name == "y") iy = static_cast<int>(i);
        if (el.props[i].name == "z") iz = static_cast<int>(i);
    }
    if (ix < 0 || iy < 0 || iz < 0) fail(path, "vertex element lacks x, y or z");
    if (el.count > data_size + 1) fail(path, "vertex count exceeds the file size (truncated?)");
    m.points.resize(el.count);
    std::vector<std::vector<double>> columns(el.props.size());  // scalar properties besides x y z
    for (size_t v = 0; v < el.count; ++v) {
        const std::string where = "vertex " + std::to_string(v);
        for (size_t i = 0; i < el.props.size(); ++i) {
            const PlyProperty& p = el.props[i];
            if (p.is_list) {
                skip_ply_list(path, src, p, where);
                continue;
            }
            const double val = src.next(p.type, where);
            if (static_cast<int>(i) == ix) m.points[v][0] = val;
            if (static_cast<int>(i) == iy) m.points[v][1] = val;
            if (static_cast<int>(i) == iz) m.points[v][2] = val;
            if (static_cast<int>(i) != ix && static_cast<int>(i) != iy && static_cast<int>(i) != iz) columns[i].push_back(val);
        }
        check_point(path, v, m.points[v]);
    }
    m.attributes = ply_attributes(el.props, columns, {ix, iy, iz});
}

/// The `face` element: triangles (`vertex_indices`) and the optional `parent` of each.
void read_ply_faces(const std::string& path, const PlyElement& el, size_t data_size, PlySource& src, OutputMesh& m) {
    int ilist = -1, iparent = -1;
    for (size_t i = 0; i < el.props.size(); ++i) {
        const PlyProperty& p = el.props[i];
        if (p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index")) ilist = static_cast<int>(i);
        if (!p.is_list && p.name == "parent") iparent = static_cast<int>(i);
    }
    if (ilist < 0) fail(path, "face element lacks a vertex_indices list");
    if (el.count > data_size + 1) fail(path, "face count exceeds the file size (truncated?)");
    m.faces.resize(el.count);
    if (iparent >= 0) m.parent.resize(el.count);
    for (size_t f = 0; f < el.count; ++f) {
        const std::string where = "face " + std::to_string(f);
        for (size_t i = 0; i < el.props.size(); ++i) {
            const PlyProperty& p = el.props[i];
            if (p.is_list && static_cast<int>(i) == ilist) {
                const uint32_t k = as_index(path, src.next(p.count_type, where), where);
                if (k != 3) fail(path, where + " has " + std::to_string(k) + " vertices, expected a triangle");
                for (uint32_t j = 0; j < k; ++j) m.faces[f][j] = as_index(path, src.next(p.type, where), where);
            } else if (p.is_list) {
                skip_ply_list(path, src, p, where);
            } else {
                const double val = src.next(p.type, where);
                if (static_cast<int>(i) == iparent) m.parent[f] = as_index(path, val, where + " parent");
            }
        }
    }
}

/// An element other than vertex and face: its values are read and discarded.
void skip_ply_element(const std::string& path, const PlyElement& el, PlySource& src) {
    for (size_t r = 0; r < el.count; ++r) {
        const std::string where = el.name + " " + std::to_string(r);
        for (const PlyProperty& p : el.props) {
            if (p.is_list)
                skip_ply_list(path, src, p, where);
            else
                src.next(p.type, where);
        }
    }
}

}  // namespace

OutputMesh read_ply(const std::string& path) {
    const std::string text = slurp(path);
    if (text.empty()) fail(path, "empty file");
    const size_t end_header = text.find("end_header");
    if (text.rfind("ply", 0) != 0 || end_header == std::string::npos) fail(path, "not a PLY file (bad header)");
    size_t data_start = text.find('\n', end_header);
    data_start = data_start == std::string::npos ? text.size() : data_start + 1;
    const PlyHeader header = parse_ply_header(path, std::string_view(text).substr(0, end_header));

    // Counts are checked against the data size before reserving (truncated or hostile headers).
    const size_t data_size = text.size() - data_start;
    OutputMesh m;
    PlySource src(path, std::string_view(text).substr(data_start), header.format);
    bool have_vertex = false, have_face = false;
    for (const PlyElement& el : header.elements) {
        if (el.name == "vertex") {
            have_vertex = true;
            read_ply_vertices(path, el, data_size, src, m);
        } else if (el.name == "face") {
            have_face = true;
            read_ply_faces(path, el, data_size, src, m);
        } else {
            skip_ply_element(path, el, src);
        }
    }
    if (!have_vertex || !have_face) fail(path, "PLY lacks a vertex or face element");
    check_indices(path, m);
    return m;
}

}  // namespace singlestrip::verify_read_detail
