#pragma once
// The 4D and 3D table variants measured in one process, their runs interleaved (run i: 4D then
// 3D) so that both see the same machine noise: time and memory of each, and the 3D/4D ratios.
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "aerial/bench/precompute_report.h"

namespace aerial::bench {

// The kind a pass is compared by: "incident radiance" and "scattering density" count together
// as "density", and "accumulate" with "multiple scattering", the order ignored.
std::string ComparisonKind(const std::string& pass);

// The median ms of each pass, or of each group of passes by key (ComparisonKind, PassKind...),
// in pass order.
std::vector<std::pair<std::string, double>> PassMedians(
    const BenchResult& result, const std::function<std::string(const std::string&)>& key);

// Ratios 3D / 4D of medians over the runs (< 1: the 3D variant is cheaper).
struct VariantRatios {
  double gpu = 0.0, wall = 0.0, memory = 0.0;
  std::vector<std::pair<std::string, double>> kinds;  // by ComparisonKind, in pass order
};
VariantRatios CompareVariants(const BenchResult& lut4d, const BenchResult& lut3d);

// One variant's precompute: its ReportDoc plus "variant", "precompute_ms" (median GPU time),
// "wall_ms" and "pass_median_ms".
nlohmann::json VariantJson(const BenchResult& result);

void PrintComparison(const BenchResult& lut4d, const BenchResult& lut3d, std::FILE* out);
// Both variants: "variants" lists the VariantJson of each, "ratios" holds CompareVariants.
std::string ComparisonJson(const BenchResult& lut4d, const BenchResult& lut3d);

}  // namespace aerial::bench
