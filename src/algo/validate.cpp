// Structural diagnosis of a triangle soup: one pass over edges grouped by their vertex pair
// (CSR by smaller vertex, no hash maps), union-find for components and vertex fans, and BFS
// orientation propagation over manifold edges.
#include "singlestrip/validate.hpp"

#include <algorithm>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/soup_edges.hpp"
#include "core/topology.hpp"
#include "face_order.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/repair.hpp"

namespace singlestrip {
namespace {

constexpr std::size_t kMaxPerKind = 10;  // listed problems per kind; the rest are counted

struct UnionFind {
    std::vector<uint32_t> parent;
    explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    uint32_t find(uint32_t x) {
        while (parent[x] != x) {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        return x;
    }
    void unite(uint32_t a, uint32_t b) {
        a = find(a);
        b = find(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
};

std::string edge_name(uint32_t a, uint32_t b) {
    return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

/// Collects problems of one kind, keeping the first kMaxPerKind messages.
struct ProblemList {
    explicit ProblemList(std::string k) : kind(std::move(k)) {}
    std::string kind;
    std::vector<std::string> messages;
    std::size_t total = 0;
    void add(std::string m) {
        if (messages.size() < kMaxPerKind) messages.push_back(std::move(m));
        ++total;
    }
    void emit(std::vector<SoupProblem>& out) const {
        for (const auto& m : messages) out.push_back({kind, m});
        if (total > messages.size())
            out.push_back({kind, "... and " + std::to_string(total - messages.size()) + " more " + kind + " problems"});
    }
};

/// Everything diagnose_soup, mesh_info and prepare_soup need, computed once.
struct Analysis {
    const TriangleSoup& soup;
    const std::vector<uint32_t>* origin_;
    std::size_t nf = 0, nv = 0;
    std::vector<char> usable;    // face in range and with three distinct vertices
    std::vector<uint32_t> twin;  // half-edge 3f+k -> its partner on a 2-face edge, else kNone
    std::vector<uint32_t> comp;  // edge-connected component root per usable face
    std::vector<int8_t> flip;    // orientation BFS result (1 = flip to be consistent)
    ProblemList out_of_range{"index_out_of_range"}, repeated{"repeated_vertex"}, duplicate{"duplicate_face"}, nm_edge{"non_manifold_edge"},
        nm_vertex{"non_manifold_vertex"}, inconsistent{"inconsistent_orientation"}, non_orientable{"non_orientable"};
    uint64_t edges = 0, boundary_edges = 0, non_manifold_edges = 0, referenced = 0, boundary_loops = 0;
    std::vector<uint64_t> component_sizes;
    bool orientable = true, oriented = true;

    /// origin: the given face of each face when the soup was reordered (orientation ties and
    /// component numbers then follow the given order).
    explicit Analysis(const TriangleSoup& s, const std::vector<uint32_t>* origin = nullptr)
        : soup(s), origin_(origin), nf(s.triangles.size()), nv(s.points.size()) {
        run();
    }

    /// Face number for messages: the triangle, and for a file with polygons the file's polygon
    /// (face numbers count triangles after fan triangulation; the user knows the file's faces).
    std::string fid(std::size_t f) const {
        const auto& sp = soup.source_polygon;
        const bool polygons = sp.size() == nf && nf > 0 && sp.back() != nf - 1;
        return std::to_string(f) + (polygons ? " (polygon " + std::to_string(sp[f]) + " of the file)" : std::string());
    }

    uint32_t from(uint32_t h) const { return soup.triangles[h / 3][h % 3]; }
    uint32_t to(uint32_t h) const { return soup.triangles[h / 3][(h % 3 + 1) % 3]; }

    void run() {
        usable.assign(nf, 1);
        std::vector<char> used(nv, 0);
        for (std::size_t f = 0; f < nf; ++f) {
            const auto& t = soup.triangles[f];
            for (uint32_t v : t)
                if (v >= nv) {
                    out_of_range.add("face " + fid(f) + " references vertex " + std::to_string(v) + " but there are only " +
                                     std::to_string(nv) + " vertices");
                    usable[f] = 0;
                    break;
                }
            if (!usable[f]) continue;
            for (uint32_t v : t) used[v] = 1;
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
                repeated.add("face " + fid(f) + " (" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) +
                             ") repeats a vertex");
                usable[f] = 0;
            }
        }
        referenced = static_cast<uint64_t>(std::count(used.begin(), used.end(), 1));
        group_edges();
        find_fans();
        orient_bfs();
    }

    // Usable half-edges grouped by undirected edge (soup_edges.hpp), each edge examined once.
    void group_edges() {
        // The grouping first: its sort needs 28 bytes a face for a moment, before the arrays
        // below exist; it is freed (14 bytes a face) before the per-face counts (the peak).
        std::optional<SoupEdges> grouped(std::in_place, soup.triangles, nv, &usable);
        twin.reserve(Mesh::reserved_halfedges(nf));  // handed on to the mesh (PreparedSoup::twin)
        twin.assign(3 * nf, kNone);
        UnionFind faces(nf);
        corners_ = std::make_unique<UnionFind>(3 * nf);
        UnionFind bverts(nv);
        std::vector<char> on_boundary(nv, 0);
        grouped->for_each_edge([&](const SoupEdges::Edge& e) { on_edge(e, faces, bverts, on_boundary); });
        grouped.reset();
        comp.assign(nf, kNone);
        std::vector<uint32_t> size_of_root(nf, 0);  // face ids are uint32_t throughout
        for (std::size_t f = 0; f < nf; ++f)
            if (usable[f]) {
                comp[f] = faces.find(static_cast<uint32_t>(f));
                ++size_of_root[comp[f]];
            }
        for (uint64_t s : size_of_root)
            if (s) component_sizes.push_back(s);
        std::sort(component_sizes.rbegin(), component_sizes.rend());
        for (std::size_t v = 0; v < nv; ++v)
            if (on_boundary[v] && bverts.find(static_cast<uint32_t>(v)) == v) ++boundary_loops;
    }

    uint32_t corner_at(uint32_t h, uint32_t v) const { return from(h) == v ? h : 3 * (h / 3) + (h % 3 + 1) % 3; }

    using Range = SoupEdges::Iterator;

    void on_edge(const SoupEdges::Edge& e, UnionFind& faces, UnionFind& bverts, std::vector<char>& on_boundary) {
        ++edges;
        const uint32_t lo = e.lo, hi = e.hi;
        const Range b = e.first;
        if (e.kind != EdgeKind::boundary) report_duplicates(lo, hi, b, e.last);
        for (auto i = b + 1; i < e.last; ++i) {
            faces.unite(*b / 3, *i / 3);
            corners_->unite(corner_at(*b, lo), corner_at(*i, lo));
            corners_->unite(corner_at(*b, hi), corner_at(*i, hi));
        }
        switch (e.kind) {
            case EdgeKind::boundary:
                ++boundary_edges;
                bverts.unite(lo, hi);
                on_boundary[lo] = on_boundary[hi] = 1;
                return;
            case EdgeKind::inconsistent:
                oriented = false;
                inconsistent.add(edge_name(lo, hi) + ": faces " + fid(b[0] / 3) + " and " + fid(b[1] / 3) + " both run from " +
                                 std::to_string(from(b[0])) + " to " + std::to_string(to(b[0])) + " (inconsistent orientation)");
                [[fallthrough]];
            case EdgeKind::manifold:
                SoupEdges::pair(e, twin);
                return;
            case EdgeKind::non_manifold: {
                ++non_manifold_edges;
                std::string fs;
                for (auto i = b; i < e.last; ++i) fs += (i > b ? ", " : "") + fid(*i / 3);
                nm_edge.add(edge_name(lo, hi) + " is shared by " + std::to_string(e.num_halfedges()) + " faces (" + fs +
                            "); at most 2 are allowed");
                return;
            }
        }
    }

    uint32_t third(uint32_t h) const { return soup.triangles[h / 3][(h % 3 + 2) % 3]; }

    // Duplicate faces share all three edges; each set is reported once, at the edge of its two
    // smallest vertices (lo, hi): the faces there whose third vertex is above hi, grouped by it.
    // Edges come in (lo, hi) order and groups in third-vertex order, so the report is ordered by
    // sorted vertex triple, faces ascending, without sorting the faces.
    void report_duplicates(uint32_t lo, uint32_t hi, Range b, Range e) {
        // Two faces (nearly every edge): no duplicate unless they share the third vertex too. Saves
        // the list below, a heap allocation per edge.
        if (e - b == 2 && (third(b[0]) != third(b[1]) || third(b[0]) <= hi)) return;
        std::vector<std::pair<uint32_t, uint32_t>> by_third;  // (third vertex, face), usually 2 entries
        for (auto i = b; i != e; ++i)
            if (third(*i) > hi) by_third.emplace_back(third(*i), *i / 3);
        if (by_third.size() < 2) return;
        std::sort(by_third.begin(), by_third.end());
        for (std::size_t i = 0; i < by_third.size();) {
            std::size_t j = i + 1;
            while (j < by_third.size() && by_third[j].first == by_third[i].first) ++j;
            if (j - i > 1) {
                std::string faces;
                for (std::size_t k = i; k < j; ++k) faces += (k > i ? ", " : "") + fid(by_third[k].second);
                duplicate.add("faces " + faces + " are duplicates (same vertices " + std::to_string(lo) + ", " + std::to_string(hi) + ", " +
                              std::to_string(by_third[i].first) + ")");
            }
            i = j;
        }
    }

    // A vertex is manifold when all its corners are joined through edges at it into one fan.
    // Corners are only ever joined with corners at the same vertex, so each union-find set lies
    // at one vertex and the number of fans at v is the number of set roots among its corners.
    void find_fans() {
        std::vector<uint32_t> fans(nv, 0);
        for (std::size_t f = 0; f < nf; ++f)
            if (usable[f])
                for (uint32_t k = 0; k < 3; ++k) {
                    const auto c = static_cast<uint32_t>(3 * f + k);
                    if (corners_->find(c) == c) ++fans[from(c)];
                }
        corners_.reset();
        for (std::size_t v = 0; v < nv; ++v)
            if (fans[v] > 1)
                nm_vertex.add("vertex " + std::to_string(v) + " is where " + std::to_string(fans[v]) +
                              " separate fans of faces meet (non-manifold vertex)");
    }

    // BFS from the lowest-numbered face of each component; flip[g] = flip[f] xor (same direction).
    // Then each component keeps the orientation of the majority of its faces (ties: of its
    // lowest face), so --orient never turns most of a mesh inside out.
    void orient_bfs() {
        flip.assign(nf, -1);
        std::vector<uint32_t> queue;
        for (std::size_t s = 0; s < nf; ++s) {
            if (!usable[s] || flip[s] >= 0) continue;
            flip[s] = 0;
            queue.assign(1, static_cast<uint32_t>(s));
            bool conflict = false;
            for (std::size_t qi = 0; qi < queue.size(); ++qi) {
                const uint32_t f = queue[qi];
                for (uint32_t k = 0; k < 3; ++k) {
                    const uint32_t h = 3 * f + k, t = twin[h];
                    if (t == kNone) continue;
                    const uint32_t g = t / 3;
                    const int8_t want = static_cast<int8_t>(flip[f] ^ (from(h) == from(t) ? 1 : 0));
                    if (flip[g] < 0) {
                        flip[g] = want;
                        queue.push_back(g);
                    } else if (flip[g] != want && !conflict) {
                        conflict = true;
                        orientable = false;
                        non_orientable.add("the surface containing face " + fid(s) +
                                           " is not orientable (Moebius-like): orientations propagated from face " + fid(s) +
                                           " disagree across " + edge_name(std::min(from(h), to(h)), std::max(from(h), to(h))) +
                                           " between faces " + fid(f) + " and " + fid(g));
                    }
                }
            }
            std::size_t flips = 0;
            for (uint32_t f : queue) flips += flip[f] == 1 ? 1 : 0;
            if (2 * flips > queue.size() || (2 * flips == queue.size() && flip[given_lowest(queue)] == 1))
                for (uint32_t f : queue) flip[f] = static_cast<int8_t>(1 - flip[f]);
        }
        if (!orientable) oriented = false;
    }

    /// The face of `faces` that comes first in the given order (faces[0] unless reordered).
    uint32_t given_lowest(const std::vector<uint32_t>& faces) const {
        if (!origin_) return faces[0];
        return *std::min_element(faces.begin(), faces.end(), [&](uint32_t a, uint32_t b) { return (*origin_)[a] < (*origin_)[b]; });
    }

    /// After the faces were flipped by `flip` (orientable soup only).
    void mark_consistently_oriented() {
        inconsistent = ProblemList{"inconsistent_orientation"};
        oriented = true;
    }

    std::size_t total_problems() const {
        std::size_t n = nf == 0 ? 1 : 0;
        for (const ProblemList* l : {&out_of_range, &repeated, &duplicate, &nm_edge, &nm_vertex, &inconsistent, &non_orientable})
            n += l->total;
        return n;
    }

    std::vector<SoupProblem> problems() const {
        std::vector<SoupProblem> out;
        if (nf == 0) out.push_back({"no_faces", "the mesh has no faces"});
        out_of_range.emit(out);
        repeated.emit(out);
        duplicate.emit(out);
        nm_edge.emit(out);
        nm_vertex.emit(out);
        inconsistent.emit(out);
        non_orientable.emit(out);
        return out;
    }

    std::unique_ptr<UnionFind> corners_;
};

/// " (fix: ...)" naming the option that repairs the kinds of problem in `ps` (docs/repair.md).
std::string fix_hint(const std::vector<SoupProblem>& ps) {
    static const std::vector<std::pair<std::string, std::string>> actions = {
        {"index_out_of_range", "drops faces with an index out of range"},
        {"repeated_vertex", "drops faces that repeat a vertex"},
        {"duplicate_face", "drops duplicate faces"},
        {"non_manifold_edge", "cuts non-manifold edges and vertices apart"},
        {"non_manifold_vertex", "cuts non-manifold edges and vertices apart"},
        {"non_orientable", "cuts a non-orientable surface into an orientable piece"},
        {"inconsistent_orientation", "re-orients the faces"}};
    auto present = [&](const std::string& kind) {
        return std::any_of(ps.begin(), ps.end(), [&](const SoupProblem& p) { return p.kind == kind; });
    };
    std::vector<std::string> said;
    for (const auto& [kind, action] : actions)
        if (present(kind) && std::find(said.begin(), said.end(), action) == said.end()) said.push_back(action);
    if (said.empty()) return {};
    if (said.size() == 1 && present("inconsistent_orientation")) return " (fix: --orient or --repair re-orients the faces)";
    std::string hint = " (fix: --repair ";
    for (std::size_t i = 0; i < said.size(); ++i) hint += (i == 0 ? "" : i + 1 == said.size() ? " and " : ", ") + said[i];
    return hint + ")";
}

/// "<file>: p1; p2; ... (and N more problems ...) (fix: ...)"; `total` counts problems beyond the listed ones.
std::string join_problems(const std::vector<SoupProblem>& ps, std::size_t total, const std::string& filename) {
    constexpr std::size_t kShown = 5;
    std::string msg = filename + ": ";
    std::size_t shown = 0;
    for (const auto& p : ps) {
        if (shown == kShown) break;
        if (p.message.rfind("... and ", 0) == 0) continue;  // a cap marker, counted in `total`
        msg += (shown ? "; " : "") + p.message;
        ++shown;
    }
    if (total > shown) msg += " (and " + std::to_string(total - shown) + " more problems; run 'singlestrip info' for all)";
    return msg + fix_hint(ps);
}

/// Reverses every face with flip[f] == 1; returns how many.
long long apply_flips(TriangleSoup& soup, const std::vector<int8_t>& flip) {
    long long flipped = 0;
    for (std::size_t f = 0; f < soup.triangles.size(); ++f)
        if (flip[f] == 1) {
            std::swap(soup.triangles[f][1], soup.triangles[f][2]);
            ++flipped;
        }
    return flipped;
}

/// The pairing after the faces with flip[f] == 1 were reversed ((a,b,c) -> (a,c,b) turns the
/// half-edges 0, 1, 2 of the face into 2, 1, 0). In place, O(F).
std::vector<uint32_t> flipped_twins(std::vector<uint32_t> twin, const std::vector<int8_t>* flip) {
    if (!flip) return twin;
    auto moved = [&](uint32_t h) { return h != kNone && (*flip)[h / 3] == 1 ? h - h % 3 + 2 - h % 3 : h; };
    for (uint32_t& t : twin) t = moved(t);
    for (std::size_t f = 0; f < flip->size(); ++f)
        if ((*flip)[f] == 1) std::swap(twin[3 * f], twin[3 * f + 2]);
    return twin;
}

/// Components numbered 0.. in the order of their lowest face (of the given order when the
/// soup was reordered); unusable faces get kNone.
std::vector<uint32_t> number_components(const Analysis& a, uint32_t* count) {
    std::vector<uint32_t> id(a.nf, kNone), of_root(a.nf, kNone);
    uint32_t next = 0;
    auto visit = [&](std::size_t f) {
        if (a.comp[f] == kNone) return;
        if (of_root[a.comp[f]] == kNone) of_root[a.comp[f]] = next++;
        id[f] = of_root[a.comp[f]];
    };
    if (a.origin_) {
        std::vector<uint32_t> at(a.nf);  // given face -> its face here
        for (std::size_t f = 0; f < a.nf; ++f) at[(*a.origin_)[f]] = static_cast<uint32_t>(f);
        for (uint32_t f : at) visit(f);
    } else {
        for (std::size_t f = 0; f < a.nf; ++f) visit(f);
    }
    *count = next;
    return id;
}

/// The faces of `soup` put in `order` (order[i]: the face that goes to position i), or back.
void permute_faces(TriangleSoup& soup, const std::vector<uint32_t>& order, bool back) {
    auto apply = [&](auto& a) {
        if (a.empty()) return;
        std::remove_reference_t<decltype(a)> b(a.size());
        for (size_t i = 0; i < order.size(); ++i) (back ? b[order[i]] : b[i]) = a[back ? i : order[i]];
        a = std::move(b);
    };
    apply(soup.triangles);
    apply(soup.source_polygon);
}

}  // namespace

std::vector<SoupProblem> diagnose_soup(const TriangleSoup& soup) {
    return Analysis(soup).problems();
}

void validate_soup(const TriangleSoup& soup, const std::string& filename_for_messages) {
    Analysis a(soup);
    auto ps = a.problems();
    if (!ps.empty()) throw InputError(join_problems(ps, a.total_problems(), filename_for_messages));
}

long long orient_soup(TriangleSoup& soup) {
    std::vector<int8_t> flip;
    {
        Analysis a(soup);
        if (!a.orientable) return -1;
        flip = std::move(a.flip);
    }
    return apply_flips(soup, flip);
}

PreparedSoup prepare_soup_components(TriangleSoup soup, const PrepareOptions& opt, const std::string& filename_for_messages) {
    PreparedSoup out;
    if (opt.locality) out.face_origin = locality_order(soup);
    const bool reordered = !out.face_origin.empty();
    if (reordered) permute_faces(soup, out.face_origin, false);
    if (reordered && opt.vertex_locality) out.vertex_origin = locality_vertex_order(soup);
    if (!out.vertex_origin.empty()) permute_vertices(soup, out.vertex_origin, false);
    // One analysis serves every step: flipping faces by the BFS result changes nothing the
    // analysis found except the orientation findings, which it makes consistent (every 2-face
    // edge then has flip[f] xor flip[g] == same-direction, so it runs opposite ways), and
    // leaves the components as they were. A non-orientable soup is left as is and reported
    // with everything else.
    Analysis a(soup, reordered ? &out.face_origin : nullptr);
    const bool orient = opt.orient && a.orientable && !a.oriented;
    if (orient) a.mark_consistently_oriented();
    if (a.total_problems() > 0) {
        if (reordered) {  // a refusal names faces and vertices as given: analyse the given soup again
            if (!out.vertex_origin.empty()) permute_vertices(soup, out.vertex_origin, true);
            permute_faces(soup, out.face_origin, true);
            return prepare_soup_components(std::move(soup), PrepareOptions{opt.orient, false, false}, filename_for_messages);
        }
        throw InputError(join_problems(a.problems(), a.total_problems(), filename_for_messages));
    }
    if (orient) apply_flips(soup, a.flip);
    out.component = number_components(a, &out.num_components);
    out.twin = flipped_twins(std::move(a.twin), orient ? &a.flip : nullptr);
    out.soup = std::move(soup);
    return out;
}

TriangleSoup prepare_soup(TriangleSoup soup, const PrepareOptions& opt, const std::string& filename_for_messages) {
    return prepare_soup_components(std::move(soup), opt, filename_for_messages).soup;
}

std::vector<uint32_t> face_components(const TriangleSoup& soup, uint32_t* count) {
    uint32_t n = 0;
    std::vector<uint32_t> id = number_components(Analysis(soup), &n);
    if (count) *count = n;
    return id;
}

uint64_t unwelded_vertices(const TriangleSoup& soup) {
    const std::vector<uint32_t> rep = weld_map(soup);
    std::vector<char> seen(soup.points.size(), 0);
    uint64_t n = 0;
    for (const Triangle& t : soup.triangles)
        for (uint32_t v : t)
            if (v < rep.size() && rep[v] != v && !seen[v]) {
                seen[v] = 1;
                ++n;
            }
    return n;
}

MeshInfo mesh_info(const TriangleSoup& soup) {
    Analysis a(soup);
    MeshInfo info;
    info.vertices = soup.points.size();
    info.referenced_vertices = a.referenced;
    info.faces = soup.triangles.size();
    if (soup.source_polygon.empty()) {
        info.polygons = info.faces;
    } else {
        std::vector<uint32_t> sp = soup.source_polygon;
        std::sort(sp.begin(), sp.end());
        info.polygons = static_cast<uint64_t>(std::unique(sp.begin(), sp.end()) - sp.begin());
    }
    info.edges = a.edges;
    info.boundary_edges = a.boundary_edges;
    info.non_manifold_edges = a.non_manifold_edges;
    info.components = a.component_sizes.size();
    info.component_sizes = a.component_sizes;
    info.boundary_loops = a.boundary_loops;
    info.euler_characteristic = euler_characteristic(a.referenced, a.edges, info.faces);
    info.orientable = a.orientable;
    info.oriented = a.oriented;
    info.problems = a.problems();
    info.unwelded_vertices = unwelded_vertices(soup);
    // Genus by chi = 2c - 2g - b, meaningful for a manifold orientable surface.
    info.genus_valid = a.orientable && a.non_manifold_edges == 0 && a.nm_vertex.total == 0 && info.components >= 1 &&
                       a.out_of_range.total == 0 && a.repeated.total == 0;
    if (info.genus_valid) info.genus = genus_from_euler(info.euler_characteristic, info.boundary_loops, info.components);
    return info;
}

}  // namespace singlestrip
