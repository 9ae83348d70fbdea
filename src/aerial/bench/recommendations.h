#pragma once
// What a user should pick, one line per use, from a bench run's own figures at the figure tier:
// which path for real-time frames, which tables for which suns, what to render references with.
#include <string>
#include <vector>

#include "aerial/bench/bench_results.h"

namespace aerial::bench {

// The views a recommendation reads (bench_plan.h's views): daylight and a low sun.
inline constexpr const char* kDaylightViews[] = {"noon", "afternoon", "high-altitude"};
inline constexpr const char* kLowSunViews[] = {"sunset", "twilight"};

// Above this relative RMSE against the 4D tables in daylight, the 3D tables are not recommended
// even where memory is tight: 1%, about what one table read is good to (docs/accuracy.md, "Accuracy").
inline constexpr double kDaylightTolerance = 0.01;

// Markdown lines, each starting with "- **use**:".
std::vector<std::string> Recommendations(const BenchResults& b);

}  // namespace aerial::bench
