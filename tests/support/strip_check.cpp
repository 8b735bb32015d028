#include "strip_check.hpp"

#include "singlestrip/io.hpp"
#include "singlestrip/pipeline.hpp"

namespace singlestrip {

std::string engine_test_name(const ::testing::TestParamInfo<StripEngine>& info) {
    return engine_name(info.param);
}

}  // namespace singlestrip

namespace singlestrip::testing {

StripCheck strip_and_verify(const TriangleSoup& soup, const StripOptions& options) {
    PipelineOptions o;
    o.strip = options;
    o.self_check = true;
    PipelineResult r = stripify(soup, o);
    StripCheck c;
    c.result = std::move(r.strip);
    c.arrays = std::move(r.arrays);
    c.indices = std::move(r.indices);
    VerifyInput in = verify_input(soup, c.arrays, c.indices);
    in.constraints = vertex_pairs(options.constraint_edges);
    in.source = index_of(options.source);
    in.target = index_of(options.target);
    c.report = verify(in);
    return c;
}

std::string describe(const StripCheck& c) {
    const StripStats& s = c.result.stats;
    return "in " + std::to_string(s.input_triangles) + " out " + std::to_string(s.output_triangles) + " splits " +
           std::to_string(s.splits) + " swaps " + std::to_string(s.swaps) + " indices " + std::to_string(c.indices.size()) + "\n" +
           c.report.to_string();
}

}  // namespace singlestrip::testing
