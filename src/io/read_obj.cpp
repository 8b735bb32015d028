// singlestrip — Wavefront OBJ reader.
//
// Contract. Line records; '#' starts a comment line. `v x y z` (anything after z — w, colours —
// is ignored) adds a vertex; `f r1 r2 r3 ...` adds a polygon whose corner references are
// "i", "i/t", "i//n" or "i/t/n" (1-based; negative: relative to the vertices so far; only the
// position i is read). A '#' after the corners ends the line; a '#' glued to a reference with
// more text after it is refused (a comment or more corners: the file is ambiguous). Every other
// record (vt, vn, g, o, s, l, p, usemtl, mtllib, ...) is skipped and named when the file has no
// faces. Faces may reference vertices defined later; indices are checked at the end. Errors
// name the line and the face (the file's `f` record number, 0-based).
#include <algorithm>
#include <cstring>
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
    void face(Line& l, const char* line_end);

    const std::string& path_;
    std::string_view d_;
    SoupBuilder out_;
    std::size_t line_ = 0;
    uint32_t faces_ = 0;
    std::vector<uint32_t> corners_;
    std::vector<Pending> pending_;
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
        else if (kw == "f")
            face(l, line_end);
        else if (skipped_.size() < 64 || skipped_.count(std::string(kw.substr(0, 20))))
            ++skipped_[std::string(kw.substr(0, 20))];
    }
    const std::size_t nv = out_.soup.points.size();
    for (const Pending& q : pending_)
        if (q.low < 0 || static_cast<std::size_t>(q.high) >= nv) {
            line_ = q.line;
            fail_line("face " + std::to_string(q.face) + " references vertex " + std::to_string(q.low < 0 ? q.low : q.high) +
                      " but the file has only " + std::to_string(nv) + " vertices");
        }
    std::string detail = "the file has " + std::to_string(nv) + " vertices and 0 faces";
    if (!skipped_.empty()) {
        detail += "; records not read:";
        for (const auto& [kw, n] : skipped_) detail += " '" + kw + "' (" + std::to_string(n) + (n == 1 ? " line)" : " lines)");
        detail += "; faces are read from 'f' records";
    }
    return out_.finish(detail);
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
}

/// The vertex number of one corner reference "i[/[t][/[n]]]" (t, n: integers), or false.
bool corner_index(std::string_view t, long long& i) {
    const std::size_t s1 = t.find('/');
    if (!parse_integer(t.substr(0, s1), i) || i == 0) return false;
    if (s1 == std::string_view::npos) return true;
    const std::string_view rest = t.substr(s1 + 1);
    const std::size_t s2 = rest.find('/');
    long long x = 0;
    const std::string_view tex = rest.substr(0, s2);
    if (!tex.empty() && !parse_integer(tex, x)) return false;
    if (s2 == std::string_view::npos) return !tex.empty();
    const std::string_view normal = rest.substr(s2 + 1);
    return !normal.empty() && parse_integer(normal, x);
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
        long long i = 0;
        if (!corner_index(t, i) || i < -2147483648LL || i > 2147483647LL) fail_line(face() + ": bad vertex reference " + quoted(t));
        const long long zero_based = i > 0 ? i - 1 : nv + i;
        if (zero_based < 0 || zero_based >= nv) {
            // Forward references are checked when every vertex is known.
            low = out_of_range ? std::min(low, zero_based) : zero_based;
            high = out_of_range ? std::max(high, zero_based) : zero_based;
            out_of_range = true;
        }
        corners_.push_back(static_cast<uint32_t>(zero_based));
    }
    if (corners_.size() < 3) fail_line(face() + " has only " + std::to_string(corners_.size()) + " vertices (at least 3 needed)");
    if (out_of_range) pending_.push_back({line_, faces_, low, high});
    out_.add_polygon(corners_.data(), corners_.size());
    ++faces_;
}

}  // namespace

TriangleSoup read_obj(const std::string& path, std::string_view d) {
    return ObjReader(path, d).run();
}

}  // namespace singlestrip::io_detail
