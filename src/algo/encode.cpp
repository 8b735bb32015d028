// singlestrip — shortest GL_TRIANGLE_STRIP encoding of a face sequence.
//
// Dynamic programming over faces. After face j has been emitted the only things that matter for
// the future are the last two indices (an ordered pair of f_j's vertices, 6 choices) and the
// parity of the next triangle index (2): 12 states. Between f_j and f_{j+1} we may append
// indices that form degenerate (skipped) triangles; the first non-degenerate triangle formed
// must be f_{j+1} with its winding. The cheapest way from each state of f_j to each state of
// f_{j+1} is a shortest path (BFS) over (last two indices, parity) with letters taken from the
// vertices of f_j and f_{j+1}: an index outside them can only sit inside degenerate triangles
// and any vertex already present does that job as well. The BFS depends only on how f_{j+1}
// overlaps f_j, so its 12 x 12 cost matrix is built once per overlap pattern (24 of them) and the
// DP costs O(144) per face. The tables also hold each transition's run of indices (as labels),
// so reconstruction is a table lookup per face; working memory is 14 bytes per face.
// The DP keeps costs relative to the cheapest state, one byte each: six states are never
// reachable (their last two indices contradict the face's winding) and every other state of
// one face reaches every other state of the next within 6 indices (checked when the tables are
// built), so after a normalisation relative costs are at most 6, and 16 steps later at most
// 6 + 16 x 6. A step is then a min-plus product on 16 byte lanes, SSE2 where the target has it
// (every x86-64), and the costs are normalised every 16th step (the horizontal minimum was on
// every step's critical path): 1.3M-face sphere 30 -> 18 ns a face, genus-20 4M 31 -> 21.
#include <cstddef>  // before encode.hpp, which uses size_t without including it

#include "singlestrip/encode.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#if defined(__SSE2__) && !defined(SINGLESTRIP_NO_SIMD)
#include <emmintrin.h>
#endif

#include "singlestrip/errors.hpp"

namespace singlestrip {
namespace {

constexpr int kStates = 12;  // ordered pair slot (6) x parity (2)
constexpr uint8_t kUnreachable = 0xff;
constexpr int kLanes = 16;  // kStates padded to a vector register of bytes
using Lanes = std::array<uint8_t, kLanes>;

/// Ordered pair of distinct positions (ix, iy) in a triangle <-> slot 0..5.
int pair_slot(int ix, int iy) {
    return ix * 2 + (iy > ix ? iy - 1 : iy);
}
std::pair<int, int> slot_pair(int slot) {
    const int ix = slot / 2, r = slot % 2;
    return {ix, r < ix ? r : r + 1};
}

bool same_winding(const Triangle& t, const Triangle& f) {
    for (int r = 0; r < 3; ++r)
        if (t[0] == f[r] && t[1] == f[(r + 1) % 3] && t[2] == f[(r + 2) % 3]) return true;
    return false;
}

/// Search graph between two faces, on labels 0..m-1 (labels 0..2 = the previous face's
/// vertices, 3 = the new face's other vertex). Node (x, y, p) = last two labels and parity of
/// the next triangle; terminal nodes (one per state of the target face) end the search.
struct Graph {
    int m;
    Triangle target;  // labels
    [[nodiscard]] int nodes() const { return m * m * 2; }
    [[nodiscard]] int node(int x, int y, int p) const { return (x * m + y) * 2 + p; }

    struct Search {
        std::array<uint8_t, 6 * 6 * 2 + kStates> dist;
        std::array<int16_t, 6 * 6 * 2 + kStates> parent;
        std::array<int8_t, 6 * 6 * 2 + kStates> letter;
    };

    /// BFS from one node; dist of terminal t is at nodes() + t.
    [[nodiscard]] Search bfs(int source) const {
        Search s;
        s.dist.fill(kUnreachable);
        s.parent.fill(-1);
        s.letter.fill(-1);
        std::array<int, 6 * 6 * 2> queue{};
        int head = 0, tail = 0;
        s.dist[source] = 0;
        queue[tail++] = source;
        while (head < tail) {
            const int u = queue[head++];
            const int p = u % 2, y = (u / 2) % m, x = u / 2 / m;
            for (int z = 0; z < m; ++z) {
                int v;
                if (x == y || y == z || x == z) {
                    v = node(y, z, 1 - p);  // degenerate: skipped by the decoder
                } else {
                    const Triangle tri =
                        p == 0 ? Triangle{uint32_t(x), uint32_t(y), uint32_t(z)} : Triangle{uint32_t(y), uint32_t(x), uint32_t(z)};
                    if (!same_winding(tri, target)) continue;  // a stray triangle: forbidden
                    int iy = 0, iz = 0;
                    for (int k = 0; k < 3; ++k) {
                        if (target[k] == uint32_t(y)) iy = k;
                        if (target[k] == uint32_t(z)) iz = k;
                    }
                    v = nodes() + pair_slot(iy, iz) * 2 + (1 - p);
                }
                if (s.dist[v] != kUnreachable) continue;
                s.dist[v] = static_cast<uint8_t>(s.dist[u] + 1);
                s.parent[v] = static_cast<int16_t>(u);
                s.letter[v] = static_cast<int8_t>(z);
                if (v < nodes()) queue[tail++] = v;
            }
        }
        return s;
    }

    /// Labels appended on the BFS path from the search's source to node `to`, in order.
    static void path(const Search& s, int to, std::vector<int>& out) {
        const size_t start = out.size();
        for (int v = to; s.parent[v] >= 0; v = s.parent[v]) out.push_back(s.letter[v]);
        std::reverse(out.begin() + static_cast<std::ptrdiff_t>(start), out.end());
    }
};

/// Cheapest run of appended labels from one state of the previous face to one state of the next.
struct Transition {
    uint8_t cost = kUnreachable;
    uint8_t len = 0;
    std::array<int8_t, 14> labels{};  // BFS paths are at most 7 long; the first face adds 2
};
using Matrix = std::array<std::array<Transition, kStates>, kStates>;  // [from state][to state]

void store_path(const Graph& g, const Graph::Search& s, int to, std::vector<int>& scratch, Transition& t, uint8_t extra_cost) {
    scratch.clear();
    Graph::path(s, g.nodes() + to, scratch);
    if (scratch.size() + t.len > t.labels.size()) throw InternalError("encode_triangle_strip: path too long");
    for (int l : scratch) t.labels[t.len++] = static_cast<int8_t>(l);
    t.cost = static_cast<uint8_t>(s.dist[g.nodes() + to] + extra_cost);
}

/// Labels of `next` relative to `prev`; throws if they do not share an edge.
Triangle relabel(const Triangle& prev, const Triangle& next, size_t j) {
    Triangle labels{};
    int shared = 0;
    for (int k = 0; k < 3; ++k) {
        labels[k] = 3;
        for (int i = 0; i < 3; ++i)
            if (next[k] == prev[i]) labels[k] = static_cast<uint32_t>(i), ++shared;
    }
    if (shared < 2)
        throw InternalError("encode_triangle_strip: faces " + std::to_string(j) + " and " + std::to_string(j + 1) +
                            " do not share an edge");
    return labels;
}

int pattern_key(const Triangle& labels) {
    return static_cast<int>(labels[0] * 16 + labels[1] * 4 + labels[2]);
}

Graph graph_for(const Triangle& labels) {
    const bool new_vertex = labels[0] == 3 || labels[1] == 3 || labels[2] == 3;
    return Graph{new_vertex ? 4 : 3, labels};
}

int start_node(const Graph& g, int state) {
    const auto [ix, iy] = slot_pair(state / 2);
    return g.node(ix, iy, state % 2);
}

Matrix transition_matrix(const Graph& g) {
    Matrix mat{};
    std::vector<int> scratch;
    for (int from = 0; from < kStates; ++from) {
        const Graph::Search s = g.bfs(start_node(g, from));
        for (int to = 0; to < kStates; ++to)
            if (s.dist[g.nodes() + to] != kUnreachable) store_path(g, s, to, scratch, mat[from][to], 0);
    }
    return mat;
}

/// The first face: any two leading labels (next triangle has parity 0), then a BFS run.
std::array<Transition, kStates> first_face_transitions() {
    const Graph g{3, Triangle{0, 1, 2}};
    std::array<Transition, kStates> best{};
    std::vector<int> scratch;
    for (int u = 0; u < 3; ++u)
        for (int v = 0; v < 3; ++v) {
            const Graph::Search s = g.bfs(g.node(u, v, 0));
            for (int to = 0; to < kStates; ++to) {
                const uint8_t d = s.dist[g.nodes() + to];
                if (d == kUnreachable || d + 2 >= best[to].cost) continue;
                Transition t;
                t.labels[t.len++] = static_cast<int8_t>(u);
                t.labels[t.len++] = static_cast<int8_t>(v);
                store_path(g, s, to, scratch, t, 2);
                best[to] = t;
            }
        }
    return best;
}

/// What the byte-wide relative costs rely on: a target state is reachable from every state the
/// previous face can be left in, or from none (then the first face cannot be left in it either),
/// within kMaxStep indices.
void check_byte_costs(const std::array<Lanes, kStates>& rows, const std::array<Transition, kStates>& first) {
    constexpr uint8_t kMaxStep = 6;
    for (int to = 0; to < kStates; ++to)
        for (int from = 0; from < kStates; ++from) {
            if (first[from].cost == kUnreachable) continue;
            const bool reachable = first[to].cost != kUnreachable;
            if (reachable != (rows[from][to] != kUnreachable) || (reachable && rows[from][to] > kMaxStep))
                throw InternalError("encode_triangle_strip: transition table outside its byte-cost bounds");
        }
}

/// Tables for every overlap pattern (labels distinct, in 0..3: 24 of the 64 keys), built once.
struct Tables {
    std::array<Transition, kStates> first;
    std::array<std::optional<Matrix>, 64> step;
    std::array<std::array<Lanes, kStates>, 64> rows{};  // step[k]'s costs [from][to], lanes past kStates unreachable
};

const Tables& tables() {
    static const Tables t = [] {
        Tables r;
        r.first = first_face_transitions();
        for (uint32_t a = 0; a < 4; ++a)
            for (uint32_t b = 0; b < 4; ++b)
                for (uint32_t c = 0; c < 4; ++c)
                    if (a != b && b != c && a != c) {
                        const Triangle labels{a, b, c};
                        const int key = pattern_key(labels);
                        r.step[key] = transition_matrix(graph_for(labels));
                        for (int from = 0; from < kStates; ++from) {
                            r.rows[key][from].fill(kUnreachable);
                            for (int to = 0; to < kStates; ++to) r.rows[key][from][to] = (*r.step[key])[from][to].cost;
                        }
                        check_byte_costs(r.rows[key], r.first);
                    }
        return r;
    }();
    return t;
}

/// One DP step: next[to] = min over from of cost[from] + row[from][to], the first `from` on a tie
/// (returned per lane). Saturating byte sums keep kUnreachable the largest value.
Lanes relax(Lanes& cost, const std::array<Lanes, kStates>& rows) {
    Lanes from_of{};
#if defined(__SSE2__) && !defined(SINGLESTRIP_NO_SIMD)
    __m128i next = _mm_set1_epi8(static_cast<char>(kUnreachable)), best = _mm_setzero_si128();
    for (int from = 0; from < kStates; ++from) {
        if (cost[from] == kUnreachable) continue;
        const __m128i row = _mm_loadu_si128(reinterpret_cast<const __m128i*>(rows[from].data()));
        const __m128i cand = _mm_adds_epu8(_mm_set1_epi8(static_cast<char>(cost[from])), row);
        const __m128i least = _mm_min_epu8(next, cand);
        const __m128i better = _mm_andnot_si128(_mm_cmpeq_epi8(least, next), _mm_set1_epi8(-1));
        best = _mm_or_si128(_mm_and_si128(better, _mm_set1_epi8(static_cast<char>(from))), _mm_andnot_si128(better, best));
        next = least;
    }
    _mm_storeu_si128(reinterpret_cast<__m128i*>(cost.data()), next);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(from_of.data()), best);
#else
    Lanes next;
    next.fill(kUnreachable);
    for (int from = 0; from < kStates; ++from) {
        if (cost[from] == kUnreachable) continue;
        for (int to = 0; to < kLanes; ++to) {
            const int cand = std::min<int>(cost[from] + rows[from][to], kUnreachable);
            if (cand < next[to]) next[to] = static_cast<uint8_t>(cand), from_of[to] = static_cast<uint8_t>(from);
        }
    }
    cost = next;
#endif
    return from_of;
}

/// Subtracts the cheapest state's cost from the others (unreachable ones stay so); returns it.
uint8_t normalise(Lanes& cost) {
#if defined(__SSE2__) && !defined(SINGLESTRIP_NO_SIMD)
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(cost.data()));
    __m128i m = _mm_min_epu8(v, _mm_srli_si128(v, 8));
    m = _mm_min_epu8(m, _mm_srli_si128(m, 4));
    m = _mm_min_epu8(m, _mm_srli_si128(m, 2));
    m = _mm_min_epu8(m, _mm_srli_si128(m, 1));
    const auto least = static_cast<uint8_t>(_mm_cvtsi128_si32(m) & 0xff);
    const __m128i unreachable = _mm_cmpeq_epi8(v, _mm_set1_epi8(static_cast<char>(kUnreachable)));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(cost.data()),
                     _mm_or_si128(_mm_subs_epu8(v, _mm_set1_epi8(static_cast<char>(least))), unreachable));
#else
    uint8_t least = kUnreachable;
    for (uint8_t c : cost) least = std::min(least, c);
    for (uint8_t& c : cost) c = c == kUnreachable ? c : static_cast<uint8_t>(c - least);
#endif
    if (least == kUnreachable) throw InternalError("encode_triangle_strip: no encoding found");
    return least;
}

void check_face(const Triangle& f, size_t j) {
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2])
        throw InternalError("encode_triangle_strip: face " + std::to_string(j) + " repeats a vertex");
}

}  // namespace

std::vector<uint32_t> encode_triangle_strip(std::span<const Triangle> faces) {
    const size_t n = faces.size();
    if (n == 0) return {};
    for (size_t j = 0; j < n; ++j) check_face(faces[j], j);

    const Tables& tab = tables();
    const std::array<Transition, kStates>& first = tab.first;
    const std::array<std::optional<Matrix>, 64>& cache = tab.step;
    std::vector<uint8_t> pattern(n, 0);                 // pattern key of step j-1 -> j
    std::vector<std::array<uint8_t, kStates>> back(n);  // best predecessor state
    // Costs relative to the cheapest state, base + cost[t] in all (the bounds: top of the file).
    Lanes cost;
    cost.fill(kUnreachable);
    for (int t = 0; t < kStates; ++t) cost[t] = first[t].cost;
    uint64_t base = normalise(cost);
    for (size_t j = 0; j + 1 < n; ++j) {
        const Triangle labels = relabel(faces[j], faces[j + 1], j);
        const int key = pattern_key(labels);
        pattern[j + 1] = static_cast<uint8_t>(key);
        if (!cache[key]) throw InternalError("encode_triangle_strip: no table for an overlap pattern");
        const Lanes best_from = relax(cost, tab.rows[key]);
        std::copy_n(best_from.begin(), kStates, back[j + 1].begin());
        if ((j & 15) == 15) base += normalise(cost);  // 6 + 16 x 6 < kUnreachable
    }

    std::vector<uint8_t> state(n);
    state[n - 1] = 0;
    for (uint8_t t = 1; t < kStates; ++t)
        if (cost[t] < cost[state[n - 1]]) state[n - 1] = t;
    if (cost[state[n - 1]] == kUnreachable) throw InternalError("encode_triangle_strip: no encoding found");
    for (size_t j = n - 1; j >= 1; --j) state[j - 1] = back[j][state[j]];

    std::vector<uint32_t> out;
    out.reserve(static_cast<size_t>(base + cost[state[n - 1]]));
    const Transition& t0 = first[state[0]];
    for (int k = 0; k < t0.len; ++k) out.push_back(faces[0][t0.labels[k]]);
    for (size_t j = 1; j < n; ++j) {
        const Transition& t = (*cache[pattern[j]])[state[j - 1]][state[j]];
        uint32_t extra = 0;  // label 3: the vertex of faces[j] that faces[j-1] lacks
        for (uint32_t v : faces[j])
            if (v != faces[j - 1][0] && v != faces[j - 1][1] && v != faces[j - 1][2]) extra = v;
        for (int k = 0; k < t.len; ++k) out.push_back(t.labels[k] == 3 ? extra : faces[j - 1][t.labels[k]]);
    }
    return out;
}

std::vector<Triangle> decode_triangle_strip(const std::vector<uint32_t>& indices, std::optional<uint32_t> restart) {
    std::vector<Triangle> out;
    size_t begin = 0;  // first index of the current strip: parity counts from there
    for (size_t i = 0; i + 2 < indices.size(); ++i) {
        const uint32_t a = indices[i], b = indices[i + 1], c = indices[i + 2];
        if (restart && a == *restart) {
            begin = i + 1;
            continue;
        }
        if (restart && (b == *restart || c == *restart)) continue;
        if (a == b || b == c || a == c) continue;
        out.push_back((i - begin) % 2 == 0 ? Triangle{a, b, c} : Triangle{b, a, c});
    }
    return out;
}

const char* join_mode_name(JoinMode mode) noexcept {
    return mode == JoinMode::Restart ? "restart" : "degenerate";
}

std::optional<JoinMode> parse_join_mode(std::string_view name) noexcept {
    if (name == "degenerate") return JoinMode::Degenerate;
    if (name == "restart") return JoinMode::Restart;
    return std::nullopt;
}

std::vector<uint32_t> join_strips(const std::vector<std::vector<uint32_t>>& strips, JoinMode mode, uint32_t restart) {
    std::vector<uint32_t> out;
    for (const auto& s : strips) {
        if (s.empty()) throw InternalError("join_strips: empty strip");
        if (!out.empty()) {
            if (mode == JoinMode::Restart) {
                out.push_back(restart);
            } else {
                // The next strip must start at an even position to keep its windings.
                const uint32_t last = out.back();
                out.push_back(last);
                out.push_back(s.front());
                if (out.size() % 2 == 1) out.push_back(s.front());
            }
        }
        out.insert(out.end(), s.begin(), s.end());
    }
    return out;
}

}  // namespace singlestrip
