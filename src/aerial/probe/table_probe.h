#pragma once
// Evaluates the render-time table lookups (shaders/probe/probe.comp) for a batch of view rays.
#include <span>
#include <vector>

#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/probe.h"

namespace aerial {

std::vector<ProbeResult> ProbeTables(const AtmosphereTables& tables,
                                     std::span<const ProbeQuery> queries);

}  // namespace aerial
