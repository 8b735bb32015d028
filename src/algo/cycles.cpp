// singlestrip — fundamental cycles by steepest ascent over the strip order (paper §4).
#include "singlestrip/cycles.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>
#include <utility>

#include "core/face_sides.hpp"
#include "core/id_vector.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/tree_cotree.hpp"
#include "singlestrip/vec3.hpp"

namespace singlestrip {

namespace {

/// Thrown by FaceSearch when its searches together have visited more faces than their budget.
struct SearchBudgetSpent {};
/// The budget: visits per face, per cycle (2g + h - 1), and at least (compute_fundamental_cycles()).
constexpr uint64_t kSearchPerFace = 16, kSearchPerCycle = 4096, kSearchFloor = 65536;
/// Past F + kSearchFloor visits, the searches give up early when the visits per cycle so far,
/// times the cycles, exceed this many budgets (corridors: 10-56; every other mesh measured: at
/// most 2.3, cheese.off).
constexpr uint64_t kSearchProjection = 8;
/// From this many faces a strip that starts inside a mesh with boundary is replayed from the
/// boundary (choose_nested_reordered()) before classes are computed: holes1000 at 4M faces
/// 1.03 -> 0.48 s and 598 -> 461 MB with the same cycles; on head.off (small) the classes' choice
/// is half as long (47 faces against 99).
constexpr uint32_t kReorderFaces = uint32_t{1} << 19;

/// Breadth-first searches over faces with arrays allocated once and reset by a stamp: a search
/// costs the faces it visits, not O(F) (there is one or more per fundamental triangle).
class FaceSearch {
public:
    /// `budget`: faces all searches together may visit before path() throws SearchBudgetSpent;
    /// `cycles`: the cycles they are for (next_cycle() checks the pace).
    FaceSearch(const Mesh& mesh, uint64_t budget, uint64_t cycles)
        : mesh_(mesh), stamp_(mesh.num_faces(), 0), parent_(mesh.num_faces(), kNone), budget_(budget), initial_(budget), cycles_(cycles) {}

    /// Called before the searches for each further cycle: throws SearchBudgetSpent when, at the
    /// pace so far, all the cycles would spend the budget many times over (on corridors between
    /// long holes the first cycle's searches alone visit 1.5 F faces: the budget then goes on
    /// the first dozen cycles, a third of the time `--cycles` took before the fallback).
    void next_cycle() {
        const uint64_t used = initial_ - budget_;
        if (done_ > 0 && used > mesh_.num_faces() + kSearchFloor && used / done_ * cycles_ > kSearchProjection * initial_)
            throw SearchBudgetSpent{};
        ++done_;
    }

    /// Shortest chain of edge-adjacent faces from `from` to `to` (both included) avoiding `avoid`;
    /// with `time`, only through faces whose time is greater than `after`. Empty if there is none.
    std::vector<FaceId> path(FaceId from, FaceId to, FaceId avoid, const IdSpan<FaceId, uint32_t>* time = nullptr, uint32_t after = 0) {
        if (++current_ == 0) {  // stamps wrapped: forget them all once
            stamp_.assign(stamp_.size(), 0);
            current_ = 1;
        }
        queue_.assign(1, from);
        visit(from, from);
        for (size_t head = 0; head < queue_.size() && !seen(to); ++head) {
            const FaceId f = queue_[head];
            for (const HalfedgeId h : sides(f)) {
                const FaceId g = mesh_.neighbor(h);
                if (!g.valid() || g == avoid || seen(g)) continue;
                if (time && ((*time)[g] == kNone || (*time)[g] <= after)) continue;
                if (budget_-- == 0) throw SearchBudgetSpent{};
                visit(g, f);
                queue_.push_back(g);
            }
        }
        if (!seen(to)) return {};
        std::vector<FaceId> chain;
        for (FaceId f = to; f != from; f = parent_[f]) chain.push_back(f);
        chain.push_back(from);
        std::reverse(chain.begin(), chain.end());
        return chain;
    }

private:
    [[nodiscard]] bool seen(FaceId f) const { return stamp_[f] == current_; }
    void visit(FaceId f, FaceId parent) {
        stamp_[f] = current_;
        parent_[f] = parent;
    }
    const Mesh& mesh_;
    IdVector<FaceId, uint32_t> stamp_;
    IdVector<FaceId, FaceId> parent_;
    std::vector<FaceId> queue_;
    uint32_t current_ = 0;
    uint64_t budget_;
    const uint64_t initial_, cycles_;
    uint64_t done_ = 0;  ///< cycles whose searches have started
};

/// A basis of the classes kept so far, in echelon form: rows_[c] is a class whose lowest set bit
/// is c. Reducing a class touches only the words from its lowest bit on.
class Z2Basis {
public:
    explicit Z2Basis(size_t dim) : rows_(dim) {}
    /// Adds v if it is independent of the rows; false if it reduces to zero.
    bool insert(std::vector<uint64_t> v) {
        for (size_t w = 0; w < v.size(); ++w)
            while (v[w] != 0) {
                const size_t c = 64 * w + static_cast<size_t>(std::countr_zero(v[w]));
                if (c >= rows_.size()) return false;  // no such bit: the classifier's bits are < dim
                if (rows_[c].empty()) {
                    rows_[c] = std::move(v);
                    return true;
                }
                for (size_t k = w; k < v.size(); ++k) v[k] ^= rows_[c][k];
            }
        return false;
    }

private:
    std::vector<std::vector<uint64_t>> rows_;
};

/// Output faces (strip positions) and points, read from the output arrays or, without copying
/// them, from the split mesh and its strip order.
struct ArraysFaces {
    const StripArrays& a;
    [[nodiscard]] Triangle face(uint32_t f) const { return a.faces[f]; }
    [[nodiscard]] const Point3& point(uint32_t v) const { return a.points[v]; }
};
struct MeshFaces {
    const Mesh& mesh;
    const std::vector<uint32_t>& order;
    [[nodiscard]] Triangle face(uint32_t f) const {
        const FaceId g(order[f]);
        return {mesh.from(Mesh::halfedge(g, 0)).idx(), mesh.from(Mesh::halfedge(g, 1)).idx(), mesh.from(Mesh::halfedge(g, 2)).idx()};
    }
    [[nodiscard]] const Point3& point(uint32_t v) const { return mesh.position(VertexId(v)); }
};

template <class Faces>
Point3 centroid(const Faces& a, uint32_t f) {
    const Triangle t = a.face(f);
    return vec3::centroid(a.point(t[0]), a.point(t[1]), a.point(t[2]));
}

/// Midpoint of the edge shared by faces f and g; false if they share fewer than two vertices.
template <class Faces>
bool shared_midpoint(const Faces& a, uint32_t f, uint32_t g, Point3& out) {
    uint32_t common[2];
    int n = 0;
    const Triangle tf = a.face(f), tg = a.face(g);
    for (uint32_t v : tf)
        if (std::find(tg.begin(), tg.end(), v) != tg.end() && n < 2) common[n++] = v;
    if (n < 2) return false;
    out = vec3::midpoint(a.point(common[0]), a.point(common[1]));
    return true;
}

template <class Faces>
std::vector<Point3> polyline_of(const Faces& faces, const std::vector<uint32_t>& cycle) {
    std::vector<Point3> pts;
    const size_t n = cycle.size();
    pts.reserve(2 * n);
    for (size_t i = 0; i < n; ++i) {
        pts.push_back(centroid(faces, cycle[i]));
        if (n < 2) break;
        Point3 m;
        if (shared_midpoint(faces, cycle[i], cycle[(i + 1) % n], m)) pts.push_back(m);
    }
    return pts;
}

template <class Faces>
double length_of(const Faces& faces, const std::vector<uint32_t>& cycle) {
    if (cycle.size() < 2) return 0.0;
    const std::vector<Point3> pts = polyline_of(faces, cycle);
    double len = 0.0;
    for (size_t i = 0; i < pts.size(); ++i) len += vec3::distance(pts[i], pts[(i + 1) % pts.size()]);
    return len;
}

/// What the candidate rules read: the mesh, the strip order both ways, and the take times
/// (the strip positions when the fundamental triangles were replayed).
struct StripView {
    const Mesh& mesh;
    const std::vector<uint32_t>& order;  ///< position -> face (StripResult::order)
    IdSpan<FaceId, uint32_t> pos;        ///< face -> position
    IdSpan<FaceId, uint32_t> take_time;
    /// Positions seam and seam + 1 hold faces that need not be neighbours (reordered(); kNone in
    /// a strip): no strip segment runs across it.
    uint32_t seam = kNone;
    /// The face at strip position p.
    [[nodiscard]] FaceId at(uint32_t p) const { return FaceId(order[p]); }
};

/// A candidate cycle through a fundamental triangle, as MESH faces. A strip segment (T and
/// order[lo..hi]) stays a range until it is classified: it can be as long as the strip, and
/// most candidates are never looked at.
struct Candidate {
    CycleSource source = CycleSource::StripSegment;
    std::vector<FaceId> faces;
    bool lazy = false;
    FaceId t = kNone;
    uint32_t lo = 0, hi = 0;  ///< strip positions
    [[nodiscard]] size_t size() const { return lazy ? size_t{hi} - lo + 2 : faces.size(); }
    const std::vector<FaceId>& materialize(const std::vector<uint32_t>& order) {
        if (!lazy) return faces;
        faces.reserve(size());
        faces.push_back(t);
        for (uint32_t k = lo; k <= hi; ++k) faces.push_back(FaceId(order[k]));
        lazy = false;
        return faces;
    }
};

/// T's distinct neighbours, largest position first (D = [0], S = [1], Algorithm 3).
std::vector<FaceId> neighbors_by_position(const StripView& v, FaceId t, uint32_t p) {
    std::vector<FaceId> nb;
    for (const HalfedgeId h : sides(t)) {
        const FaceId g = v.mesh.neighbor(h);
        if (g.valid() && std::find(nb.begin(), nb.end(), g) == nb.end()) nb.push_back(g);
    }
    if (nb.size() < 2)
        throw InternalError("fundamental cycles: fundamental triangle at position " + std::to_string(p) + " has fewer than two neighbours");
    std::sort(nb.begin(), nb.end(), [&](FaceId a, FaceId b) { return v.pos[a] > v.pos[b]; });
    return nb;
}

// (1) Algorithm 4, steepest ascent from S: the neighbour with the largest position not beyond
// D's. Positions strictly increase (the strip successor is a neighbour): it terminates; empty
// when it runs into T or exceeds `budget` faces.
std::vector<FaceId> steepest_ascent(const StripView& v, FaceId t, FaceId s, FaceId d, size_t budget) {
    std::vector<FaceId> up{t, s};
    for (FaceId cur = s; cur != d;) {
        FaceId best = kNone;
        for (const HalfedgeId h : sides(cur)) {
            const FaceId g = v.mesh.neighbor(h);
            if (!g.valid() || g == t || v.pos[g] > v.pos[d]) continue;
            if (!best.valid() || v.pos[g] > v.pos[best]) best = g;
        }
        if (!best.valid() || v.pos[best] <= v.pos[cur] || up.size() > budget) return {};
        up.push_back(cur = best);
    }
    return up;
}

// (2) The mirror image, steepest descent from D: the neighbour with the smallest position not
// below S's; a different shortcut, used when shorter or when (1) is rejected.
std::vector<FaceId> steepest_descent(const StripView& v, FaceId t, FaceId s, FaceId d, size_t budget) {
    std::vector<FaceId> down{d};
    for (FaceId cur = d; cur != s;) {
        FaceId best = kNone;
        for (const HalfedgeId h : sides(cur)) {
            const FaceId g = v.mesh.neighbor(h);
            if (!g.valid() || g == t || v.pos[g] < v.pos[s]) continue;
            if (!best.valid() || v.pos[g] < v.pos[best]) best = g;
        }
        if (!best.valid() || v.pos[best] >= v.pos[cur] || down.size() > budget) return {};
        down.push_back(cur = best);
    }
    std::reverse(down.begin(), down.end());  // S .. D
    down.insert(down.begin(), t);
    return down;
}

// (5) The paper's parallel path, shortest: T's neighbours taken after T were joined, when T was
// taken, by the faces still unstriped then (the faces taken later); a breadth-first path
// through those closes the cycle. Independent of strip positions.
std::vector<std::vector<FaceId>> parallel_paths(const StripView& v, FaceSearch& search, FaceId t, const std::vector<FaceId>& nb) {
    const uint32_t tt = v.take_time[t];
    std::vector<FaceId> later;
    for (const FaceId g : nb)
        if (v.take_time[g] != kNone && v.take_time[g] > tt) later.push_back(g);
    std::vector<std::vector<FaceId>> paths;
    for (size_t x = 0; x < later.size(); ++x)
        for (size_t y = x + 1; y < later.size(); ++y) {
            std::vector<FaceId> path = search.path(later[x], later[y], t, &v.take_time, tt);
            if (path.empty()) continue;
            path.insert(path.begin(), t);
            paths.push_back(std::move(path));
        }
    return paths;
}

/// Every candidate of the fundamental triangle at position p, shortest first (ties in the order
/// of the header's list).
std::vector<Candidate> candidates_for(const StripView& v, FaceSearch& search, uint32_t p) {
    const FaceId t = v.at(p);
    const std::vector<FaceId> nb = neighbors_by_position(v, t, p);
    const FaceId d = nb[0], s = nb[1];
    // The breadth-first candidates first: the walks (1) and (2) may follow the strip for as long
    // as it is, so they stop at a few times the shortest of those (they would not be kept).
    std::vector<FaceId> around = search.path(s, d, t);  // (4)
    if (!around.empty()) around.insert(around.begin(), t);
    std::vector<std::vector<FaceId>> parallel = parallel_paths(v, search, t, nb);
    size_t shortest = around.empty() ? v.order.size() : around.size();
    for (const auto& path : parallel) shortest = std::min(shortest, path.size());
    const size_t budget = shortest >= v.order.size() ? v.order.size() : 4 * shortest + 64;

    std::vector<Candidate> cand;
    auto add = [&](CycleSource source, std::vector<FaceId> faces) {
        if (!faces.empty()) cand.push_back({source, std::move(faces)});
    };
    add(CycleSource::SteepestAscent, steepest_ascent(v, t, s, d, budget));
    add(CycleSource::SteepestDescent, steepest_descent(v, t, s, d, budget));
    // (3) Strip cycles: T and the strip segment between two neighbours on the same side of T
    // (§4: "a strip segment from the outedge neighbor of T to the third-edge neighbor").
    for (size_t x = 0; x < nb.size(); ++x)
        for (size_t y = x + 1; y < nb.size(); ++y) {
            const uint32_t lo = std::min(v.pos[nb[x]], v.pos[nb[y]]), hi = std::max(v.pos[nb[x]], v.pos[nb[y]]);
            if (lo < p && p < hi) continue;                                // the segment would pass through T
            if (v.seam != kNone && lo <= v.seam && v.seam < hi) continue;  // not a chain of neighbours
            Candidate c;
            c.lazy = true;
            c.t = t;
            c.lo = lo;
            c.hi = hi;
            cand.push_back(std::move(c));
        }
    add(CycleSource::ShortestPath, std::move(around));
    for (auto& path : parallel) add(CycleSource::ParallelPath, std::move(path));
    if (cand.empty()) throw InternalError("fundamental cycles: no path around the fundamental triangle at position " + std::to_string(p));
    // Shortest first, ties in candidate order. (A stable insertion sort: a handful of
    // candidates; std::stable_sort's temporary buffer trips ASan's alloc-dealloc check in
    // GCC 12's libstdc++.)
    for (size_t x = 1; x < cand.size(); ++x)
        for (size_t y = x; y > 0 && cand[y].size() < cand[y - 1].size(); --y) std::swap(cand[y], cand[y - 1]);
    return cand;
}

/// Class bits of the tree–cotree generators, shortest generator first (ties in bit order).
std::vector<size_t> generators_by_length(const HomologyClassifier& classifier) {
    std::vector<std::pair<size_t, size_t>> by_length(classifier.dimension());  // (length, bit)
    for (size_t j = 0; j < by_length.size(); ++j) by_length[j] = {classifier.generator_length(j), j};
    std::sort(by_length.begin(), by_length.end());
    std::vector<size_t> bits(by_length.size());
    for (size_t k = 0; k < bits.size(); ++k) bits[k] = by_length[k].second;
    return bits;
}

/// The j-th unit vector of `dim` bits: the class of tree–cotree generator j.
std::vector<uint64_t> unit_class(size_t dim, size_t j) {
    std::vector<uint64_t> v((dim + 63) / 64, 0);
    v[j / 64] = uint64_t{1} << (j % 64);
    return v;
}

/// Face -> position in `order`. \throw InternalError if `order` is not a permutation of the faces.
IdVector<FaceId, uint32_t> positions_of(const std::vector<uint32_t>& order, uint32_t nf) {
    if (order.size() != nf) throw InternalError("fundamental cycles: strip order does not cover the mesh");
    IdVector<FaceId, uint32_t> pos(nf, kNone);
    for (uint32_t i = 0; i < nf; ++i) {
        const FaceId f(order[i]);
        if (f.idx() >= nf || pos[f] != kNone) throw InternalError("fundamental cycles: strip order is not a permutation");
        pos[f] = i;
    }
    return pos;
}

/// dim H1(M; Z2) = 2g+h-1, or 2g on a closed surface.
size_t rank_of(const Mesh& mesh) {
    const long long loops = mesh.num_boundary_loops();
    return static_cast<size_t>(2 * mesh.genus() + (loops > 0 ? loops - 1 : 0));
}

/// A candidate that, apart from T (its first face), runs through faces after position p only.
bool in_suffix(const StripView& v, const Candidate& c, uint32_t p) {
    if (c.lazy) return c.lo > p;
    for (size_t k = 1; k < c.faces.size(); ++k)
        if (v.pos[c.faces[k]] <= p) return false;
    return true;
}

// Replayed triangles, no classes needed. Let T at position p (p >= 1) have exactly two
// neighbours after it, joined in U_{p+1} (the replay found it fundamental). A cycle through T and
// otherwise through U_{p+1} is, in H1(U_p), the new class T adds plus a class of U_{p+1}; so a
// cycle per triangle, each inside its own suffix, are independent in H1(U_1) (take the one of
// smallest position in a vanishing sum), and U_1 -> M is injective on H1 when the replay found
// exactly dim triangles (no face caps a hole). Each triangle keeps its shortest such candidate
// (a parallel path always is one). False, with `chosen` unspecified, when a condition fails.
bool choose_nested(const StripView& v, FaceSearch& search, const std::vector<uint32_t>& fundamental, size_t dim,
                   std::vector<Candidate>& chosen) {
    if (fundamental.size() != dim) return false;
    chosen.clear();
    for (size_t i = 0; i < fundamental.size(); ++i) {
        const uint32_t p = fundamental[i];
        if (p == 0 || (i > 0 && p <= fundamental[i - 1])) return false;
        uint32_t later = 0;
        for (const HalfedgeId h : sides(v.at(p))) {
            const FaceId g = v.mesh.neighbor(h);
            later += g.valid() && v.pos[g] > p;
        }
        if (later != 2) return false;
        search.next_cycle();
        std::vector<Candidate> cand = candidates_for(v, search, p);
        auto it = std::find_if(cand.begin(), cand.end(), [&](const Candidate& c) { return in_suffix(v, c, p); });
        if (it == cand.end()) return false;
        it->materialize(v.order);
        chosen.push_back(std::move(*it));
    }
    return true;
}

/// The first position whose face has an edge on the mesh boundary; kNone on a closed mesh.
uint32_t first_on_boundary(const Mesh& mesh, const std::vector<uint32_t>& order) {
    if (mesh.num_boundary_edges() == 0) return kNone;
    for (uint32_t p = 0; p < order.size(); ++p)
        for (const HalfedgeId h : sides(FaceId(order[p])))
            if (mesh.is_boundary(h)) return p;
    return kNone;
}

/// choose_nested() for a strip that starts inside a mesh with boundary (its first face caps a
/// hole, so the replay finds one triangle more than dim): the same faces with the strip's prefix
/// up to its first face on the boundary, q, read backwards. That order starts on the boundary;
/// it is a chain of neighbours but for the seam between positions q and q + 1, which no strip
/// segment crosses (the conditions are checked as for the strip). False if it fails too.
bool choose_nested_reordered(const Mesh& mesh, const std::vector<uint32_t>& order, FaceSearch& search, size_t dim,
                             std::vector<Candidate>& chosen) {
    const uint32_t q = first_on_boundary(mesh, order);
    if (q == kNone || q == 0) return false;
    std::vector<uint32_t> reordered(order);
    std::reverse(reordered.begin(), reordered.begin() + q + 1);
    IdVector<FaceId, uint32_t> pos(mesh.num_faces(), 0);
    for (uint32_t p = 0; p < reordered.size(); ++p) pos[FaceId(reordered[p])] = p;
    StripView view{mesh, reordered, pos, pos};
    view.seam = q;
    return choose_nested(view, search, replay_fundamental_positions(mesh, reordered), dim, chosen);
}

/// Any fundamental triangles: classes computed, the shortest independent candidate kept.
std::vector<Candidate> choose_independent(const StripView& view, FaceSearch& search, const std::vector<uint32_t>& fundamental) {
    // Shortcuts and strip segments can be null-homologous or dependent (a steepest ascent that
    // closes around one vertex of T; with deferred islands spliced in, strip positions are not
    // the order in which faces were taken, so a segment may miss the handle). Keep, per
    // fundamental triangle in strip order, the shortest candidate independent in H1(M; Z2) of
    // those kept so far; fill the slots left with the shortest independent tree–cotree generators.
    const HomologyClassifier classifier(view.mesh);
    const size_t dim = classifier.dimension();
    Z2Basis basis(dim);
    auto keep = [&](const std::vector<FaceId>& faces) { return basis.insert(classifier.classify(faces)); };
    std::vector<Candidate> chosen(fundamental.size());
    std::vector<size_t> pending;
    size_t rank = 0;
    for (size_t i = 0, j = 0; i < fundamental.size(); i = j) {
        // A triangle counted twice (a first face joining loops) fills both slots from one list.
        while (j < fundamental.size() && fundamental[j] == fundamental[i]) ++j;
        search.next_cycle();
        std::vector<Candidate> cand = candidates_for(view, search, fundamental[i]);
        size_t next = 0;
        for (size_t slot = i; slot < j; ++slot) {
            while (next < cand.size() && !keep(cand[next].materialize(view.order))) ++next;
            if (next == cand.size()) {
                pending.push_back(slot);
                continue;
            }
            chosen[slot] = std::move(cand[next++]);
            ++rank;
        }
    }
    // Slots left, and the rank still missing: constraint edges change which faces are
    // fundamental (a constraint loop around a handle makes one cycle "visible" only to the
    // surface), so the surface's 2g+h-1 may exceed the fundamental triangles met. Fill with the
    // shortest independent tree–cotree generators; drop slots that cannot be filled (more
    // fundamental triangles than dim H1, e.g. an interior seed): the cycles are the surface's.
    // Generators are built only when kept; their classes are unit vectors (tree_cotree.hpp).
    if (rank < dim) {
        const std::vector<size_t> gens = generators_by_length(classifier);
        auto keep_generator = [&](size_t j) { return basis.insert(unit_class(dim, j)); };
        size_t next = 0;
        for (size_t i : pending) {
            while (next < gens.size() && !keep_generator(gens[next])) ++next;
            if (next == gens.size()) break;
            chosen[i] = {CycleSource::TreeCotree, classifier.generator(gens[next++])};
            ++rank;
        }
        for (; rank < dim && next < gens.size(); ++next)
            if (keep_generator(gens[next])) {
                chosen.push_back({CycleSource::TreeCotree, classifier.generator(gens[next])});
                ++rank;
            }
    }

    return chosen;
}

}  // namespace

Cycles compute_fundamental_cycles(const StripResult& result) {
    const Mesh& mesh = result.mesh;
    const uint32_t nf = mesh.num_faces();
    const IdVector<FaceId, uint32_t> pos = positions_of(result.order, nf);
    // The growth builder records its fundamental triangles and when each face was taken; any
    // other strip order gets them by replay, and its positions serve as take times: the faces
    // after a fundamental triangle are then exactly the region it was removed from.
    const bool recorded = result.take_time.size() == nf;
    const std::vector<uint32_t> fundamental = recorded ? result.fundamental_positions : replay_fundamental_positions(mesh, result.order);
    for (const uint32_t p : fundamental)
        if (p >= nf) throw InternalError("fundamental cycles: fundamental position out of range");
    const StripView view{mesh, result.order, pos, recorded ? IdSpan<FaceId, uint32_t>(result.take_time) : pos};

    // A replayed strip usually needs no homology classes at all (choose_nested()); otherwise
    // each candidate's class is computed and checked against those kept.
    // The breadth-first searches visit the faces within a cycle's length of T, each time: on
    // corridors one quad wide between long holes that is most of the mesh for every hole
    // (hole corridors, 1M faces: 42 s for 500 cycles). Past 16 visits a face plus 4,096 a cycle
    // (cheese.off, genus 133, needs 1,024-2,048 a cycle), the tree–cotree generators are the
    // cycles instead: a basis too, in time linear in their length (the same 1M faces: 1.6 s).
    const size_t rank = rank_of(mesh);  // two passes over the boundary: once
    FaceSearch search(mesh, kSearchPerFace * uint64_t{nf} + kSearchPerCycle * uint64_t{rank} + kSearchFloor, rank);
    std::vector<Candidate> chosen;
    try {
        bool nested = !recorded && choose_nested(view, search, fundamental, rank, chosen);
        // The growth builder's own triangles need classes: a dense Z2 basis of (2g)^2 bits and a
        // class per candidate, O(g) each (g^2 in all). The replay of its order usually needs none,
        // so the cost follows the cycles' length; classes only when the replay's conditions fail.
        if (!nested && recorded) {
            const StripView replayed{mesh, result.order, pos, pos};
            nested = choose_nested(replayed, search, replay_fundamental_positions(mesh, result.order), rank, chosen);
        }
        // A large strip that starts inside a mesh with boundary: read from the boundary instead
        // (the classes' arrays and sort cost more there than the shorter cycles they may find).
        if (!nested && nf >= kReorderFaces) nested = choose_nested_reordered(mesh, result.order, search, rank, chosen);
        if (!nested) chosen = choose_independent(view, search, fundamental);
    } catch (const SearchBudgetSpent&) {
        Cycles out = tree_cotree_cycles(result);
        out.sources.assign(out.cycles.size(), CycleSource::TreeCotree);
        return out;
    }

    Cycles out;
    const MeshFaces faces{mesh, result.order};  // not strip_arrays(): a copy of the whole output
    for (const Candidate& c : chosen) {
        if (c.faces.empty()) continue;  // a slot no independent cycle could fill
        std::vector<uint32_t> cycle;
        cycle.reserve(c.faces.size());
        for (const FaceId f : c.faces) cycle.push_back(pos[f]);
        out.lengths.push_back(length_of(faces, cycle));
        out.cycles.push_back(std::move(cycle));
        out.sources.push_back(c.source);
    }
    return out;
}

std::vector<Point3> cycle_polyline(const StripArrays& arrays, const std::vector<uint32_t>& cycle) {
    return polyline_of(ArraysFaces{arrays}, cycle);
}

std::vector<std::vector<Point3>> cycle_polylines(const StripArrays& arrays, const Cycles& cycles) {
    std::vector<std::vector<Point3>> out;
    out.reserve(cycles.cycles.size());
    for (const auto& cycle : cycles.cycles) {
        for (const uint32_t f : cycle)
            if (f >= arrays.faces.size())
                throw RequestError("cycle face " + std::to_string(f) + " is out of range (" + std::to_string(arrays.faces.size()) +
                                   " faces)");
        out.push_back(cycle_polyline(arrays, cycle));
    }
    return out;
}

double cycle_length(const StripArrays& arrays, const std::vector<uint32_t>& cycle) {
    return length_of(ArraysFaces{arrays}, cycle);
}

Cycles tree_cotree_cycles(const StripResult& result) {
    Cycles out;
    out.cycles = tree_cotree_generators(result.mesh, result.order);
    const MeshFaces faces{result.mesh, result.order};
    out.lengths.reserve(out.cycles.size());
    for (const auto& c : out.cycles) out.lengths.push_back(length_of(faces, c));
    return out;
}

}  // namespace singlestrip
