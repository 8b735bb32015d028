// libFuzzer target for one mesh reader (FUZZ_FORMAT selects it; see fuzz/CMakeLists.txt).
// The fuzz bytes are the file. read_mesh_file() must return a usable soup or throw InputError;
// a small soup that it returns then goes through the whole checked pipeline (check_pipeline.hpp).
// The ASCII/binary variants of PLY and STL share a reader: each target skips (returns -1, so
// libFuzzer does not keep the input) files of the other kind, so its corpus stays on its kind.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <string_view>

#include "check_pipeline.hpp"
#include "fuzz_common.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"

namespace {

enum Format { kObj, kOff, kPlyAscii, kPlyBinary, kStlAscii, kStlBinary };
constexpr Format kFormat = FUZZ_FORMAT;

const char* extension() {
    switch (kFormat) {
        case kObj:
            return ".obj";
        case kOff:
            return ".off";
        case kPlyAscii:
        case kPlyBinary:
            return ".ply";
        case kStlAscii:
        case kStlBinary:
            return ".stl";
    }
    return ".bin";
}

/// Whether the input belongs to this target's variant.
bool wanted(std::string_view s) {
    switch (kFormat) {
        case kPlyAscii:
            return s.substr(0, 512).find("format binary") == std::string_view::npos;
        case kPlyBinary:
            return s.substr(0, 512).find("format binary") != std::string_view::npos;
        case kStlAscii:
        case kStlBinary: {
            const size_t first = s.find_first_not_of(" \t\r\n");
            const bool solid = first != std::string_view::npos && s.substr(first, 5) == "solid";
            return kFormat == kStlAscii ? solid : !solid;
        }
        default:
            return true;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace singlestrip;
    if (!wanted(std::string_view(reinterpret_cast<const char*>(data), size))) return -1;
    const std::string path = fuzzcheck::write_temp(data, size, extension());
    TriangleSoup soup;
    try {
        soup = read_mesh_file(path);
    } catch (const InputError& e) {
        if (std::strncmp(e.what(), path.c_str(), path.size()) != 0)
            fuzzcheck::finding(std::string("InputError message does not start with the path: ") + e.what());
        return 0;
    } catch (const std::bad_alloc&) {
        fuzzcheck::finding("read_mesh_file: std::bad_alloc (a declared count was trusted?)");
    } catch (const std::exception& e) {
        fuzzcheck::finding(std::string("read_mesh_file threw a non-InputError: ") + typeid(e).name() + ": " + e.what());
    }
    if (auto p = fuzzcheck::check_soup(soup); !p.empty()) fuzzcheck::finding(p);
    if (soup.triangles.size() <= 2000) {
        fuzzcheck::Request req;
        req.orient = size % 2 == 0;  // both with and without re-orientation, cheaply
        if (auto p = fuzzcheck::check_pipeline(std::move(soup), req); !p.empty()) fuzzcheck::finding(p);
    }
    return 0;
}
