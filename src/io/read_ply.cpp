// singlestrip — PLY reader (ASCII, binary little and big endian): the header, what is read from
// it, and the decoding of triangle strips. The bodies are walked in read_ply_body.cpp.
//
// Contract. Header: "ply", "format ascii|binary_little_endian|binary_big_endian <version>",
// "comment"/"obj_info" lines, "element <name> <count>", "property <type> <name>" and
// "property list <count type> <entry type> <name>" (types char uchar short ushort int uint float
// double, or int8 ... float64), "end_header". Vertices come from the element 'vertex' (or
// 'vertices'): its first x, y and z properties, which must be float or double; every other
// property is skipped. Faces come from 'face' (or 'faces'): the first 'vertex_indices' list of
// an integer type (else 'vertex_index'), fan-triangulated; and from 'tristrips': a list of
// strips separated by -1, each decoded with alternating winding, (a,b,c), (c,b,d)... as
// triangles (v_i, v_i+1, v_i+2) for even i and (v_i+1, v_i, v_i+2) for odd i, triangles with a
// repeated vertex skipped (each strip triangle is a polygon of its own). Every other element is
// skipped and, when the file has no faces, named. Data after the last element is ignored.
// Errors name the header line, or the element and item (and line, ASCII); face numbers are the
// item numbers of the face element.
#include "read_ply.hpp"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

namespace singlestrip::io_detail::ply {
namespace {

Type type_named(std::string_view t) {
    if (t == "char" || t == "int8") return Type::I8;
    if (t == "uchar" || t == "uint8") return Type::U8;
    if (t == "short" || t == "int16") return Type::I16;
    if (t == "ushort" || t == "uint16") return Type::U16;
    if (t == "int" || t == "int32") return Type::I32;
    if (t == "uint" || t == "uint32") return Type::U32;
    if (t == "float" || t == "float32") return Type::F32;
    if (t == "double" || t == "float64") return Type::F64;
    return Type::None;
}

/// Tokens of one header line.
std::vector<std::string_view> split(std::string_view line) {
    std::vector<std::string_view> t;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_space(line[i])) ++i;
        const std::size_t b = i;
        while (i < line.size() && !is_space(line[i])) ++i;
        if (i > b) t.push_back(line.substr(b, i - b));
    }
    return t;
}

class HeaderParser {
public:
    HeaderParser(const std::string& path, std::string_view d) : path_(path), d_(d) {}
    Header run();

private:
    [[noreturn]] void bad(const std::string& what) const {
        fail(path_, "malformed PLY header: line " + std::to_string(line_) + ": " + what);
    }
    void property(const std::vector<std::string_view>& t);
    void choose_roles();
    void choose_attributes(Element& e);

    const std::string& path_;
    std::string_view d_;
    std::size_t line_ = 0;
    Header h_;
};

Header HeaderParser::run() {
    std::size_t p = 0;
    bool format = false;
    for (;;) {
        if (p >= d_.size()) fail(path_, "malformed PLY header: no 'end_header' line");
        const std::size_t nl = d_.find('\n', p);
        const std::size_t end = nl == std::string_view::npos ? d_.size() : nl;
        const std::vector<std::string_view> t = split(d_.substr(p, end - p));
        p = end + 1;
        if (++line_ == 1) {
            if (t.size() != 1 || t[0] != "ply") fail(path_, "not a PLY file (it does not start with 'ply')");
            continue;
        }
        if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
        if (t[0] == "end_header") break;
        if (t[0] == "format") {
            if (t.size() != 3) bad("'format' needs a format and a version");
            if (t[1] == "ascii")
                h_.format = Format::Ascii;
            else if (t[1] == "binary_little_endian")
                h_.format = Format::LittleEndian;
            else if (t[1] == "binary_big_endian")
                h_.format = Format::BigEndian;
            else
                bad("unknown format " + quoted(t[1]) + " (ascii, binary_little_endian or binary_big_endian)");
            format = true;
        } else if (t[0] == "element") {
            long long count = 0;
            if (t.size() != 3) bad("'element' needs a name and a count");
            if (!parse_integer(t[2], count) || count < 0) bad("bad count " + quoted(t[2]) + " for element '" + std::string(t[1]) + "'");
            h_.elements.push_back({std::string(t[1]), static_cast<unsigned long long>(count), line_, Kind::Other, {}});
        } else if (t[0] == "property") {
            property(t);
        } else {
            bad("unknown keyword " + quoted(t[0]));
        }
    }
    if (!format) fail(path_, "malformed PLY header: no 'format' line");
    h_.body = std::min(p, d_.size());
    h_.body_line = line_ + 1;
    choose_roles();
    return h_;
}

void HeaderParser::property(const std::vector<std::string_view>& t) {
    if (h_.elements.empty()) bad("'property' before any 'element'");
    Property pr;
    Element& e = h_.elements.back();
    if (t.size() >= 2 && t[1] == "list") {
        if (t.size() != 5) bad("'property list' needs a count type, an entry type and a name");
        pr.name = t[4];
        pr.count = type_named(t[2]);
        pr.type = type_named(t[3]);
        pr.type_text = "list " + std::string(t[2]) + " " + std::string(t[3]);
        if (pr.count == Type::None || !is_integral(pr.count))
            bad("list '" + pr.name + "' of element '" + e.name + "' has count type " + quoted(t[2]) + " (an integer type is needed)");
        if (pr.type == Type::None) bad("list '" + pr.name + "' of element '" + e.name + "' has unknown entry type " + quoted(t[3]));
    } else {
        if (t.size() != 3) bad("'property' needs a type and a name");
        pr.name = t[2];
        pr.type = type_named(t[1]);
        pr.type_text = t[1];
        if (pr.type == Type::None) bad("property '" + pr.name + "' of element '" + e.name + "' has unknown type " + quoted(t[1]));
    }
    e.props.push_back(std::move(pr));
}

/// Decides what is read from which element and property; refuses what cannot be read.
void HeaderParser::choose_roles() {
    for (Element& e : h_.elements) {
        const std::string where = "line " + std::to_string(e.line) + ": element '" + e.name + "'";
        if (e.count > 0 && e.props.empty())
            fail(path_, "malformed PLY header: " + where + " declares " + std::to_string(e.count) + " items but has no properties");
        auto first = [&](const char* name) -> Property* {
            for (Property& pr : e.props)
                if (pr.name == name) return &pr;
            return nullptr;
        };
        if (e.name == "vertex" || e.name == "vertices") {
            e.kind = Kind::Vertices;
            h_.vertices += e.count;
            const Role roles[3] = {Role::X, Role::Y, Role::Z};
            int k = 0;
            for (const char* c : {"x", "y", "z"}) {
                Property* pr = first(c);
                if (!pr)
                    fail(path_, "unsupported PLY file: " + where + " has no property '" + c +
                                    "' (vertex coordinates x, y, z must be float or double)");
                if (pr->count != Type::None || is_integral(pr->type))
                    fail(path_, "unsupported PLY file: line " + std::to_string(e.line) + ": property '" + c + "' of element '" + e.name +
                                    "' has type '" + pr->type_text + "' (coordinates must be float or double)");
                pr->role = roles[k++];
            }
            if (h_.vertices == e.count) choose_attributes(e);  // several vertex elements: positions only
        } else if (e.name == "face" || e.name == "faces" || e.name == "tristrips") {
            e.kind = e.name == "tristrips" ? Kind::Strips : Kind::Faces;
            auto int_list = [](const Property* pr) { return pr && pr->count != Type::None && is_integral(pr->type); };
            Property* list = int_list(first("vertex_indices")) ? first("vertex_indices") : first("vertex_index");
            if (!int_list(list))
                fail(path_,
                     "unsupported PLY file: " + where +
                         " has no 'vertex_indices' (or 'vertex_index') list of an integer type (char, uchar, short, ushort, int or uint)");
            list->role = Role::Corners;
        }
    }
    std::size_t vertex_elements = 0;
    for (const Element& e : h_.elements) vertex_elements += e.kind == Kind::Vertices;
    if (vertex_elements > 1) {  // attributes are kept for one vertex element only
        h_.attributes.clear();
        h_.slots = 0;
        for (Element& e : h_.elements)
            for (Property& pr : e.props)
                if (pr.role == Role::Attribute) pr.role = Role::Skip;
    }
    if (h_.vertices >= 0xffffffffull)
        fail(path_, "too many vertices (the header declares " + std::to_string(h_.vertices) + "; at most 2^32-2)");
}

/// The groups of vertex properties that make one attribute, in the names writers use.
struct Group {
    const char* name;
    AttributeBlend blend;
    std::vector<std::vector<const char*>> spellings;  // alternatives, each a full list of properties
};

const std::vector<Group>& groups() {
    static const std::vector<Group> g{
        {"NORMAL", AttributeBlend::Unit, {{"nx", "ny", "nz"}}},
        {"COLOR_0", AttributeBlend::Linear, {{"red", "green", "blue", "alpha"}, {"red", "green", "blue"}}},
        {"TEXCOORD_0", AttributeBlend::Linear, {{"s", "t"}, {"u", "v"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}},
    };
    return g;
}

/// Every scalar vertex property besides x, y, z becomes (part of) an attribute: normals,
/// colours (integers scaled to [0, 1]), texture coordinates, and any other scalar under its own
/// name (integers copied from the nearest corner, not averaged: they may be ids).
void HeaderParser::choose_attributes(Element& e) {
    auto scalar = [&](const char* name) -> Property* {
        for (Property& pr : e.props)
            if (pr.name == name) return pr.role == Role::Skip && pr.count == Type::None ? &pr : nullptr;
        return nullptr;
    };
    auto add = [&](Property& pr, VertexAttribute& a) {
        pr.role = Role::Attribute;
        pr.slot = h_.slots++;
        if (a.name == "COLOR_0" && pr.type == Type::U8) pr.scale = 1.0 / 255;
        if (a.name == "COLOR_0" && pr.type == Type::U16) pr.scale = 1.0 / 65535;
        ++a.components;
    };
    for (const Group& g : groups())
        for (const auto& names : g.spellings) {
            std::vector<Property*> ps;
            for (const char* n : names) ps.push_back(scalar(n));
            if (std::find(ps.begin(), ps.end(), nullptr) != ps.end()) continue;
            VertexAttribute a{g.name, 0, g.blend, {}};
            for (Property* pr : ps) add(*pr, a);
            h_.attributes.push_back(std::move(a));
            break;
        }
    for (Property& pr : e.props)
        if (pr.role == Role::Skip && pr.count == Type::None) {
            VertexAttribute a{pr.name, 0, is_integral(pr.type) ? AttributeBlend::Nearest : AttributeBlend::Linear, {}};
            add(pr, a);
            h_.attributes.push_back(std::move(a));
        }
}

}  // namespace

void Sink::bad_index(const std::string& where, const std::string& what, long long index) const {
    fail(path_, where + what + " references vertex " + std::to_string(index) + " but the file has only " + std::to_string(vertices_) +
                    " vertices");
}

void Sink::strip(const long long* v, std::size_t k, long long restart, uint64_t item, const std::string& where) {
    const std::string what = "tristrips item " + std::to_string(item);
    std::size_t start = 0;  // first entry of the current strip
    for (std::size_t i = 0; i < k; ++i) {
        if (v[i] == restart) {
            start = i + 1;
            continue;
        }
        if (v[i] < 0 || static_cast<unsigned long long>(v[i]) >= vertices_) bad_index(where, what + " entry " + std::to_string(i), v[i]);
        if (i < start + 2) continue;
        // Odd triangles of a strip are wound the other way round: (v_i-1, v_i-2, v_i).
        const bool odd = (i - start) % 2 == 1;
        const auto a = static_cast<uint32_t>(v[odd ? i - 1 : i - 2]), b = static_cast<uint32_t>(v[odd ? i - 2 : i - 1]),
                   c = static_cast<uint32_t>(v[i]);
        if (a != b && b != c && a != c) out_.add_triangle(a, b, c);
    }
}

}  // namespace singlestrip::io_detail::ply

namespace singlestrip::io_detail {

TriangleSoup read_ply(const std::string& path, std::string_view d) {
    using namespace ply;
    const Header h = HeaderParser(path, d).run();
    SoupBuilder out(path);
    out.soup.attributes = h.attributes;
    Sink sink(path, out, h.vertices);
    if (h.format == Format::Ascii)
        read_ascii_body(path, d, h, sink);
    else
        read_binary_body(path, d, h, sink);
    // A vertex element with list properties gives no attribute rows (its items are skipped).
    const auto& attrs = out.soup.attributes;
    if (std::any_of(attrs.begin(), attrs.end(), [&](const auto& a) { return a.values.size() != out.soup.points.size() * a.components; }))
        out.soup.attributes.clear();
    if (!out.soup.triangles.empty()) return out.finish("");
    // No faces: say which elements there were, so that the user sees what was not understood.
    bool declared = false;
    std::vector<std::string> others;
    for (const Element& e : h.elements) {
        declared = declared || e.kind == Kind::Faces || e.kind == Kind::Strips;
        if (e.kind == Kind::Other) others.push_back(e.name);
    }
    if (!others.empty() && !declared) {
        std::string names = "'" + others[0] + "'";
        for (std::size_t i = 1; i < others.size(); ++i) names += ", '" + others[i] + "'";
        return out.finish("the PLY header declares " + std::to_string(h.vertices) + " vertices; " +
                          (others.size() == 1 ? "element " : "elements ") + names + (others.size() == 1 ? " is" : " are") +
                          " not understood; faces are read from 'face' or 'tristrips'");
    }
    return out.finish("the PLY header declares " + std::to_string(h.vertices) + " vertices and 0 faces");
}

}  // namespace singlestrip::io_detail
