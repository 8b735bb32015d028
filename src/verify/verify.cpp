// singlestrip — the independent verifier (see verify.hpp for the list of checks): verify() runs
// the check families in order (their files: verify_checks.hpp); here also the report's text, and
// the checks of the vertices and of the topology.
//
// Independence: the verifier has its own adjacency (hash maps keyed by vertex pairs), its own
// strip decoder and its own tree-cotree; it includes nothing from mesh.hpp, strip.hpp or
// encode.hpp. Geometry is in plain doubles with relative tolerances (kRelTol).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/verify.hpp"
#include "verify_attributes.hpp"
#include "verify_checks.hpp"

namespace singlestrip {

namespace verify_detail {

// The tolerances of every geometric test (verify_checks.hpp), set by verify() for its duration.
thread_local double kRelTol = 1e-9;
thread_local double kFloatSlack = 0;

namespace {

struct ToleranceScope {
    explicit ToleranceScope(bool float32) : saved(kRelTol), saved_slack(kFloatSlack) {
        kRelTol = float32 ? 1e-5 : 1e-9;
        kFloatSlack = float32 ? 4.0 / (1 << 23) : 0.0;
    }
    ~ToleranceScope() {
        kRelTol = saved;
        kFloatSlack = saved_slack;
    }
    ToleranceScope(const ToleranceScope&) = delete;
    ToleranceScope& operator=(const ToleranceScope&) = delete;
    double saved, saved_slack;
};

// Input vertices unchanged (as a float32 file holds them), every coordinate finite.
void check_vertices(const VerifyInput& in, Failures& fails, VerifyReport& report) {
    const size_t n = in.in_points.size();
    if (in.out_points.size() < n) {
        fails.add("vertices",
                  "output has " + std::to_string(in.out_points.size()) + " vertices, fewer than the input's " + std::to_string(n));
    }
    auto as_stored = [&](const Point3& p) {  // what a float32 file can hold of an input vertex
        return in.float32 ? Point3{static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])} : p;
    };
    if (in.float32)
        report.notes.push_back(
            "float32 positions (glTF): input vertices compared after rounding to float32; geometric tolerances "
            "1e-5 relative (instead of 1e-9) plus 4 float32 ulps of the coordinates; parents inferred");
    for (size_t v = 0; v < std::min(n, in.out_points.size()); ++v)
        if (!(in.out_points[v] == as_stored(in.in_points[v])))
            fails.add("vertices", "vertex " + std::to_string(v) + " moved (input vertices must be unchanged)");
    for (size_t v = 0; v < in.out_points.size(); ++v)
        for (double c : in.out_points[v])
            if (!std::isfinite(c)) {
                fails.add("vertices", "vertex " + std::to_string(v) + " has a non-finite coordinate");
                break;
            }
}

// The output's Euler characteristic and boundary loops are the input's.
void check_topology(const Adjacency& inp, const Adjacency& out, Failures& fails, VerifyReport& report) {
    for (const auto& p : out.problems) fails.add("manifold", p);
    report.output_vertices = static_cast<size_t>(out.referenced_vertices);
    report.euler_characteristic = out.euler;
    report.boundary_loops = out.boundary_loops;
    if (out.euler != inp.euler)
        fails.add("topology",
                  "Euler characteristic " + std::to_string(out.euler) + " differs from the input's " + std::to_string(inp.euler));
    if (out.boundary_loops != inp.boundary_loops)
        fails.add("topology",
                  std::to_string(out.boundary_loops) + " boundary loop(s), the input has " + std::to_string(inp.boundary_loops));
}

}  // namespace

}  // namespace verify_detail

using namespace verify_detail;

std::string VerifyReport::to_string() const {
    std::ostringstream os;
    if (ok()) {
        os << "OK: " << output_faces << " output faces (" << input_faces << " input), Euler characteristic " << euler_characteristic << ", "
           << boundary_loops << " boundary loop(s), genus " << genus;
        if (strips > 1) os << ", " << strips << " strips (one per component)";
        if (cycles_checked) os << ", " << cycles_checked << " independent cycles";
        os << "\n";
    } else {
        os << "FAILED: " << failures.size() << " problem line(s)\n";
        for (const auto& f : failures) os << "  " << f << "\n";
    }
    for (const auto& n : notes) os << "  note: " << n << "\n";
    return os.str();
}

std::vector<Triangle> verify_decode_strip(const std::vector<uint32_t>& indices, uint32_t restart_index) {
    return gl_decode(indices, restart_index);
}

VerifyReport verify(const VerifyInput& in) {
    const ToleranceScope tolerance(in.float32);
    VerifyReport report;
    Failures fails(report);
    report.input_faces = in.in_faces.size();
    report.output_faces = in.out_faces.size();

    // The input is the reference everything is compared with.
    const Adjacency inp = build_adjacency(in.in_points.size(), in.in_faces, "input");
    if (!inp.manifold || in.in_faces.empty()) {
        for (const auto& p : inp.problems) fails.add("input", p);
        if (in.in_faces.empty()) fails.add("input", "no faces");
        report.notes.push_back("input is not a valid manifold mesh; output not checked");
        fails.finish();
        return report;
    }
    check_vertices(in, fails, report);
    if (in.out_faces.empty()) {
        fails.add("faces", "output has no faces");
        fails.finish();
        return report;
    }
    const Adjacency out = build_adjacency(in.out_points.size(), in.out_faces, "output");
    check_topology(inp, out, fails, report);
    Checked chk{in, inp, out, resolve_parents(in, out, fails), fails, report};
    check_geometry(chk);
    std::vector<std::string> attribute_failures;
    verify_detail::check_attributes(in, chk.parent, attribute_failures, report.notes);
    for (const std::string& f : attribute_failures) fails.add("attributes", f);
    check_boundary_tiling(chk);
    size_t num_components = 0;
    const std::vector<uint32_t> strip_end = check_strips(chk, num_components);
    check_indices(chk);
    check_constraints(chk);
    check_source_target(chk, strip_end.front());
    check_cycles_request(chk, num_components);
    fails.finish();
    return report;
}

}  // namespace singlestrip
