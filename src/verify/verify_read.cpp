// singlestrip — the verifier's own readers for OUTPUT files (.ply/.obj/.off), index files and
// cycle files. Deliberately independent of src/io/*: a bug in the writer or the input readers
// must not be able to hide itself by being read back with the same code.
#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "singlestrip/errors.hpp"
#include "singlestrip/verify.hpp"

namespace singlestrip {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw InputError(path + ": " + what);
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot open file");
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) fail(path, "read error");
    return std::move(ss).str();
}

// The verifier's own copy of io.hpp's lower_extension (without the dot): its readers share no
// code with the readers whose output it checks.
std::string lower_extension(const std::string& path) {
    const auto slash = path.find_last_of("/\\");
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
    std::string ext = path.substr(dot + 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

bool parse_double(std::string_view tok, double& out) {
    if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
    const char* end = tok.data() + tok.size();
    auto res = std::from_chars(tok.data(), end, out);
    return res.ec == std::errc() && res.ptr == end;
}

bool parse_long(std::string_view tok, long long& out) {
    if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
    const char* end = tok.data() + tok.size();
    auto res = std::from_chars(tok.data(), end, out);
    return res.ec == std::errc() && res.ptr == end;
}

std::vector<std::string_view> split_ws(std::string_view line) {
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        size_t j = i;
        while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
        if (j > i) out.push_back(line.substr(i, j - i));
        i = j;
    }
    return out;
}

/// Splits text into lines (handles \n and \r\n), keeping line numbers implicit by position.
std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    size_t start = 0;
    while (start <= text.size()) {
        size_t nl = text.find('\n', start);
        if (nl == std::string_view::npos) nl = text.size();
        std::string_view line = text.substr(start, nl - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back(line);
        start = nl + 1;
    }
    return lines;
}

const OutputAttribute* find_output_attribute(const std::vector<OutputAttribute>& attrs, const std::string& name) {
    for (const OutputAttribute& a : attrs)
        if (a.name == name) return &a;
    return nullptr;
}

void check_point(const std::string& path, size_t v, const Point3& p) {
    for (double c : p)
        if (!std::isfinite(c)) fail(path, "vertex " + std::to_string(v) + " has a non-finite coordinate");
}

void check_indices(const std::string& path, const OutputMesh& m) {
    for (size_t f = 0; f < m.faces.size(); ++f)
        for (uint32_t v : m.faces[f])
            if (v >= m.points.size())
                fail(path, "face " + std::to_string(f) + " references vertex " + std::to_string(v) + " but the file has only " +
                               std::to_string(m.points.size()) + " vertices");
}

// ---------------------------------------------------------------------------------------------
// PLY

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

// ---------------------------------------------------------------------------------------------
// OBJ

/// One OBJ record of numbers ("vt u v", "vn x y z"): its first `k` numbers.
std::vector<double> obj_numbers(const std::string& path, const std::vector<std::string_view>& tok, size_t k, const std::string& where) {
    if (tok.size() < k + 1) fail(path, where + ": '" + std::string(tok[0]) + "' needs " + std::to_string(k) + " numbers");
    std::vector<double> x(k);
    for (size_t i = 0; i < k; ++i)
        if (!parse_double(tok[i + 1], x[i]) || !std::isfinite(x[i])) fail(path, where + ": bad number '" + std::string(tok[i + 1]) + "'");
    return x;
}

/// An OBJ index (1-based, or negative: relative to the `count` records read so far) as 0-based.
long long obj_index(long long idx, size_t count) {
    return idx > 0 ? idx - 1 : static_cast<long long>(count) + idx;
}

/// The per-vertex attribute of one OBJ index stream (vt or vn): vertex v takes the record its
/// corners name; every corner must name one (else no attribute) and all of v's the same one.
struct ObjStream {
    const char* name;
    size_t width;
    std::vector<double> records;                   // width numbers per record
    std::vector<std::array<long long, 3>> corner;  // raw index per face corner, 0 = none
    std::vector<size_t> count_at;                  // records read when the face was read
};

void obj_stream_attribute(const std::string& path, const ObjStream& st, const OutputMesh& m, std::vector<OutputAttribute>& out) {
    const size_t n_rec = st.records.size() / st.width;
    for (const auto& c : st.corner)
        for (long long x : c)
            if (x == 0) return;  // a corner without one: the stream is not an attribute
    if (st.corner.empty()) return;
    OutputAttribute a{
        st.name,       static_cast<uint32_t>(st.width), std::vector<double>(m.points.size() * st.width, std::nan("")), 1e-9, 1e-9,
        "decimal text"};
    std::vector<long long> given(m.points.size(), -1);
    for (size_t f = 0; f < st.corner.size(); ++f)
        for (size_t k = 0; k < 3; ++k) {
            const long long r = obj_index(st.corner[f][k], st.count_at[f]);
            if (r < 0 || static_cast<size_t>(r) >= n_rec)
                fail(path, "face " + std::to_string(f) + " references " + st.name + " record " + std::to_string(st.corner[f][k]) +
                               " but the file has " + std::to_string(n_rec));
            const uint32_t v = m.faces[f][k];
            if (given[v] >= 0 && given[v] != r &&
                !std::equal(&st.records[static_cast<size_t>(r) * st.width], &st.records[static_cast<size_t>(r) * st.width] + st.width,
                            &st.records[static_cast<size_t>(given[v]) * st.width]))
                fail(path, "vertex " + std::to_string(v) + " is given two different " + st.name + " values by its corners (face " +
                               std::to_string(f) + "); an output vertex has one");
            given[v] = r;
            std::copy_n(&st.records[static_cast<size_t>(r) * st.width], st.width, &a.values[v * st.width]);
        }
    out.push_back(std::move(a));
}

OutputMesh read_obj(const std::string& path) {
    const std::string text = slurp(path);
    OutputMesh m;
    std::vector<std::array<long long, 3>> raw;  // 1-based or negative, resolved below
    std::vector<size_t> nverts_at;              // vertex count when the face was read
    ObjStream uv{"TEXCOORD_0", 2, {}, {}, {}}, nrm{"NORMAL", 3, {}, {}, {}};
    std::vector<double> rgb;  // "v x y z r g b": only when every v has one
    bool every_v_coloured = true;
    const auto lines = split_lines(text);
    for (size_t li = 0; li < lines.size(); ++li) {
        std::string_view line = lines[li];
        if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        const auto tok = split_ws(line);
        if (tok.empty()) continue;
        const std::string where = "line " + std::to_string(li + 1);
        if (tok[0] == "v") {
            if (tok.size() < 4) fail(path, where + ": vertex needs 3 coordinates");
            Point3 p{};
            for (int k = 0; k < 3; ++k)
                if (!parse_double(tok[static_cast<size_t>(k) + 1], p[static_cast<size_t>(k)]))
                    fail(path, where + ": bad coordinate '" + std::string(tok[static_cast<size_t>(k) + 1]) + "'");
            check_point(path, m.points.size(), p);
            m.points.push_back(p);
            every_v_coloured = every_v_coloured && tok.size() == 7;
            if (every_v_coloured) {
                const std::vector<double> c = obj_numbers(path, {tok.begin() + 3, tok.end()}, 3, where);
                rgb.insert(rgb.end(), c.begin(), c.end());
            }
        } else if (tok[0] == "vt" || tok[0] == "vn") {
            ObjStream& st = tok[0] == "vt" ? uv : nrm;
            const std::vector<double> x = obj_numbers(path, tok, st.width, where);
            st.records.insert(st.records.end(), x.begin(), x.end());
        } else if (tok[0] == "f") {
            if (tok.size() != 4)
                fail(path, where + ": face " + std::to_string(raw.size()) + " has " + std::to_string(tok.size() - 1) +
                               " vertices, expected a triangle");
            std::array<long long, 3> f{}, t{}, n{};
            for (size_t k = 0; k < 3; ++k) {
                const std::string_view full = tok[k + 1];
                const size_t s1 = full.find('/'), s2 = s1 == std::string_view::npos ? s1 : full.find('/', s1 + 1);
                auto index = [&](std::string_view part, long long& out) {
                    if (part.empty()) return;  // "i//n": no texture coordinate
                    if (!parse_long(part, out) || out == 0) fail(path, where + ": bad vertex index '" + std::string(full) + "'");
                };
                if (!parse_long(full.substr(0, s1), f[k]) || f[k] == 0)
                    fail(path, where + ": bad vertex index '" + std::string(full) + "'");
                if (s1 != std::string_view::npos) index(full.substr(s1 + 1, s2 == std::string_view::npos ? s2 : s2 - s1 - 1), t[k]);
                if (s2 != std::string_view::npos) index(full.substr(s2 + 1), n[k]);
            }
            raw.push_back(f);
            nverts_at.push_back(m.points.size());
            uv.corner.push_back(t), uv.count_at.push_back(uv.records.size() / 2);
            nrm.corner.push_back(n), nrm.count_at.push_back(nrm.records.size() / 3);
        }
        // g, o, s, usemtl, mtllib, l: irrelevant to the check.
    }
    m.faces.resize(raw.size());
    for (size_t f = 0; f < raw.size(); ++f) {
        for (size_t k = 0; k < 3; ++k) {
            const long long idx = obj_index(raw[f][k], nverts_at[f]);
            if (idx < 0 || idx >= static_cast<long long>(m.points.size()))
                fail(path, "face " + std::to_string(f) + " references vertex " + std::to_string(raw[f][k]) + " but the file has only " +
                               std::to_string(m.points.size()) + " vertices");
            m.faces[f][k] = static_cast<uint32_t>(idx);
        }
    }
    if (m.faces.empty()) fail(path, "no faces");
    obj_stream_attribute(path, uv, m, m.attributes);
    obj_stream_attribute(path, nrm, m, m.attributes);
    if (every_v_coloured && !m.points.empty()) m.attributes.push_back({"COLOR_0", 3, std::move(rgb), 1e-9, 1e-9, "decimal text"});
    return m;
}

// ---------------------------------------------------------------------------------------------
// OFF

/// The attributes of OFF vertex rows "x y z [nx ny nz] [r g b [a]] [s t]". Colours: in a file
/// with an all-integer colour above 1 the all-integer colours are bytes (/255), else fractions.
std::vector<OutputAttribute> off_attributes(const std::string& path, const std::vector<std::vector<std::string_view>>& rows, bool nrm,
                                            bool col, bool tex) {
    OutputAttribute n{"NORMAL", 3, {}, 1e-9, 1e-9, "decimal text"}, c{"COLOR_0", 3, {}, 1e-9, 1e-9, "decimal text"},
        t{"TEXCOORD_0", 2, {}, 1e-9, 1e-9, "decimal text"};
    const size_t base = nrm ? 6 : 3, extra = tex ? 2 : 0;
    std::vector<std::vector<double>> colours;
    bool bytes = false;
    for (size_t v = 0; v < rows.size(); ++v) {
        const auto& row = rows[v];
        const size_t k = row.size() < base + extra ? 0 : row.size() - base - extra;
        if (row.size() < base + extra || (col ? k != 3 && k != 4 : k != 0))
            fail(path, "vertex " + std::to_string(v) + " has " + std::to_string(row.size()) + " numbers, which does not fit its header");
        std::vector<double> x(row.size());
        for (size_t i = 3; i < row.size(); ++i)
            if (!parse_double(row[i], x[i])) fail(path, "vertex " + std::to_string(v) + ": bad number '" + std::string(row[i]) + "'");
        if (nrm) n.values.insert(n.values.end(), x.begin() + 3, x.begin() + 6);
        if (tex) t.values.insert(t.values.end(), x.end() - 2, x.end());
        if (!col) continue;
        colours.emplace_back(x.begin() + static_cast<std::ptrdiff_t>(base), x.begin() + static_cast<std::ptrdiff_t>(base + k));
        const auto& rgb = colours.back();
        const bool whole = std::floor(rgb[0]) == rgb[0] && std::floor(rgb[1]) == rgb[1] && std::floor(rgb[2]) == rgb[2];
        bytes = bytes || (whole && std::max({rgb[0], rgb[1], rgb[2]}) > 1);
        c.components = std::max<uint32_t>(c.components, static_cast<uint32_t>(k));
    }
    for (const auto& rgb : colours) {
        const bool whole = std::floor(rgb[0]) == rgb[0] && std::floor(rgb[1]) == rgb[1] && std::floor(rgb[2]) == rgb[2];
        const double scale = bytes && whole ? 1.0 / 255 : 1.0;
        for (size_t i = 0; i < c.components; ++i)
            c.values.push_back(i < rgb.size() ? (i < 3 ? rgb[i] * scale : std::clamp(rgb[i] * scale, 0.0, 1.0)) : 1.0);
    }
    if (bytes) c.abs_tol = 0.5 / 255 + 1e-12, c.rel_tol = 0, c.storage = "8-bit";
    std::vector<OutputAttribute> out;
    if (nrm) out.push_back(std::move(n));
    if (col) out.push_back(std::move(c));
    if (tex) out.push_back(std::move(t));
    return out;
}

OutputMesh read_off(const std::string& path) {
    const std::string text = slurp(path);
    // Non-comment, non-blank lines.
    std::vector<std::vector<std::string_view>> rows;
    for (std::string_view line : split_lines(text)) {
        if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        auto tok = split_ws(line);
        if (!tok.empty()) rows.push_back(std::move(tok));
    }
    if (rows.empty()) fail(path, "empty file");
    size_t r = 0;
    auto& head = rows[0];
    const std::string_view magic = head[0];
    const bool tex = magic.substr(0, 2) == "ST";
    const std::string_view rest = magic.substr(tex ? 2 : 0);
    const bool col = rest.substr(0, 1) == "C", nrm = rest.substr(col ? 1 : 0) == "NOFF";
    if (rest.substr((col ? 1 : 0) + (nrm ? 1 : 0)) != "OFF") fail(path, "not an OFF file (header '" + std::string(magic) + "')");
    std::vector<std::string_view> counts(head.begin() + 1, head.end());
    ++r;
    if (counts.empty()) {
        if (r >= rows.size()) fail(path, "missing counts line");
        counts = rows[r++];
    }
    long long nv = 0, nf = 0;
    if (counts.size() < 2 || !parse_long(counts[0], nv) || !parse_long(counts[1], nf) || nv < 0 || nf < 0) fail(path, "bad counts line");
    if (static_cast<size_t>(nv + nf) > rows.size()) fail(path, "truncated file (fewer lines than the counts say)");
    OutputMesh m;
    m.points.resize(static_cast<size_t>(nv));
    for (size_t v = 0; v < m.points.size(); ++v, ++r) {
        if (r >= rows.size()) fail(path, "truncated at vertex " + std::to_string(v));
        if (rows[r].size() < 3) fail(path, "vertex " + std::to_string(v) + " needs 3 coordinates");
        for (size_t k = 0; k < 3; ++k)
            if (!parse_double(rows[r][k], m.points[v][k]))
                fail(path, "vertex " + std::to_string(v) + ": bad coordinate '" + std::string(rows[r][k]) + "'");
        check_point(path, v, m.points[v]);
    }
    if (tex || col || nrm)
        m.attributes = off_attributes(
            path, {rows.begin() + static_cast<std::ptrdiff_t>(r - m.points.size()), rows.begin() + static_cast<std::ptrdiff_t>(r)}, nrm,
            col, tex);
    m.faces.resize(static_cast<size_t>(nf));
    for (size_t f = 0; f < m.faces.size(); ++f, ++r) {
        if (r >= rows.size()) fail(path, "truncated at face " + std::to_string(f));
        long long k = 0;
        if (!parse_long(rows[r][0], k)) fail(path, "face " + std::to_string(f) + ": bad vertex count");
        if (k != 3) fail(path, "face " + std::to_string(f) + " has " + std::to_string(k) + " vertices, expected a triangle");
        if (rows[r].size() < 4) fail(path, "face " + std::to_string(f) + ": truncated");
        for (size_t j = 0; j < 3; ++j) {
            long long idx = 0;
            if (!parse_long(rows[r][j + 1], idx) || idx < 0 || idx > 0xffffffffLL)
                fail(path, "face " + std::to_string(f) + ": bad vertex index '" + std::string(rows[r][j + 1]) + "'");
            m.faces[f][j] = static_cast<uint32_t>(idx);
        }
    }
    check_indices(path, m);
    return m;
}

}  // namespace

OutputMesh read_output_mesh(const std::string& path) {
    const std::string ext = lower_extension(path);
    if (ext == "ply") return read_ply(path);
    if (ext == "obj") return read_obj(path);
    if (ext == "off") return read_off(path);
    if (ext == "glb" || ext == "gltf" || ext == "stl")
        fail(path, "a ." + ext + " result cannot be read back exactly (float32 positions" + (ext == "stl" ? ", no shared vertices" : "") +
                       "); use the .ply, .obj or .off result of the same run");
    fail(path, "cannot read a result with extension '" + ext + "' (expected .ply, .obj or .off)");
}

std::vector<uint32_t> read_index_file(const std::string& path) {
    const std::string text = slurp(path);
    std::vector<uint32_t> out;
    for (std::string_view tok : split_ws(text)) {
        long long v = 0;
        if (!parse_long(tok, v) || v < 0 || v > 0xffffffffLL)
            fail(path, "index " + std::to_string(out.size()) + ": bad token '" + std::string(tok) + "'");
        out.push_back(static_cast<uint32_t>(v));
    }
    return out;
}

std::vector<std::vector<uint32_t>> read_cycles_file(const std::string& path) {
    const std::string text = slurp(path);
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        fail(path, std::string("not valid JSON: ") + e.what());
    }
    if (!j.is_object() || !j.contains("cycles") || !j["cycles"].is_array()) fail(path, "expected an object with an array \"cycles\"");
    std::vector<std::vector<uint32_t>> cycles;
    for (size_t c = 0; c < j["cycles"].size(); ++c) {
        const auto& arr = j["cycles"][c];
        if (!arr.is_array()) fail(path, "cycle " + std::to_string(c) + " is not an array");
        std::vector<uint32_t> cyc;
        for (const auto& x : arr) {
            if (!x.is_number_unsigned() || x.get<uint64_t>() > 0xffffffffULL)
                fail(path, "cycle " + std::to_string(c) + ": entries must be face indices");
            cyc.push_back(static_cast<uint32_t>(x.get<uint64_t>()));
        }
        cycles.push_back(std::move(cyc));
    }
    return cycles;
}

}  // namespace singlestrip
