// Several edge-connected components (src/pipeline/components.cpp): parts built one at a time,
// stripped on two threads once the mesh is large, appended in part order. The results must not
// depend on which thread took a part, nor on release_intermediates.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fixtures.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/verify.hpp"
#include "strip_check.hpp"

namespace singlestrip {
namespace {

void append(TriangleSoup& s, const TriangleSoup& part, double shift) {
    const auto base = static_cast<uint32_t>(s.points.size());
    for (Point3 p : part.points) s.points.push_back({p[0] + shift, p[1], p[2]});
    for (Triangle t : part.triangles) s.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

/// 24 parts of 4 to 2,400 faces (about 20,000 in all: two threads), of genus 0 and 1, closed
/// and with boundary, so that parts finish out of order.
TriangleSoup many_parts() {
    TriangleSoup s;
    for (uint32_t i = 0; i < 24; ++i) {
        const TriangleSoup part = i % 3 == 0   ? make_torus(10 + 5 * i, 8 + i)
                                  : i % 3 == 1 ? make_icosphere(1 + i % 4)
                                               : make_grid_disk(3 + i, 4);
        append(s, part, 100.0 * i);
    }
    return s;
}

class Parts : public EngineTest {};

TEST_P(Parts, TwoThreadsGiveWhatOnePartAtATimeGives) {
    const TriangleSoup s = many_parts();
    ASSERT_GE(s.triangles.size(), size_t{1} << 14);
    PipelineOptions o;
    o.strip = opts();
    o.self_check = true;
    o.cycles = true;
    o.strip.source = VertexId(s.triangles[s.triangles.size() / 2][0]);  // a later part goes first
    const PipelineResult kept = stripify(s, o);
    ASSERT_EQ(kept.components.size(), 24u);
    EXPECT_EQ(kept.components[0].first_face, 0u);
    EXPECT_EQ(kept.indices, degenerate_joined_indices(kept));
    VerifyInput vi = verify_input(s, kept.arrays, kept.indices);
    vi.source = o.strip.source->idx();
    const VerifyReport rep = verify(vi);
    EXPECT_TRUE(rep.ok()) << rep.to_string();
    EXPECT_EQ(rep.strips, 24u);
    // Each component's own strip, alone, is the same strip (same faces, same indices).
    size_t cycles = 0;
    for (const ComponentStrip& c : kept.components) {
        std::vector<Triangle> faces(kept.arrays.faces.begin() + static_cast<std::ptrdiff_t>(c.first_face),
                                    kept.arrays.faces.begin() + static_cast<std::ptrdiff_t>(c.first_face + c.output_triangles));
        EXPECT_EQ(encode_triangle_strip(faces).size(), c.strip_indices);
        cycles += 2 * static_cast<size_t>(c.genus) + c.boundary_loops - (c.boundary_loops > 0 ? 1 : 0);
    }
    ASSERT_TRUE(kept.cycles.has_value());
    EXPECT_EQ(kept.cycles->cycles.size(), cycles);
    // Lean: the same output, the input released.
    o.release_intermediates = true;
    const PipelineResult lean = stripify(s, o);
    EXPECT_EQ(lean.indices, kept.indices);
    EXPECT_EQ(lean.arrays.faces, kept.arrays.faces);
    EXPECT_EQ(lean.arrays.parent, kept.arrays.parent);
    EXPECT_EQ(lean.arrays.points, kept.arrays.points);
    ASSERT_TRUE(lean.cycles.has_value());
    EXPECT_EQ(lean.cycles->cycles, kept.cycles->cycles);
    EXPECT_TRUE(lean.input.triangles.empty());
}

TEST_P(Parts, TheFirstFailingPartInOrderIsTheOneNamed) {
    // Constraint walls that cut two parts apart (the 5th and the 20th): the error names the 5th,
    // whichever thread reached which first.
    const TriangleSoup s = many_parts();
    PipelineOptions o;
    o.strip = opts();
    uint32_t face = 0;
    std::vector<uint32_t> first_face;
    for (uint32_t i = 0; i < 24; ++i) {
        first_face.push_back(face);
        const TriangleSoup part = i % 3 == 0   ? make_torus(10 + 5 * i, 8 + i)
                                  : i % 3 == 1 ? make_icosphere(1 + i % 4)
                                               : make_grid_disk(3 + i, 4);
        face += static_cast<uint32_t>(part.triangles.size());
    }
    for (const uint32_t part : {19u, 4u}) {  // an icosphere part: wall off one face
        const Triangle& t = s.triangles[first_face[part]];
        for (int k = 0; k < 3; ++k) o.strip.constraint_edges.push_back({t[k], t[(k + 1) % 3]});
    }
    PipelineStage stage = PipelineStage::Done;
    try {
        stripify(s, o, &stage);
        ADD_FAILURE() << "walls around one face cut its component apart";
    } catch (const RequestError& e) {
        EXPECT_NE(std::string(e.what()).find("component 4 of 24"), std::string::npos) << e.what();
        EXPECT_EQ(stage, PipelineStage::Strip);
    }
}

INSTANTIATE_TEST_SUITE_P(Engines, Parts, kBothEngines, engine_test_name);

}  // namespace
}  // namespace singlestrip
