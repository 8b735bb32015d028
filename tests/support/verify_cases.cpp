// Test support: the verifier's shared test cases (verify_cases.hpp).
#include "verify_cases.hpp"

#include <string>

namespace singlestrip::testing {

std::string joined(const VerifyReport& r) {
    std::string s;
    for (const auto& f : r.failures) s += f + "\n";
    for (const auto& n : r.notes) s += "note: " + n + "\n";
    return s;
}

bool has_failure(const VerifyReport& r, const std::string& check, const std::string& needle) {
    for (const auto& f : r.failures)
        if (f.rfind(check + ":", 0) == 0 && f.find(needle) != std::string::npos) return true;
    return false;
}

bool has_failure_prefix(const VerifyReport& r, const std::string& check) {
    return has_failure(r, check);
}

VerifyInput quad() {
    VerifyInput in;
    in.in_points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    in.in_faces = {{0, 1, 2}, {0, 2, 3}};
    in.out_points = in.in_points;
    in.out_faces = in.in_faces;
    in.out_parent = {0, 1};
    return in;
}

VerifyInput split_quad() {
    VerifyInput in = quad();
    in.out_points.push_back({0.5, 0.5, 0});
    in.out_faces = {{0, 1, 4}, {4, 1, 2}, {4, 2, 3}, {0, 4, 3}};
    in.out_parent = {0, 0, 1, 1};
    return in;
}

}  // namespace singlestrip::testing
