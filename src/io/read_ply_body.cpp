// singlestrip — PLY bodies (see read_ply.cpp for the contract). Both walk every element in
// header order, item by item; a list count is checked against the bytes left before its entries
// are read, so nothing is allocated from a count the data cannot hold.
#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "read_ply.hpp"

namespace singlestrip::io_detail::ply {
namespace {

[[noreturn]] void truncated(const std::string& path, const Element& e, uint64_t item) {
    fail(path, "truncated PLY file: element '" + e.name + "' declares " + std::to_string(e.count) + " items but the data ends at item " +
                   std::to_string(item));
}

/// Largest value of a narrow list count type (counts of 32 bits are bounded by the data instead).
long long count_max(Type t) {
    const std::size_t bits = 8 * size_of(t) - (is_signed(t) ? 1 : 0);
    return bits >= 63 ? INT64_MAX : (1LL << bits) - 1;
}

// ---- ASCII ----

class AsciiBody {
public:
    AsciiBody(const std::string& path, std::string_view d, const Header& h, Sink& sink)
        : path_(path), c_(d.substr(h.body)), h_(h), sink_(sink) {
        c_.line = h.body_line;
    }
    void run() {
        for (const Element& e : h_.elements) element(e);
    }

private:
    [[noreturn]] void bad(const Element& e, uint64_t i, const std::string& what, std::string_view tok) const {
        fail(path_,
             "line " + std::to_string(c_.line) + ": element '" + e.name + "' item " + std::to_string(i) + ": " + what + " " + quoted(tok));
    }
    std::size_t left() const { return static_cast<std::size_t>(c_.end - c_.p); }
    void element(const Element& e);
    void list(const Element& e, const Property& pr, uint64_t i);

    const std::string& path_;
    TextCursor c_;
    const Header& h_;
    Sink& sink_;
    std::vector<long long> entries_;
    std::vector<double> row_;
};

void AsciiBody::element(const Element& e) {
    if (e.count == 0) return;
    auto& pts = sink_.out().soup.points;
    // An item holds at least one token of one byte and a separator per property.
    if (e.kind == Kind::Vertices) pts.reserve(pts.size() + fit(left(), 2 * e.props.size(), e.count));
    if (e.kind != Kind::Other) sink_.out().reserve_triangles(fit(left(), 8, e.count));
    row_.assign(h_.slots, 0.0);
    for (uint64_t i = 0; i < e.count; ++i) {
        Point3 p{};
        for (const Property& pr : e.props) {
            if (pr.count != Type::None) {
                list(e, pr, i);
                continue;
            }
            const std::string_view t = c_.token();
            if (t.empty()) truncated(path_, e, i);
            long long n = 0;
            double x = 0;
            if (is_integral(pr.type) ? !parse_integer(t, n) : !parse_real(t, x)) bad(e, i, "cannot parse property '" + pr.name + "'", t);
            if (pr.role == Role::X) p[0] = x;
            if (pr.role == Role::Y) p[1] = x;
            if (pr.role == Role::Z) p[2] = x;
            if (pr.role == Role::Attribute) row_[pr.slot] = (is_integral(pr.type) ? static_cast<double>(n) : x) * pr.scale;
        }
        if (e.kind == Kind::Vertices) {
            pts.push_back(p);
            if (h_.slots) sink_.attributes(row_.data());
        }
    }
}

void AsciiBody::list(const Element& e, const Property& pr, uint64_t i) {
    const std::string_view t = c_.token();
    if (t.empty()) truncated(path_, e, i);
    long long n = 0;
    if (!parse_integer(t, n) || n < 0) bad(e, i, "bad count for list '" + pr.name + "'", t);
    if (n > count_max(pr.count))
        bad(e, i,
            "count of list '" + pr.name + "' out of range for its " + std::to_string(8 * size_of(pr.count)) + "-bit " +
                (is_signed(pr.count) ? "signed" : "unsigned") + " type:",
            t);
    const bool corners = pr.role == Role::Corners;
    if (corners && e.kind == Kind::Faces && n < 3)
        fail(path_, "line " + std::to_string(c_.line) + ": face " + std::to_string(i) + " has only " + std::to_string(n) +
                        " vertices (at least 3 needed)");
    // An entry is at least one byte and a separator.
    if (static_cast<unsigned long long>(n) > left() / 2 + 1) {
        fail(path_, "truncated PLY file: line " + std::to_string(c_.line) + ": element '" + e.name + "' item " + std::to_string(i) +
                        ": list '" + pr.name + "' declares more entries than the rest of the file can hold: " + quoted(t));
    }
    entries_.clear();
    for (long long k = 0; k < n; ++k) {
        const std::string_view v = c_.token();
        if (v.empty()) truncated(path_, e, i);
        long long x = 0;
        double y = 0;
        if (is_integral(pr.type) ? !parse_integer(v, x) : !parse_real(v, y))
            bad(e, i, "cannot parse an entry of list '" + pr.name + "'", v);
        if (corners) entries_.push_back(x);
    }
    if (!corners) return;
    const std::string where = "line " + std::to_string(c_.line) + ": ";
    if (e.kind == Kind::Faces)
        sink_.face(entries_.data(), entries_.size(), i, [&] { return where; });
    else
        sink_.strip(entries_.data(), entries_.size(), is_signed(pr.type) ? -1 : count_max(pr.type), i, where);
}

// ---- binary ----

template <class T>
T load(const char* p, bool swap) {
    using U = std::conditional_t<sizeof(T) == 1, uint8_t,
                                 std::conditional_t<sizeof(T) == 2, uint16_t, std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>>>;
    U u;
    std::memcpy(&u, p, sizeof u);
    if (swap) {
        if constexpr (sizeof(T) == 2) u = static_cast<U>(__builtin_bswap16(u));
        if constexpr (sizeof(T) == 4) u = __builtin_bswap32(u);
        if constexpr (sizeof(T) == 8) u = __builtin_bswap64(u);
    }
    return std::bit_cast<T>(u);
}

long long as_integer(Type t, const char* p, bool swap) {
    switch (t) {
        case Type::I8:
            return load<int8_t>(p, swap);
        case Type::U8:
            return load<uint8_t>(p, swap);
        case Type::I16:
            return load<int16_t>(p, swap);
        case Type::U16:
            return load<uint16_t>(p, swap);
        case Type::I32:
            return load<int32_t>(p, swap);
        case Type::U32:
            return load<uint32_t>(p, swap);
        default:
            return 0;
    }
}

double as_real(Type t, const char* p, bool swap) {
    return t == Type::F32 ? load<float>(p, swap) : load<double>(p, swap);
}

class BinaryBody {
public:
    BinaryBody(const std::string& path, std::string_view d, const Header& h, Sink& sink)
        : path_(path),
          p_(d.data() + h.body),
          end_(d.data() + d.size()),
          h_(h),
          sink_(sink),
          swap_((h.format == Format::BigEndian) == (std::endian::native == std::endian::little)) {}
    void run() {
        for (const Element& e : h_.elements) {
            bool lists = false;
            for (const Property& pr : e.props) lists = lists || pr.count != Type::None;
            if (lists)
                with_lists(e);
            else
                fixed(e);
        }
    }

private:
    std::size_t left() const { return static_cast<std::size_t>(end_ - p_); }
    void fixed(const Element& e);
    void attribute_row(const Element& e, const char* item, std::size_t vertex);
    void with_lists(const Element& e);
    bool fast_triangles(const Element& e);

    const std::string& path_;
    const char* p_;
    const char* end_;
    const Header& h_;
    Sink& sink_;
    bool swap_;
    std::vector<long long> entries_;
    std::vector<double> row_;
};

/// Elements of scalars only: one size check, then the coordinates of vertex items.
void BinaryBody::fixed(const Element& e) {
    if (e.count == 0) return;
    std::size_t record = 0;
    std::size_t offset[3] = {0, 0, 0};
    Type type[3] = {Type::None, Type::None, Type::None};
    for (const Property& pr : e.props) {
        if (pr.role == Role::X || pr.role == Role::Y || pr.role == Role::Z) {
            const auto k = static_cast<std::size_t>(pr.role) - static_cast<std::size_t>(Role::X);
            offset[k] = record;
            type[k] = pr.type;
        }
        record += size_of(pr.type);
    }
    if (e.count > left() / record) truncated(path_, e, left() / record);
    const auto n = static_cast<std::size_t>(e.count);
    if (e.kind == Kind::Vertices) {
        auto& pts = sink_.out().soup.points;
        const std::size_t first = pts.size();
        pts.resize(first + n);
        const bool floats = type[0] == Type::F32 && type[1] == Type::F32 && type[2] == Type::F32;
        for (std::size_t i = 0; i < n; ++i) {
            const char* item = p_ + i * record;
            Point3& q = pts[first + i];
            if (floats) {
                for (int k = 0; k < 3; ++k) q[k] = load<float>(item + offset[k], swap_);
            } else {
                for (int k = 0; k < 3; ++k) q[k] = as_real(type[k], item + offset[k], swap_);
            }
            if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
                fail(path_, "vertex " + std::to_string(first + i) + " has a non-finite coordinate (NaN or infinity)");
            if (h_.slots) attribute_row(e, item, first + i);
        }
    }
    p_ += n * record;
}

/// The attribute properties of one binary vertex item, handed to the sink.
void BinaryBody::attribute_row(const Element& e, const char* item, std::size_t vertex) {
    row_.resize(h_.slots);
    std::size_t at = 0;
    for (const Property& pr : e.props) {
        if (pr.role == Role::Attribute) {
            const double x =
                is_integral(pr.type) ? static_cast<double>(as_integer(pr.type, item + at, swap_)) : as_real(pr.type, item + at, swap_);
            if (!std::isfinite(x))
                fail(path_, "vertex " + std::to_string(vertex) + ": property '" + pr.name + "' is not finite (NaN or infinity)");
            row_[pr.slot] = x * pr.scale;
        }
        at += size_of(pr.type);
    }
    sink_.attributes(row_.data());
}

/// The common face layout (only a uchar-counted list of 32-bit indices), read without the
/// general property loop. False (nothing read) for any other layout.
bool BinaryBody::fast_triangles(const Element& e) {
    if (e.kind != Kind::Faces || e.props.size() != 1 || e.props[0].count != Type::U8) return false;
    const Type t = e.props[0].type;
    if (t != Type::I32 && t != Type::U32) return false;
    long long v[255];
    const unsigned long long nv = sink_.vertices();
    for (uint64_t i = 0; i < e.count; ++i) {
        if (left() < 1) truncated(path_, e, i);
        const std::size_t k = static_cast<unsigned char>(*p_);
        if (k * 4 > left() - 1)
            fail(path_, "truncated PLY file: element '" + e.name + "' item " + std::to_string(i) + ": list '" + e.props[0].name +
                            "' declares " + std::to_string(k) + " entries but only " + std::to_string((left() - 1) / 4) +
                            " fit in the rest of the file");
        ++p_;
        for (std::size_t j = 0; j < k; ++j, p_ += 4) v[j] = t == Type::I32 ? load<int32_t>(p_, swap_) : load<uint32_t>(p_, swap_);
        // Triangles, nearly every face of most files, skip the general polygon path.
        if (k == 3 && static_cast<unsigned long long>(v[0]) < nv && static_cast<unsigned long long>(v[1]) < nv &&
            static_cast<unsigned long long>(v[2]) < nv)
            sink_.out().add_triangle(static_cast<uint32_t>(v[0]), static_cast<uint32_t>(v[1]), static_cast<uint32_t>(v[2]));
        else
            sink_.face(v, k, i, [] { return std::string(); });
    }
    return true;
}

void BinaryBody::with_lists(const Element& e) {
    // A face item is at least a count and three entries: that bounds what may be reserved.
    if (e.kind != Kind::Other) sink_.out().reserve_triangles(fit(left(), 4, e.count));
    if (fast_triangles(e)) return;
    for (uint64_t i = 0; i < e.count; ++i) {
        for (const Property& pr : e.props) {
            if (pr.count == Type::None) {
                if (left() < size_of(pr.type)) truncated(path_, e, i);
                p_ += size_of(pr.type);
                continue;
            }
            if (left() < size_of(pr.count)) truncated(path_, e, i);
            const long long n = as_integer(pr.count, p_, swap_);
            p_ += size_of(pr.count);
            auto where = [&] { return "element '" + e.name + "' item " + std::to_string(i) + ": list '" + pr.name + "' declares "; };
            if (n < 0) fail(path_, "corrupt PLY file: " + where() + "a negative number of entries (" + std::to_string(n) + ")");
            const std::size_t size = size_of(pr.type);
            if (static_cast<unsigned long long>(n) > left() / size)
                fail(path_, "truncated PLY file: " + where() + std::to_string(n) + " entries but only " + std::to_string(left() / size) +
                                " fit in the rest of the file");
            if (pr.role != Role::Corners) {
                p_ += static_cast<std::size_t>(n) * size;
                continue;
            }
            entries_.resize(static_cast<std::size_t>(n));
            for (auto& x : entries_) {
                x = as_integer(pr.type, p_, swap_);
                p_ += size;
            }
            if (e.kind == Kind::Faces)
                sink_.face(entries_.data(), entries_.size(), i, [] { return std::string(); });
            else
                sink_.strip(entries_.data(), entries_.size(), is_signed(pr.type) ? -1 : count_max(pr.type), i, "");
        }
    }
}

}  // namespace

void read_ascii_body(const std::string& path, std::string_view d, const Header& h, Sink& sink) {
    AsciiBody(path, d, h, sink).run();
}
void read_binary_body(const std::string& path, std::string_view d, const Header& h, Sink& sink) {
    BinaryBody(path, d, h, sink).run();
}

}  // namespace singlestrip::io_detail::ply
