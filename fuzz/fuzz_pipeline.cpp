// libFuzzer target for the whole pipeline: a small mesh and options (engine included) decoded
// from the bytes (decode_mesh.hpp), run through check_pipeline.hpp; every successful result must
// pass verify().
#include <cstdint>
#include <cstdlib>

#include "check_pipeline.hpp"
#include "decode_mesh.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace singlestrip;
    FuzzedDataProvider in(data, size);
    TriangleSoup soup;
    try {
        soup = fuzzcheck::decode_soup(in);
    } catch (const RequestError&) {
        return 0;  // generator parameters out of range: not an input we want
    }
    fuzzcheck::Request req;
    fuzzcheck::decode_options(in, soup, req);
    req.strip.engine = fuzzcheck::decode_engine(in, size);
    req.strip.polish = fuzzcheck::decode_polish(in, size);
    if (std::getenv("SINGLESTRIP_FUZZ_VERBOSE")) fuzzcheck::dump(soup, req);
    if (auto p = fuzzcheck::check_pipeline(std::move(soup), req); !p.empty()) fuzzcheck::finding(p);
    return 0;
}
