// singlestrip — matching engine (work in progress: delegates to the growth builder).
#include "singlestrip/strip.hpp"

namespace singlestrip {

StripResult build_strip_matching(Mesh mesh, const StripOptions& options) {
    StripResult r = build_strip_growth(std::move(mesh), options);
    r.stats.engine = StripEngine::Matching;
    return r;
}

}  // namespace singlestrip
