// Internal: stripify() for a soup with several edge-connected components (pipeline.hpp, "Several
// components"): one strip per component, joined into one output.
#pragma once

#include <cstdint>
#include <vector>

#include "singlestrip/pipeline.hpp"

namespace singlestrip::detail {

/// Strips every component of r.input (comp[f] = component of face f, `count` components) and
/// fills r.strip.stats (totals), r.arrays, r.indices, r.components and r.cycles (when asked).
/// `twin`: the analysis' edge pairing of r.input (PreparedSoup::twin), or empty; each component
/// is built from its part of it, without pairing its half-edges again.
/// \pre r.input passed prepare_soup(); r.options is the request. \throw RequestError for a seed
/// face, source, target or constraint that cannot be met (naming the component); InternalError
/// on a bug. Complexity: build_strip() per component plus O(V + F); one component's soup and mesh
/// at a time beside r.input.
void strip_components(PipelineResult& r, const std::vector<uint32_t>& comp, uint32_t count, std::vector<uint32_t> twin,
                      PipelineStage* stage);

}  // namespace singlestrip::detail
