// singlestrip — the verifier's strip checks: its own GL_TRIANGLE_STRIP decoder, one contiguous
// strip per edge-connected component, and the index sequence decoding to the output's faces.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "verify_checks.hpp"

namespace singlestrip::verify_detail {

// Pieces between restart values are separate strips, each starting at even parity.
std::vector<Triangle> gl_decode(const std::vector<uint32_t>& s, uint32_t restart) {
    std::vector<Triangle> out;
    size_t piece = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == restart) {
            piece = i + 1;
            continue;
        }
        if (i < piece + 2 || s[i - 1] == restart || s[i - 2] == restart) continue;
        const uint32_t a = s[i - 2], b = s[i - 1], c = s[i];
        if (a == b || b == c || a == c) continue;
        out.push_back(((i - 2 - piece) % 2 == 0) ? Triangle{a, b, c} : Triangle{b, a, c});
    }
    return out;
}
namespace {

/// Edge-connected component of every output face (through manifold twins), numbered in order of
/// first appearance; `count` gets their number.
std::vector<uint32_t> out_components(const Adjacency& out, size_t& count) {
    const size_t F = out.faces.size();
    std::vector<uint32_t> comp(F, kNo);
    count = 0;
    std::vector<uint32_t> stack;
    for (uint32_t s = 0; s < F; ++s) {
        if (comp[s] != kNo) continue;
        comp[s] = static_cast<uint32_t>(count);
        stack.assign(1, s);
        while (!stack.empty()) {
            const uint32_t f = stack.back();
            stack.pop_back();
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t t = out.twin[3 * f + k];
                if (t != kNo && comp[t / 3] == kNo) {
                    comp[t / 3] = static_cast<uint32_t>(count);
                    stack.push_back(t / 3);
                }
            }
        }
        ++count;
    }
    return comp;
}
bool same_cyclic(const Triangle& a, const Triangle& b) {
    for (int r = 0; r < 3; ++r)
        if (a[0] == b[r] && a[1] == b[(r + 1) % 3] && a[2] == b[(r + 2) % 3]) return true;
    return false;
}
}  // namespace

uint32_t common_vertices(const Triangle& a, const Triangle& b, std::array<uint32_t, 3>& out) {
    uint32_t n = 0;
    for (uint32_t x : a)
        if (x == b[0] || x == b[1] || x == b[2]) out[n++] = x;
    return n;
}
// One strip per edge-connected component of the output, each a contiguous run of faces in which
// consecutive faces share an edge; a new strip starts exactly where the component changes.
// Returns the last face of each strip; `num_components` receives the output's components.
std::vector<uint32_t> check_strips(const Checked& chk, size_t& num_components) {
    const VerifyInput& in = chk.in;
    const Adjacency& out = chk.out;
    Failures& fails = chk.fails;
    VerifyReport& report = chk.report;
    const size_t F = chk.num_faces();
    // in which consecutive faces share an edge; a new strip starts exactly where the component changes.
    const std::vector<uint32_t> comp = out_components(out, num_components);
    std::vector<uint32_t> strip_end;  // last face of each strip
    {
        std::vector<bool> seen(num_components, false);
        seen[comp[0]] = true;
        for (uint32_t f = 0; f + 1 < F; ++f) {
            if (comp[f + 1] != comp[f]) {
                strip_end.push_back(f);
                if (seen[comp[f + 1]])
                    fails.add("strip", "face " + std::to_string(f + 1) +
                                           " returns to an edge-connected component already stripped "
                                           "(each component must be one contiguous strip)");
                seen[comp[f + 1]] = true;
                continue;
            }
            if (!out.face_ok[f] || !out.face_ok[f + 1]) continue;
            std::array<uint32_t, 3> common{};
            const uint32_t k = common_vertices(in.out_faces[f], in.out_faces[f + 1], common);
            if (k != 2)
                fails.add("strip", "faces " + std::to_string(f) + " and " + std::to_string(f + 1) + " share " + std::to_string(k) +
                                       " vertices, not an edge");
        }
        strip_end.push_back(static_cast<uint32_t>(F - 1));
        report.strips = strip_end.size();
        report.genus = (2 * static_cast<long long>(num_components) - out.euler - static_cast<long long>(out.boundary_loops)) / 2;
    }
    return strip_end;
}

// The index sequence decodes to exactly the output's faces, in order, with their winding.
void check_indices(const Checked& chk) {
    const VerifyInput& in = chk.in;
    Failures& fails = chk.fails;
    const size_t F = chk.num_faces();
    if (in.indices) {
        const auto& s = *in.indices;
        bool range_ok = true;
        for (size_t i = 0; i < s.size(); ++i)
            if (s[i] >= in.out_points.size() && s[i] != in.restart_index) {
                fails.add("indices", "index " + std::to_string(i) + " = " + std::to_string(s[i]) + " out of range (" +
                                         std::to_string(in.out_points.size()) + " vertices)");
                range_ok = false;
            }
        if (range_ok) {
            const auto dec = gl_decode(s, in.restart_index);
            if (dec.size() != F)
                fails.add("indices",
                          "index sequence decodes to " + std::to_string(dec.size()) + " triangles, the output has " + std::to_string(F));
            for (size_t f = 0; f < std::min(dec.size(), F); ++f)
                if (!same_cyclic(dec[f], in.out_faces[f])) {
                    const bool flipped = same_cyclic({dec[f][1], dec[f][0], dec[f][2]}, in.out_faces[f]);
                    fails.add("indices", "decoded triangle " + std::to_string(f) + " " + tri_str(dec[f]) +
                                             (flipped ? " has the opposite winding of face " : " differs from face ") + std::to_string(f) +
                                             " " + tri_str(in.out_faces[f]));
                }
        }
    }
}

}  // namespace singlestrip::verify_detail
