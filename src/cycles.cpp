// singlestrip — fundamental cycles by steepest ascent over the strip order (paper §4).
#include "singlestrip/cycles.hpp"

#include <algorithm>
#include <numeric>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/tree_cotree.hpp"

namespace singlestrip {

namespace {

/// Breadth-first shortest path of faces from `from` to `to` avoiding face `avoid`; empty when
/// there is none. The path includes both ends.
// Shortest chain of edge-adjacent faces from `from` to `to` avoiding `avoid`; with `time`, only
// through faces whose time is greater than `after`.
std::vector<uint32_t> bfs_path(const Mesh& mesh, uint32_t from, uint32_t to, uint32_t avoid,
                               const std::vector<uint32_t>* time = nullptr, uint32_t after = 0) {
    std::vector<uint32_t> parent(mesh.num_faces(), kNone);
    std::vector<uint32_t> queue{from};
    parent[from] = from;
    for (size_t head = 0; head < queue.size(); ++head) {
        const uint32_t f = queue[head];
        if (f == to) break;
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t g = mesh.neighbor(Mesh::halfedge(f, k));
            if (g == kNone || g == avoid || parent[g] != kNone) continue;
            if (time && ((*time)[g] == kNone || (*time)[g] <= after)) continue;
            parent[g] = f;
            queue.push_back(g);
        }
    }
    if (parent[to] == kNone) return {};
    std::vector<uint32_t> path;
    for (uint32_t f = to; f != from; f = parent[f]) path.push_back(f);
    path.push_back(from);
    std::reverse(path.begin(), path.end());
    return path;
}

Point3 centroid(const StripArrays& a, uint32_t f) {
    const Triangle& t = a.faces[f];
    Point3 c{0, 0, 0};
    for (uint32_t v : t)
        for (int i = 0; i < 3; ++i) c[i] += a.points[v][i] / 3.0;
    return c;
}

double distance(const Point3& p, const Point3& q) {
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

/// Midpoint of the edge shared by faces f and g; false if they share fewer than two vertices.
bool shared_midpoint(const StripArrays& a, uint32_t f, uint32_t g, Point3& out) {
    uint32_t common[2];
    int n = 0;
    for (uint32_t v : a.faces[f])
        if (std::find(a.faces[g].begin(), a.faces[g].end(), v) != a.faces[g].end() && n < 2) common[n++] = v;
    if (n < 2) return false;
    for (int i = 0; i < 3; ++i) out[i] = 0.5 * (a.points[common[0]][i] + a.points[common[1]][i]);
    return true;
}

}  // namespace

Cycles compute_fundamental_cycles(const StripResult& result) {
    const Mesh& mesh = result.mesh;
    const uint32_t nf = mesh.num_faces();
    if (result.order.size() != nf) throw InternalError("fundamental cycles: strip order does not cover the mesh");
    std::vector<uint32_t> pos(nf, kNone);
    for (uint32_t i = 0; i < nf; ++i) {
        const uint32_t f = result.order[i];
        if (f >= nf || pos[f] != kNone) throw InternalError("fundamental cycles: strip order is not a permutation");
        pos[f] = i;
    }
    auto neighbor_ok = [&](uint32_t g, uint32_t t) { return g != kNone && g != t; };
    // The growth builder records its fundamental triangles and when each face was taken; any
    // other strip order gets them by replay, and its positions serve as take times: the faces
    // after a fundamental triangle are then exactly the region it was removed from.
    const bool recorded = result.take_time.size() == nf;
    const std::vector<uint32_t> fundamental =
        recorded ? result.fundamental_positions : replay_fundamental_positions(mesh, result.order);
    const std::vector<uint32_t>& take_time = recorded ? result.take_time : pos;

    // Per fundamental triangle: candidate cycles as chains of MESH faces, shortest first.
    struct Candidate {
        CycleSource source = CycleSource::StripSegment;
        std::vector<uint32_t> faces;
    };
    const size_t n = fundamental.size();
    std::vector<std::vector<Candidate>> candidates(n);
    for (size_t i = 0; i < n; ++i) {
        const uint32_t p = fundamental[i];
        if (p >= nf) throw InternalError("fundamental cycles: fundamental position out of range");
        const uint32_t t = result.order[p];
        std::vector<uint32_t> nb;
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t g = mesh.neighbor(Mesh::halfedge(t, k));
            if (g != kNone && std::find(nb.begin(), nb.end(), g) == nb.end()) nb.push_back(g);
        }
        if (nb.size() < 2)
            throw InternalError("fundamental cycles: fundamental triangle at position " + std::to_string(p) +
                                " has fewer than two neighbours");
        std::sort(nb.begin(), nb.end(), [&](uint32_t a, uint32_t b) { return pos[a] > pos[b]; });
        const uint32_t d = nb[0];  // destination: largest position (Algorithm 3)
        const uint32_t s = nb[1];  // source: second largest

        // (1) Algorithm 4, steepest ascent: the neighbour with the largest position not beyond
        // D's. Positions strictly increase (the strip successor is a neighbour): terminates.
        std::vector<uint32_t> up{t, s};
        for (uint32_t cur = s; cur != d && !up.empty();) {
            uint32_t best = kNone;
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t g = mesh.neighbor(Mesh::halfedge(cur, k));
                if (!neighbor_ok(g, t) || pos[g] > pos[d]) continue;
                if (best == kNone || pos[g] > pos[best]) best = g;
            }
            if (best == kNone || pos[best] <= pos[cur]) up.clear();  // S before T: ran into T
            else up.push_back(cur = best);
        }
        // (2) The mirror image, steepest descent from D: the neighbour with the smallest position
        // not below S's; a different shortcut, used when shorter or when (1) is rejected.
        std::vector<uint32_t> down{d};
        for (uint32_t cur = d; cur != s && !down.empty();) {
            uint32_t best = kNone;
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t g = mesh.neighbor(Mesh::halfedge(cur, k));
                if (!neighbor_ok(g, t) || pos[g] < pos[s]) continue;
                if (best == kNone || pos[g] < pos[best]) best = g;
            }
            if (best == kNone || pos[best] >= pos[cur]) down.clear();
            else down.push_back(cur = best);
        }
        if (!down.empty()) {
            std::reverse(down.begin(), down.end());  // S .. D
            down.insert(down.begin(), t);
        }
        // (3) Strip cycles: T and the strip segment between two neighbours on the same side of T
        // (§4: "a strip segment from the outedge neighbor of T to the third-edge neighbor").
        auto& cand = candidates[i];
        if (!up.empty()) cand.push_back({CycleSource::SteepestAscent, std::move(up)});
        if (!down.empty()) cand.push_back({CycleSource::SteepestDescent, std::move(down)});
        for (size_t x = 0; x < nb.size(); ++x)
            for (size_t y = x + 1; y < nb.size(); ++y) {
                const uint32_t lo = std::min(pos[nb[x]], pos[nb[y]]), hi = std::max(pos[nb[x]], pos[nb[y]]);
                if (lo < p && p < hi) continue;  // the segment would pass through T
                std::vector<uint32_t> c{t};
                for (uint32_t k = lo; k <= hi; ++k) c.push_back(result.order[k]);
                cand.push_back({CycleSource::StripSegment, std::move(c)});
            }
        // (4) A breadth-first shortest path from S to D avoiding T (often around one vertex of T,
        // so null-homologous, but a candidate nonetheless).
        std::vector<uint32_t> around = bfs_path(mesh, s, d, t);
        if (!around.empty()) {
            around.insert(around.begin(), t);
            cand.push_back({CycleSource::ShortestPath, std::move(around)});
        }
        // (5) The paper's parallel path, shortest: T's neighbours taken after T were joined,
        // when T was taken, by the faces still unstriped then (the faces taken later); a
        // breadth-first path through those closes the cycle. Independent of strip positions.
        {
            const uint32_t tt = take_time[t];
            std::vector<uint32_t> later;
            for (uint32_t g : nb)
                if (take_time[g] != kNone && take_time[g] > tt) later.push_back(g);
            for (size_t x = 0; x < later.size(); ++x)
                for (size_t y = x + 1; y < later.size(); ++y) {
                    std::vector<uint32_t> path = bfs_path(mesh, later[x], later[y], t, &take_time, tt);
                    if (path.empty()) continue;
                    path.insert(path.begin(), t);
                    cand.push_back({CycleSource::ParallelPath, std::move(path)});
                }
        }
        if (cand.empty())
            throw InternalError("fundamental cycles: no path around the fundamental triangle at position " +
                                std::to_string(p));
        // Shortest first, ties in candidate order. (A stable insertion sort: a handful of
        // candidates; std::stable_sort's temporary buffer trips ASan's alloc-dealloc check in
        // GCC 12's libstdc++.)
        for (size_t x = 1; x < cand.size(); ++x)
            for (size_t y = x; y > 0 && cand[y].faces.size() < cand[y - 1].faces.size(); --y) std::swap(cand[y], cand[y - 1]);
    }

    // Shortcuts and strip segments can be null-homologous or dependent (a steepest ascent that
    // closes around one vertex of T; with deferred islands spliced in, strip positions are not
    // the order in which faces were taken, so a segment may miss the handle). Keep, per
    // fundamental triangle in strip order, the shortest candidate independent in H1(M; Z2) of
    // those kept so far; fill the slots left with the shortest independent tree–cotree generators.
    Cycles out;
    const HomologyClassifier classifier(mesh);
    const size_t dim = classifier.dimension();
    std::vector<std::vector<uint64_t>> basis(dim);  // basis[c]: a class whose lowest set bit is c
    auto insert = [&](std::vector<uint64_t> v) {
        for (;;) {
            size_t c = 0;
            while (c < 64 * v.size() && !(v[c / 64] >> (c % 64) & 1u)) ++c;
            if (c >= dim) return false;  // reduced to zero: dependent
            if (basis[c].empty()) {
                basis[c] = std::move(v);
                return true;
            }
            for (size_t k = 0; k < v.size(); ++k) v[k] ^= basis[c][k];
        }
    };
    std::vector<Candidate> chosen(n);
    std::vector<size_t> pending;
    for (size_t i = 0; i < n; ++i) {
        bool found = false;
        for (Candidate& c : candidates[i])
            if (insert(classifier.classify(c.faces))) {
                chosen[i] = std::move(c);
                found = true;
                break;
            }
        if (!found) pending.push_back(i);
    }
    // Slots left, and the rank still missing: constraint edges change which faces are
    // fundamental (a constraint loop around a handle makes one cycle "visible" only to the
    // surface), so the surface's 2g+h-1 may exceed the fundamental triangles met. Fill with the
    // shortest independent tree–cotree generators; drop slots that cannot be filled (more
    // fundamental triangles than dim H1, e.g. an interior seed): the cycles are the surface's.
    size_t rank = 0;
    for (size_t i = 0; i < n; ++i) rank += !chosen[i].faces.empty();
    std::vector<Candidate> extra;
    if (rank < dim) {
        std::vector<std::vector<uint32_t>> gens = tree_cotree_generators(mesh);
        {  // shortest first, ties in generator order (see above for why not std::stable_sort)
            std::vector<size_t> by_size(gens.size());
            std::iota(by_size.begin(), by_size.end(), size_t{0});
            std::sort(by_size.begin(), by_size.end(), [&](size_t u, size_t v) {
                return gens[u].size() != gens[v].size() ? gens[u].size() < gens[v].size() : u < v;
            });
            std::vector<std::vector<uint32_t>> sorted;
            sorted.reserve(gens.size());
            for (size_t k : by_size) sorted.push_back(std::move(gens[k]));
            gens = std::move(sorted);
        }
        size_t next = 0;
        for (size_t i : pending) {
            while (next < gens.size() && !insert(classifier.classify(gens[next]))) ++next;
            if (next == gens.size()) break;
            chosen[i] = {CycleSource::TreeCotree, std::move(gens[next++])};
            ++rank;
        }
        for (; rank < dim && next < gens.size(); ++next)
            if (insert(classifier.classify(gens[next]))) {
                extra.push_back({CycleSource::TreeCotree, std::move(gens[next])});
                ++rank;
            }
    }
    for (Candidate& c : extra) chosen.push_back(std::move(c));

    const StripArrays arrays = strip_arrays(result);
    for (size_t i = 0; i < chosen.size(); ++i) {
        if (chosen[i].faces.empty()) continue;  // a slot no independent cycle could fill
        std::vector<uint32_t> cycle;
        for (uint32_t f : chosen[i].faces) cycle.push_back(pos[f]);
        out.lengths.push_back(cycle_length(arrays, cycle));
        out.cycles.push_back(std::move(cycle));
        out.sources.push_back(chosen[i].source);
    }
    return out;
}

std::vector<Point3> cycle_polyline(const StripArrays& arrays, const std::vector<uint32_t>& cycle) {
    std::vector<Point3> pts;
    const size_t n = cycle.size();
    pts.reserve(2 * n);
    for (size_t i = 0; i < n; ++i) {
        pts.push_back(centroid(arrays, cycle[i]));
        if (n < 2) break;
        Point3 m;
        if (shared_midpoint(arrays, cycle[i], cycle[(i + 1) % n], m)) pts.push_back(m);
    }
    return pts;
}

double cycle_length(const StripArrays& arrays, const std::vector<uint32_t>& cycle) {
    if (cycle.size() < 2) return 0.0;
    const std::vector<Point3> pts = cycle_polyline(arrays, cycle);
    double len = 0.0;
    for (size_t i = 0; i < pts.size(); ++i) len += distance(pts[i], pts[(i + 1) % pts.size()]);
    return len;
}

void write_cycles_json(const std::string& path, const Cycles& cycles) {
    std::ostringstream os;
    os << std::setprecision(std::numeric_limits<double>::max_digits10);
    os << "{\"cycles\": [";
    for (size_t i = 0; i < cycles.cycles.size(); ++i) {
        os << (i ? ",\n  [" : "\n  [");
        for (size_t j = 0; j < cycles.cycles[i].size(); ++j) os << (j ? "," : "") << cycles.cycles[i][j];
        os << "]";
    }
    os << (cycles.cycles.empty() ? "],\n \"lengths\": [" : "\n ],\n \"lengths\": [");
    for (size_t i = 0; i < cycles.lengths.size(); ++i) {
        const double l = cycles.lengths[i];
        os << (i ? ", " : "");
        if (std::isfinite(l)) os << l;
        else os << "null";  // JSON has no NaN/Inf
    }
    os << "]}\n";
    write_text_atomic(path, os.str());
}

void write_cycles_obj(const std::string& path, const StripArrays& arrays, const Cycles& cycles) {
    std::ostringstream os;
    os << std::setprecision(std::numeric_limits<double>::max_digits10);
    os << "# singlestrip fundamental cycles: " << cycles.cycles.size()
       << " closed polylines through face centroids and shared-edge midpoints\n";
    std::vector<std::pair<size_t, size_t>> ranges;  // first OBJ vertex (1-based), count
    size_t next = 1;
    for (const auto& cycle : cycles.cycles) {
        for (const uint32_t f : cycle)
            if (f >= arrays.faces.size())
                throw OutputError("cycles OBJ '" + path + "': face " + std::to_string(f) + " out of range");
        const std::vector<Point3> pts = cycle_polyline(arrays, cycle);
        for (const Point3& q : pts) os << "v " << q[0] << ' ' << q[1] << ' ' << q[2] << '\n';
        ranges.emplace_back(next, pts.size());
        next += pts.size();
    }
    for (size_t i = 0; i < ranges.size(); ++i) {
        const auto [first, count] = ranges[i];
        if (count < 2) continue;  // a single point is not a polyline
        os << "o cycle_" << i << "\nl";
        for (size_t k = 0; k < count; ++k) os << ' ' << first + k;
        os << ' ' << first << '\n';
    }
    write_text_atomic(path, os.str());
}

}  // namespace singlestrip
