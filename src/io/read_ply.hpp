// singlestrip — PLY reader internals shared by read_ply.cpp (header, checks, faces and strips)
// and read_ply_body.cpp (the ASCII and binary bodies).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "read_common.hpp"

namespace singlestrip::io_detail::ply {

enum class Type : uint8_t { None, I8, U8, I16, U16, I32, U32, F32, F64 };

inline std::size_t size_of(Type t) {
    switch (t) {
        case Type::I8:
        case Type::U8:
            return 1;
        case Type::I16:
        case Type::U16:
            return 2;
        case Type::I32:
        case Type::U32:
        case Type::F32:
            return 4;
        case Type::F64:
            return 8;
        case Type::None:
            return 0;
    }
    return 0;
}
inline bool is_integral(Type t) {
    return t != Type::F32 && t != Type::F64;
}
inline bool is_signed(Type t) {
    return t == Type::I8 || t == Type::I16 || t == Type::I32;
}

/// What the reader does with a property.
enum class Role : uint8_t { Skip, X, Y, Z, Corners, Attribute };

struct Property {
    std::string name;
    std::string type_text;    // as written, for messages ("int", "list uchar float")
    Type type = Type::None;   // scalar type, or the list's entry type
    Type count = Type::None;  // None: a scalar
    Role role = Role::Skip;
    std::size_t slot = 0;  // Attribute: its place in the vertex's attribute row
    double scale = 1;      // Attribute: uchar/ushort colours to [0, 1]
};

/// What the reader does with an element's items.
enum class Kind : uint8_t { Other, Vertices, Faces, Strips };

struct Element {
    std::string name;
    unsigned long long count = 0;
    std::size_t line = 0;  // header line
    Kind kind = Kind::Other;
    std::vector<Property> props;
};

enum class Format { Ascii, LittleEndian, BigEndian };

struct Header {
    Format format = Format::Ascii;
    std::vector<Element> elements;
    std::size_t body = 0;             // offset of the first body byte
    std::size_t body_line = 0;        // its line (ASCII messages)
    unsigned long long vertices = 0;  // items of all vertex elements
    /// Vertex attributes (values empty): from the properties with Role::Attribute, whose slots
    /// run through the attributes' components in order.
    std::vector<VertexAttribute> attributes;
    std::size_t slots = 0;
};

/// Receives the items the body readers decode.
class Sink {
public:
    Sink(const std::string& path, SoupBuilder& out, unsigned long long vertices) : path_(path), out_(out), vertices_(vertices) {}
    /// A face's corners (as read, signed); `where` names it in messages ("line 7: face 3").
    template <class Where>
    void face(const long long* v, std::size_t k, uint64_t item, const Where& where) {
        if (k < 3)
            fail(path_, where() + "face " + std::to_string(item) + " has only " + std::to_string(k) + " vertices (at least 3 needed)");
        corners_.resize(k);
        for (std::size_t i = 0; i < k; ++i) {
            if (v[i] < 0 || static_cast<unsigned long long>(v[i]) >= vertices_) bad_index(where(), "face " + std::to_string(item), v[i]);
            corners_[i] = static_cast<uint32_t>(v[i]);
        }
        out_.add_polygon(corners_.data(), k);
    }
    /// A strip's entries, -1 (or the unsigned type's largest value, `restart`) between strips.
    void strip(const long long* v, std::size_t k, long long restart, uint64_t item, const std::string& where);
    [[noreturn]] void bad_index(const std::string& where, const std::string& what, long long index) const;
    /// One vertex's attribute row (Header::slots values, in slot order).
    void attributes(const double* row) {
        std::size_t s = 0;
        for (VertexAttribute& a : out_.soup.attributes)
            for (uint32_t c = 0; c < a.components; ++c) a.values.push_back(row[s++]);
    }
    SoupBuilder& out() { return out_; }
    unsigned long long vertices() const { return vertices_; }
    const std::string& path() const { return path_; }

private:
    const std::string& path_;
    SoupBuilder& out_;
    unsigned long long vertices_;
    std::vector<uint32_t> corners_;
};

void read_ascii_body(const std::string& path, std::string_view d, const Header& h, Sink& sink);
void read_binary_body(const std::string& path, std::string_view d, const Header& h, Sink& sink);

}  // namespace singlestrip::io_detail::ply
