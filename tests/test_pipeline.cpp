// stripify() and report_json(): the one pipeline and the one report every front end uses.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include "fixtures.hpp"
#include "shell.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/report.hpp"

using namespace singlestrip;

using singlestrip::test::test_data;

namespace {}  // namespace

TEST(Pipeline, EachEngineGivesOneConsistentStrip) {
    for (StripEngine engine : {StripEngine::Matching, StripEngine::Growth}) {
        SCOPED_TRACE(engine_name(engine));
        PipelineOptions o;
        o.strip.engine = engine;
        o.cycles = true;
        o.self_check = true;
        PipelineStage stage = PipelineStage::Checks;
        const PipelineResult r = stripify(make_torus(12, 8), o, &stage);
        EXPECT_EQ(stage, PipelineStage::Done);
        EXPECT_EQ(r.strip.stats.engine, engine);
        EXPECT_EQ(r.arrays.faces.size(), r.strip.stats.output_triangles);
        EXPECT_EQ(r.indices, encode_triangle_strip(r.arrays.faces));
        ASSERT_TRUE(r.cycles.has_value());
        EXPECT_EQ(r.cycles->cycles.size(), 2u);  // 2g on a closed surface
        EXPECT_GE(r.seconds.build, 0.0);
        EXPECT_GE(r.seconds.strip, 0.0);
    }
}

TEST(Pipeline, StageTellsWhereItStopped) {
    PipelineStage stage = PipelineStage::Done;
    PipelineOptions o;
    o.name = "moebius";
    try {
        stripify(make_moebius_soup(5), o, &stage);
        FAIL() << "a Moebius strip was accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("moebius: ", 0), 0u) << e.what();
    }
    EXPECT_EQ(stage, PipelineStage::Checks);

    o.strip.seed_face = FaceId(1000);
    EXPECT_THROW(stripify(make_torus(6, 4), o, &stage), RequestError);
    EXPECT_EQ(stage, PipelineStage::Strip);
    EXPECT_STREQ(stage_name(stage), "build_strip");
}

TEST(Pipeline, ConstraintFileIsReadCheckedAndCounted) {
    PipelineOptions o;
    o.constraints_file = test_data("constraints_bad_token.txt");
    PipelineStage stage = PipelineStage::Checks;
    EXPECT_THROW(stripify(read_input(test_data("tetra.off")), o, &stage), InputError);
    EXPECT_EQ(stage, PipelineStage::Constraints);

    o.constraints_file = test_data("constraints_ok.txt");  // 0-1, 1-2, 3-0: a path, not a cut
    const PipelineResult r = stripify(read_input(test_data("tetra.off")), o);
    EXPECT_EQ(r.options.strip.constraint_edges.size(), 3u);
    ReportInput in;
    in.result = &r;
    EXPECT_EQ(nlohmann::json::parse(report_json(in))["options"]["constraint_edges"], 3);
}

namespace {

/// The message of the RequestError stripify() throws for `o` on tetra.off, and the stage it was in.
std::pair<std::string, PipelineStage> constraint_refusal(const PipelineOptions& o) {
    PipelineStage stage = PipelineStage::Checks;
    try {
        stripify(read_input(test_data("tetra.off")), o, &stage);
    } catch (const RequestError& e) {
        return {e.what(), stage};
    }
    return {"(accepted)", stage};
}

}  // namespace

TEST(Pipeline, ConstraintEdgesAreCheckedOnceAndNamedWhereTheUserWroteThem) {
    const std::string file =
        (std::filesystem::temp_directory_path() / ("singlestrip-test-pipeline-" + std::to_string(::getpid()) + ".txt")).string();
    PipelineOptions o;
    o.strip.constraint_edges = {{0, 1}, {2, 2}};  // every pair of distinct tetra vertices is an edge
    EXPECT_EQ(constraint_refusal(o),
              std::make_pair(std::string("constraint 1: (2, 2) is not an edge of the mesh"), PipelineStage::Constraints));

    o.strip.constraint_edges = {{0, 1}};
    std::ofstream(file) << "0 1\n# a comment line\n3 3\n";
    o.constraints_file = file;
    EXPECT_EQ(constraint_refusal(o).first, file + ": line 3: (3, 3) is not an edge of the mesh");
    std::ofstream(file) << "1 2\n4 4\n";
    o.index_base = 1;
    EXPECT_EQ(constraint_refusal(o).first,
              file + ": line 2: (3, 3) is not an edge of the mesh (vertex numbers counted from 0 here: add 1 for the file's numbering)");

    std::ofstream(file) << "\n2 3 4\n";  // 1-based: the pairs (1, 2) and (2, 3), both on line 2
    const PipelineResult r = stripify(read_input(test_data("tetra.off")), o);
    const std::vector<ConstraintEdge> want = {{0, 1, 0}, {1, 2, 2}, {2, 3, 2}};
    EXPECT_EQ(r.options.strip.constraint_edges, want);
    std::filesystem::remove(file);
}

TEST(Pipeline, ReadInputKnowsTheBuiltInModel) {
    EXPECT_TRUE(is_builtin_input("builtin:genus2"));
    EXPECT_FALSE(is_builtin_input("genus2.off"));
    EXPECT_EQ(read_input("builtin:genus2").triangles.size(), make_builtin_model().triangles.size());
    EXPECT_THROW(read_input("builtin:genus9"), RequestError);
}

TEST(Report, KeysOfAResultAndOfAFailedRun) {
    PipelineOptions o;
    o.strip.engine = StripEngine::Growth;
    o.strip.source = VertexId(0);
    o.cycles = true;
    const PipelineResult r = stripify(make_torus(8, 6), o);
    ReportInput in;
    in.input = "torus";
    in.output = "torus.ply";
    in.result = &r;
    in.stage_seconds = true;
    const auto j = nlohmann::json::parse(report_json(in));
    for (const char* key : {"input", "output", "engine", "input_triangles", "output_triangles", "splits", "swaps", "strip_indices",
                            "indices_per_triangle", "extra_percent", "genus", "boundary_loops", "fundamental_triangles", "deferred_regions",
                            "cycles", "cycle_lengths", "cycle_faces_total", "options", "seconds"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j["engine"], "growth");
    EXPECT_EQ(j["options"]["engine"], "growth");
    EXPECT_EQ(j["options"]["source"], 0);
    EXPECT_FALSE(j["options"].contains("target"));
    EXPECT_EQ(j["strip_indices"], r.indices.size());
    EXPECT_DOUBLE_EQ(j["extra_percent"].get<double>(), extra_percent(r.strip.stats));
    for (const char* key : {"read", "build", "strip", "write"}) EXPECT_TRUE(j["seconds"].contains(key)) << key;

    ReportInput failed;
    failed.options = &o;
    failed.outcome = RunOutcome{false, 3, "bad mesh", 0.5};
    const auto f = nlohmann::json::parse(report_json(failed));
    EXPECT_EQ(f["engine"], "growth");
    EXPECT_EQ(f["ok"], false);
    EXPECT_EQ(f["exit_code"], 3);
    EXPECT_EQ(f["error"], "bad mesh");
    EXPECT_EQ(f["seconds"], 0.5);
    EXPECT_FALSE(f.contains("input_triangles"));
    EXPECT_THROW(report_json({}), InternalError);
}
