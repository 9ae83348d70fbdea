#include "aerial/bench/pass_stats.h"

#include <gtest/gtest.h>

namespace aerial::bench {
namespace {

// A pass's kind drops its order and a spectral precompute's group, so that the report sums a kind
// over every order and group ("transmittance" of each group and the final one included).
TEST(PassKind, DropsTheOrderAndTheSpectralGroup) {
  EXPECT_EQ(PassKind("scattering density (order 3)"), "scattering density");
  EXPECT_EQ(PassKind("[2/4] scattering density (order 3)"), "scattering density");
  EXPECT_EQ(PassKind("[12/16] single scattering"), "single scattering");
  EXPECT_EQ(PassKind("transmittance"), "transmittance");
  EXPECT_EQ(PassKind("[not a group"), "[not a group");
}

// Counts are summed within a run (a pass recorded twice, as a caching frame's opaque scopes) and
// the median taken over runs; runs that did not count leave nothing.
TEST(MedianFragmentInvocations, SumsWithinARunAndTakesTheMedianOverRuns) {
  auto run = [](std::optional<uint64_t> a, std::optional<uint64_t> b) {
    return RunResult{.passes = {{"opaque raster", 1.0, a}, {"sky", 1.0, 7}, {"opaque raster", 1.0, b}}};
  };
  std::vector<RunResult> runs = {run(10, 5), run(40, std::nullopt), run(20, 1)};
  EXPECT_EQ(MedianFragmentInvocations(runs, "opaque raster"), 21.0);
  EXPECT_EQ(MedianFragmentInvocations(runs, "sky"), 7.0);
  EXPECT_EQ(MedianFragmentInvocations(runs, "froxel build"), std::nullopt);
  EXPECT_EQ(MedianFragmentInvocations({run(std::nullopt, std::nullopt)}, "opaque raster"), std::nullopt);
}

// Pairs are divided one by one and the median taken of their ratios (2, 1, 3): 2, where the ratio
// of the medians is 3 / 3.
TEST(MedianPairedRatio, DividesEachPairAndTakesTheMedian) {
  EXPECT_DOUBLE_EQ(MedianPairedRatio({2.0, 3.0, 30.0}, {1.0, 3.0, 10.0}), 2.0);
  EXPECT_DOUBLE_EQ(MedianPairedRatio({2.5, 3.0}, {2.0, 2.0}), 1.375);
  EXPECT_THROW(MedianPairedRatio({1.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(MedianPairedRatio({}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace aerial::bench
