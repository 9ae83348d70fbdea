#pragma once
// What the tables' texels mean (their coordinate mappings, the orders the irradiance holds):
// part of the cache key (PrecomputeOptions::Hash), raised whenever a change makes tables computed
// before it wrong.

namespace aerial {

inline constexpr int kTableLayout = 21;

}  // namespace aerial
