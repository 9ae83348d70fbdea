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

}  // namespace
}  // namespace aerial::bench
