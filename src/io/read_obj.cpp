// singlestrip — Wavefront OBJ reader.
//
// Contract. Line records; '#' starts a comment line. `v x y z` (anything after z — w, colours —
// is ignored) adds a vertex; `vt u [v [w]]` a texture coordinate (u, v kept); `vn x y z` a
// normal; `f r1 r2 r3 ...` adds a polygon whose corner references are "i", "i/t", "i//n" or
// "i/t/n" (1-based; negative: relative to the records so far). A '#' after the corners ends the
// line; a '#' glued to a reference with more text after it is refused (a comment or more
// corners: the file is ambiguous). Every other record (g, o, s, l, p, usemtl, mtllib, ...) is
// skipped and named when the file has no faces. Faces may reference records defined later;
// indices are checked at the end. Errors name the line and the face (the file's `f` record
// number, 0-based).
// Attributes. When EVERY face corner has a `t` (an `n`), the soup gets TEXCOORD_0 (NORMAL): a
// vertex is then a position with its texture coordinate and normal, vertex i < (v records) is
// position i with the attributes of its first corner, and each further combination at a
// position is a new vertex appended after them, in order of first appearance; the seam between
// two combinations is a boundary for the strip. A stream only some corners have is not kept.
// Vertex colours "v x y z r g b" (every vertex with exactly three numbers after z) become
// COLOR_0, copied to a position's seam vertices.
#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "read_common.hpp"

namespace singlestrip::io_detail {
namespace {

/// A face with corners whose vertex was not defined (yet) when the face was read: the lowest
/// and the highest such (0-based) index.
struct Pending {
    std::size_t line;
    uint32_t face;
    long long low, high;
};

constexpr uint32_t kAbsent = 0xffffffffu;
constexpr long long kNoRef = std::numeric_limits<long long>::min();  // a corner without vt (vn)

/// One attribute stream (vt or vn): its records, and per triangle corner the record used while
/// every corner so far has one.
struct Stream {
    Stream(const char* r, const char* w, std::size_t k) : record(r), what(w), width(k) {}
    const char* record;  // "vt" or "vn", for messages
    const char* what;    // "texture coordinate" or "normal"
    std::size_t width;   // numbers kept per record
    std::vector<double> values;
    std::vector<uint32_t> corner;
    bool complete = true;
    std::vector<Pending> pending;
    std::size_t records() const { return values.size() / width; }
};

class ObjReader {
public:
    ObjReader(const std::string& path, std::string_view d) : path_(path), d_(d), out_(path) {}
    TriangleSoup run();

private:
    struct Line {
        const char* p;
        const char* end;
        std::string_view token() {
            while (p != end && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\f' || *p == '\v')) ++p;
            const char* b = p;
            while (p != end && !is_space(*p)) ++p;
            return {b, static_cast<std::size_t>(p - b)};
        }
    };

    [[noreturn]] void fail_line(const std::string& what) const { fail(path_, "line " + std::to_string(line_) + ": " + what); }
    void vertex(Line& l);
    void vertex_colour(Line& l);
    void attribute_record(Line& l, Stream& st, std::size_t required);
    void face(Line& l, const char* line_end);
    bool corner_reference(std::string_view t, long long& i, long long* ref);
    void stream_corners(Stream& st, std::size_t k);
    void check_pending(const std::vector<Pending>& pending, std::size_t count, const std::string& what, const std::string& records);
    void attach_attributes(TriangleSoup& soup);

    const std::string& path_;
    std::string_view d_;
    SoupBuilder out_;
    std::size_t line_ = 0;
    uint32_t faces_ = 0;
    std::vector<uint32_t> corners_;
    std::array<std::vector<long long>, 2> refs_;  // vt and vn of the current face's corners (or kNoRef)
    std::array<Stream, 2> streams_{Stream{"vt", "texture coordinate", 2}, Stream{"vn", "normal", 3}};
    std::vector<Pending> pending_;
    std::vector<double> colours_;  // 3 per vertex while every vertex so far has a colour
    bool all_coloured_ = true;
    std::map<std::string, std::size_t> skipped_;  // record keyword -> lines, for the "no faces" message
};

TriangleSoup ObjReader::run() {
    const char* p = d_.data();
    const char* end = p + d_.size();
    // Counting the v and f lines first costs one memchr pass and saves the reallocations (time,
    // and up to twice the memory) of growing the arrays.
    std::size_t v_lines = 0, f_lines = 0;
    for (const char* q = p; q != end;) {
        while (q != end && (*q == ' ' || *q == '\t')) ++q;
        if (end - q >= 2 && (q[1] == ' ' || q[1] == '\t')) {
            v_lines += q[0] == 'v';
            f_lines += q[0] == 'f';
        }
        const char* nl = static_cast<const char*>(std::memchr(q, '\n', static_cast<std::size_t>(end - q)));
        q = nl ? nl + 1 : end;
    }
    out_.soup.points.reserve(v_lines);
    out_.reserve_triangles(f_lines);
    while (p != end) {
        ++line_;
        const char* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
        const char* line_end = nl ? nl : end;
        Line l{p, line_end};
        p = nl ? nl + 1 : end;
        const std::string_view kw = l.token();
        if (kw.empty() || kw[0] == '#') continue;
        if (kw == "v")
            vertex(l);
        else if (kw == "vt")
            attribute_record(l, streams_[0], 1);
        else if (kw == "vn")
            attribute_record(l, streams_[1], 3);
        else if (kw == "f")
            face(l, line_end);
        else if (skipped_.size() < 64 || skipped_.count(std::string(kw.substr(0, 20))))
            ++skipped_[std::string(kw.substr(0, 20))];
    }
    const std::size_t nv = out_.soup.points.size();
    check_pending(pending_, nv, "vertex", "vertices");
    for (const Stream& st : streams_) check_pending(st.pending, st.records(), st.what, std::string("'") + st.record + "' records");
    std::string detail = "the file has " + std::to_string(nv) + " vertices and 0 faces";
    if (!skipped_.empty()) {
        detail += "; records not read:";
        for (const auto& [kw, n] : skipped_) detail += " '" + kw + "' (" + std::to_string(n) + (n == 1 ? " line)" : " lines)");
        detail += "; faces are read from 'f' records";
    }
    TriangleSoup soup = out_.finish(detail);
    attach_attributes(soup);
    return soup;
}

void ObjReader::check_pending(const std::vector<Pending>& pending, std::size_t count, const std::string& what, const std::string& records) {
    for (const Pending& q : pending)
        if (q.low < 0 || static_cast<std::size_t>(q.high) >= count) {
            line_ = q.line;
            fail_line("face " + std::to_string(q.face) + " references " + what + " " + std::to_string(q.low < 0 ? q.low : q.high) +
                      " but the file has only " + std::to_string(count) + " " + records);
        }
}

/// `vt u [v [w]]` (at least `required` numbers) or `vn x y z`: the first `width` numbers kept.
void ObjReader::attribute_record(Line& l, Stream& st, std::size_t required) {
    const std::string item = std::string("'") + st.record + "' record " + std::to_string(st.records());
    std::size_t k = 0;
    for (std::string_view t = l.token(); !t.empty() && t[0] != '#' && k < 3; t = l.token(), ++k) {
        double x = 0;
        if (!parse_real(t, x)) fail_line(item + " " + coordinate_problem(t));
        if (k < st.width) st.values.push_back(x);
    }
    if (k < required) fail_line(item + " has " + std::to_string(k) + " numbers (" + std::to_string(required) + " needed)");
    for (; k < st.width; ++k) st.values.push_back(0.0);  // vt's v defaults to 0
}

void ObjReader::vertex(Line& l) {
    Point3 p{};
    for (int k = 0; k < 3; ++k) {
        const std::string_view t = l.token();
        if (t.empty() || t[0] == '#') fail_line("vertex " + std::to_string(out_.soup.points.size()) + " has fewer than 3 coordinates");
        if (!parse_real(t, p[static_cast<std::size_t>(k)]))
            fail_line("vertex " + std::to_string(out_.soup.points.size()) + " " + coordinate_problem(t));
    }
    if (out_.soup.points.size() >= 0xfffffffeu) fail_line("too many vertices (more than 2^32-2)");
    out_.soup.points.push_back(p);
    vertex_colour(l);
}

/// The common "v x y z r g b" extension: kept when every vertex has exactly three more numbers;
/// anything else after z (w, text) is ignored as before.
void ObjReader::vertex_colour(Line& l) {
    if (!all_coloured_) return;
    double c[3];
    std::size_t k = 0;
    for (std::string_view t = l.token(); !t.empty() && t[0] != '#'; t = l.token(), ++k)
        if (k >= 3 || !parse_real(t, c[k])) {
            k = 0;
            break;
        }
    if (k != 3) {
        all_coloured_ = false;
        colours_ = {};
        return;
    }
    colours_.insert(colours_.end(), c, c + 3);
}

/// One corner reference "i[/[t][/[n]]]": the numbers as written (0 where absent), or false.
bool corner_index(std::string_view t, long long& i, long long& tex_ref, long long& normal_ref) {
    tex_ref = normal_ref = 0;
    const std::size_t s1 = t.find('/');
    if (!parse_integer(t.substr(0, s1), i) || i == 0) return false;
    if (s1 == std::string_view::npos) return true;
    const std::string_view rest = t.substr(s1 + 1);
    const std::size_t s2 = rest.find('/');
    const std::string_view tex = rest.substr(0, s2);
    if (!tex.empty() && (!parse_integer(tex, tex_ref) || tex_ref == 0)) return false;
    if (s2 == std::string_view::npos) return !tex.empty();
    const std::string_view normal = rest.substr(s2 + 1);
    return !normal.empty() && parse_integer(normal, normal_ref) && normal_ref != 0;
}

/// A written reference (1-based, negative: relative to `count` records so far) 0-based.
long long zero_based(long long ref, long long count) {
    return ref > 0 ? ref - 1 : count + ref;
}

void ObjReader::face(Line& l, const char* line_end) {
    auto face = [&] { return "face " + std::to_string(faces_); };
    corners_.clear();
    const long long nv = static_cast<long long>(out_.soup.points.size());
    long long low = 0, high = 0;
    bool out_of_range = false;
    for (std::string_view t = l.token(); !t.empty(); t = l.token()) {
        if (t[0] == '#') break;
        if (const std::size_t hash = t.find('#'); hash != std::string_view::npos) {
            Line rest{l.p, line_end};
            if (!rest.token().empty())
                fail_line(face() + ": '#' right after a vertex reference with more text after it (a comment needs a space before '#')");
            t = t.substr(0, hash);
            l.p = line_end;
        }
        long long i = 0, ref[2] = {0, 0};
        auto in_int = [](long long x) { return x >= -2147483648LL && x <= 2147483647LL; };
        if (!corner_index(t, i, ref[0], ref[1]) || !in_int(i) || !in_int(ref[0]) || !in_int(ref[1]))
            fail_line(face() + ": bad vertex reference " + quoted(t));
        const long long v = zero_based(i, nv);
        if (v < 0 || v >= nv) {
            // Forward references are checked when every vertex is known.
            low = out_of_range ? std::min(low, v) : v;
            high = out_of_range ? std::max(high, v) : v;
            out_of_range = true;
        }
        corners_.push_back(static_cast<uint32_t>(v));
        for (std::size_t s = 0; s < 2; ++s)
            refs_[s].push_back(ref[s] == 0 ? kNoRef : zero_based(ref[s], static_cast<long long>(streams_[s].records())));
    }
    if (corners_.size() < 3) fail_line(face() + " has only " + std::to_string(corners_.size()) + " vertices (at least 3 needed)");
    if (out_of_range) pending_.push_back({line_, faces_, low, high});
    out_.add_polygon(corners_.data(), corners_.size());
    for (Stream& st : streams_) stream_corners(st, corners_.size());
    ++faces_;
}

/// Records the current face's references into `st` (fan order, as add_polygon), or gives the
/// stream up at the first corner without one.
void ObjReader::stream_corners(Stream& st, std::size_t k) {
    std::vector<long long>& r = refs_[static_cast<std::size_t>(&st - streams_.data())];
    const long long count = static_cast<long long>(st.records());
    for (long long x : r)
        if (x == kNoRef) {
            st.complete = false;
            st.corner = {};
        } else if (x < 0 || x >= count) {
            st.pending.push_back({line_, faces_, x, x});  // forward references are fine; checked at the end
        }
    if (st.complete)
        for (std::size_t i = 1; i + 1 < k; ++i)
            for (std::size_t c : {std::size_t{0}, i, i + 1}) st.corner.push_back(static_cast<uint32_t>(r[c]));
    r.clear();
}

using AttributeKey = std::array<uint32_t, 2>;  // the vt and vn records of a vertex (kept streams)

/// Re-points every corner to the vertex of its (position, records) combination, appending a
/// copy of the position for each combination after a position's first; returns each vertex's
/// records. \pre every kept stream has a record per corner.
std::vector<AttributeKey> split_at_seams(TriangleSoup& soup, const std::vector<const Stream*>& kept, const std::string& path,
                                         std::vector<uint32_t>& origin) {
    std::vector<AttributeKey> key(soup.points.size(), AttributeKey{kAbsent, kAbsent});
    std::vector<char> used(soup.points.size(), 0);
    std::map<std::pair<uint32_t, AttributeKey>, uint32_t> extra;  // seams: a few percent of the vertices
    for (std::size_t corner = 0; corner < 3 * soup.triangles.size(); ++corner) {
        uint32_t& v = soup.triangles[corner / 3][corner % 3];
        AttributeKey k{kAbsent, kAbsent};
        for (std::size_t s = 0; s < kept.size(); ++s) k[s] = kept[s]->corner[corner];
        if (!used[v]) {
            used[v] = 1;
            key[v] = k;
        } else if (key[v] != k) {
            const auto [it, added] = extra.try_emplace({v, k}, static_cast<uint32_t>(soup.points.size()));
            if (added) {
                if (soup.points.size() >= 0xfffffffeu) fail(path, "too many vertices with their attributes (more than 2^32-2)");
                soup.points.push_back(soup.points[v]);
                key.push_back(k);
                origin.push_back(v);
            }
            v = it->second;
        }
    }
    return key;
}

/// Makes a vertex of every (position, vt, vn) combination the faces use (see the contract).
void ObjReader::attach_attributes(TriangleSoup& soup) {
    std::vector<const Stream*> kept;
    for (const Stream& st : streams_)
        if (st.complete && !st.corner.empty()) kept.push_back(&st);
    const std::size_t n_file = soup.points.size();
    std::vector<uint32_t> origin(n_file);  // the file vertex of each vertex
    for (uint32_t v = 0; v < origin.size(); ++v) origin[v] = v;
    const std::vector<AttributeKey> key = kept.empty() ? std::vector<AttributeKey>() : split_at_seams(soup, kept, path_, origin);
    for (std::size_t s = 0; s < kept.size(); ++s) {
        const Stream& st = *kept[s];
        VertexAttribute a{st.width == 2 ? "TEXCOORD_0" : "NORMAL",
                          static_cast<uint32_t>(st.width),
                          st.width == 3 ? AttributeBlend::Unit : AttributeBlend::Linear,
                          {}};
        a.values.reserve(key.size() * st.width);
        for (const AttributeKey& k : key)  // vertices no face uses get zeros
            for (std::size_t c = 0; c < st.width; ++c) a.values.push_back(k[s] == kAbsent ? 0.0 : st.values[k[s] * st.width + c]);
        soup.attributes.push_back(std::move(a));
    }
    if (!all_coloured_ || colours_.size() != 3 * n_file) return;
    VertexAttribute colour{"COLOR_0", 3, AttributeBlend::Linear, {}};
    for (uint32_t v : origin) colour.values.insert(colour.values.end(), &colours_[3 * v], &colours_[3 * v] + 3);
    soup.attributes.push_back(std::move(colour));
}

}  // namespace

TriangleSoup read_obj(const std::string& path, std::string_view d) {
    return ObjReader(path, d).run();
}

}  // namespace singlestrip::io_detail
