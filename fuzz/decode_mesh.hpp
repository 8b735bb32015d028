// singlestrip fuzzing — a small oriented manifold (or a deliberately broken soup) decoded from
// fuzz bytes: a generator from tests/support/fixtures.hpp, random edge flips, holes, jittered geometry,
// face shuffles and flips; plus strip options (seed, constraints, source/target, engine).
#pragma once

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <utility>
#include <vector>

#include "check_pipeline.hpp"
#include "fixtures.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/soup.hpp"
#include "singlestrip/strip.hpp"

namespace singlestrip::fuzzcheck {

/// A deterministic number in [0, 1) for geometry jitter.
inline double unit(uint64_t x) {
    return static_cast<double>(splitmix64(x) >> 11) * 0x1.0p-53;
}

/// Moves every vertex by up to +-amount per axis so that no face is degenerate (generators'
/// planar grids can fold into collinear triangles after edge flips; verify() rightly rejects
/// degenerate output faces, which would be a finding about the input, not the builder).
inline void jitter(TriangleSoup& s, uint64_t seed, double amount) {
    for (size_t v = 0; v < s.points.size(); ++v)
        for (int k = 0; k < 3; ++k) s.points[v][k] += amount * (2.0 * unit(seed ^ (v * 3 + k) * 0x100000001b3ull) - 1.0);
}

/// A small mesh from the bytes; the soup may be invalid (raw mode, dropped faces, flipped faces).
inline TriangleSoup decode_soup(FuzzedDataProvider& in) {
    TriangleSoup s;
    const int kind = in.ConsumeIntegralInRange<int>(0, 13);
    auto small = [&](uint32_t lo, uint32_t hi) { return in.ConsumeIntegralInRange<uint32_t>(lo, hi); };
    switch (kind) {
        case 0:
            s = make_single_triangle();
            break;
        case 1:
            s = make_two_triangles();
            break;
        case 2:
            s = make_fan(small(1, 12));
            break;
        case 3:
            s = make_corridor(small(1, 20));
            break;
        case 4:
            s = make_grid_disk(small(1, 9), small(1, 9));
            break;
        case 5:
            s = make_annulus(small(3, 10), small(1, 3));
            break;
        case 6:
            s = make_disk_with_holes(small(0, 3), small(1, 2));
            break;
        case 7:
            s = make_icosphere(small(0, 1));
            break;
        case 8:
            s = make_uv_sphere(small(3, 8), small(2, 6));
            break;
        case 9:
            s = make_torus(small(3, 8), small(3, 6));
            break;
        case 10:
            s = make_genus_surface(small(1, 2), 1);
            break;
        case 11:
            s = make_moebius_soup(small(3, 6));
            break;
        default: {
            // Raw soup: up to 12 vertices in general position, faces from the bytes. Mostly
            // rejected by prepare_soup; those that pass are arbitrary small manifolds.
            const uint32_t nv = small(3, 12);
            for (uint32_t v = 0; v < nv; ++v) s.points.push_back({0, 0, 0});
            const uint32_t nf = small(1, 24);
            for (uint32_t f = 0; f < nf && in.remaining_bytes() > 0; ++f)
                s.triangles.push_back({small(0, nv - 1), small(0, nv - 1), small(0, nv - 1)});
            jitter(s, in.ConsumeIntegral<uint64_t>(), 1.0);
            return s;
        }
    }
    if (s.triangles.empty()) return s;
    // Topology-preserving perturbations (fixtures.hpp); they need an oriented manifold.
    if (kind != 11) {
        if (const size_t flips = in.ConsumeIntegralInRange<size_t>(0, 30)) random_edge_flips(s, flips, in.ConsumeIntegral<uint64_t>());
        if (const size_t holes = in.ConsumeIntegralInRange<size_t>(0, 3)) {
            try {
                remove_random_faces_as_holes(s, holes, in.ConsumeIntegral<uint64_t>());
            } catch (const RequestError&) {
            }
        }
    }
    jitter(s, in.ConsumeIntegral<uint64_t>(), 0.2);
    // Face order and corner rotation do not change the surface.
    const uint32_t nf = static_cast<uint32_t>(s.triangles.size());
    const int shuffles = in.ConsumeIntegralInRange<int>(0, 8);
    for (int i = 0; i < shuffles; ++i) std::swap(s.triangles[small(0, nf - 1)], s.triangles[small(0, nf - 1)]);
    const int rotations = in.ConsumeIntegralInRange<int>(0, 4);
    for (int i = 0; i < rotations; ++i) {
        auto& t = s.triangles[small(0, nf - 1)];
        t = {t[1], t[2], t[0]};
    }
    // Flipped faces (prepare_soup must refuse them, or repair them with orient) and edits
    // that break the surface (a dropped face may disconnect it; a duplicated one is invalid).
    const int flipped = in.ConsumeIntegralInRange<int>(0, 3);
    for (int i = 0; i < flipped; ++i) {
        auto& t = s.triangles[small(0, nf - 1)];
        std::swap(t[1], t[2]);
    }
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0 && nf > 1) s.triangles.erase(s.triangles.begin() + small(0, nf - 1));
    if (in.ConsumeIntegralInRange<int>(0, 31) == 0)
        s.triangles.push_back(s.triangles[small(0, static_cast<uint32_t>(s.triangles.size()) - 1)]);
    return s;
}

/// Strip options from the bytes: seed face, greedy, constraint polylines along mesh edges (and
/// sometimes arbitrary vertex pairs), source/target (sometimes out of range).
inline void decode_options(FuzzedDataProvider& in, const TriangleSoup& s, Request& req) {
    const uint32_t nf = static_cast<uint32_t>(s.triangles.size());
    const uint32_t nv = static_cast<uint32_t>(s.points.size());
    req.orient = in.ConsumeBool();
    req.strip.greedy = in.ConsumeBool();
    req.strip.validate_each_split = in.ConsumeIntegralInRange<int>(0, 7) == 0;
    if (nf == 0 || nv == 0) return;
    if (in.ConsumeBool()) req.strip.seed_face = FaceId(in.ConsumeIntegralInRange<uint32_t>(0, nf + (in.ConsumeBool() ? 2 : 0) - 1));
    const int polylines = in.ConsumeIntegralInRange<int>(0, 3);
    for (int p = 0; p < polylines; ++p) {
        // A walk along face edges: from a face corner, repeatedly step to a vertex of a face
        // that holds the current vertex.
        const Triangle& t0 = s.triangles[in.ConsumeIntegralInRange<uint32_t>(0, nf - 1)];
        uint32_t cur = t0[in.ConsumeIntegralInRange<int>(0, 2)];
        const int steps = in.ConsumeIntegralInRange<int>(1, 6);
        for (int k = 0; k < steps; ++k) {
            std::vector<uint32_t> nbrs;
            for (const auto& t : s.triangles)
                for (int c = 0; c < 3; ++c)
                    if (t[c] == cur) {
                        nbrs.push_back(t[(c + 1) % 3]);
                        nbrs.push_back(t[(c + 2) % 3]);
                    }
            if (nbrs.empty()) break;
            const uint32_t next = nbrs[in.ConsumeIntegralInRange<size_t>(0, nbrs.size() - 1)];
            req.strip.constraint_edges.push_back({cur, next});
            cur = next;
        }
    }
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0)
        req.strip.constraint_edges.push_back({in.ConsumeIntegralInRange<uint32_t>(0, nv), in.ConsumeIntegralInRange<uint32_t>(0, nv - 1)});
    if (in.ConsumeIntegralInRange<int>(0, 3) == 0) req.strip.source = VertexId(in.ConsumeIntegralInRange<uint32_t>(0, nv));
    if (in.ConsumeIntegralInRange<int>(0, 3) == 0) req.strip.target = VertexId(in.ConsumeIntegralInRange<uint32_t>(0, nv));
    req.cycles = in.ConsumeIntegralInRange<int>(0, 3) != 0;
}

/// The strip engine, decoded after everything else so older inputs decode as before. Once the
/// bytes have run out ConsumeBool() is false and the input's length parity picks the engine, so
/// the existing corpus exercises both.
inline StripEngine decode_engine(FuzzedDataProvider& in, size_t size) {
    return in.ConsumeBool() != ((size & 1) != 0) ? StripEngine::Growth : StripEngine::Matching;
}

/// StripOptions::polish, decoded after the engine (older inputs: off once the bytes ran out, and
/// on for one input length in three, so the existing corpus exercises it).
inline bool decode_polish(FuzzedDataProvider& in, size_t size) {
    return in.ConsumeBool() || size % 3 == 0;
}

/// Prints the decoded case as an OFF file plus the options (SINGLESTRIP_FUZZ_VERBOSE=1), so a
/// finding can be replayed with the CLI.
inline void dump(const TriangleSoup& s, const Request& req) {
    std::fprintf(stderr, "OFF\n%zu %zu 0\n", s.points.size(), s.triangles.size());
    for (const auto& p : s.points) std::fprintf(stderr, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
    for (const auto& t : s.triangles) std::fprintf(stderr, "3 %u %u %u\n", t[0], t[1], t[2]);
    std::fprintf(stderr, "# engine=%s orient=%d greedy=%d polish=%d cycles=%d seed_face=%lld source=%lld target=%lld constraints:",
                 engine_name(req.strip.engine), req.orient, req.strip.greedy, req.strip.polish, req.cycles,
                 req.strip.seed_face ? (long long)req.strip.seed_face->idx() : -1LL,
                 req.strip.source ? (long long)req.strip.source->idx() : -1LL,
                 req.strip.target ? (long long)req.strip.target->idx() : -1LL);
    for (const ConstraintEdge& e : req.strip.constraint_edges) std::fprintf(stderr, " %u-%u", e.a, e.b);
    std::fprintf(stderr, "\n");
}

}  // namespace singlestrip::fuzzcheck
