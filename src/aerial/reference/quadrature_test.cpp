#include "aerial/reference/quadrature.h"

#include <gtest/gtest.h>

namespace aerial::reference {
namespace {

// n-point Gauss-Legendre is exact for degree 2n - 1: x^7 + x^6 on [0, 2] with n = 4 and x^15 + x^14
// with n = 8. 1e-14 is the nodes' and weights' 16-digit rounding.
TEST(GaussLegendre, ExactForDegreeTwoNMinusOne) {
  double sum4 = 0.0, sum8 = 0.0;
  ForEachGaussLegendreNode(kGaussLegendre4X, kGaussLegendre4W, 0.0, 2.0,
                           [&](double x, double w) { sum4 += w * (std::pow(x, 7) + std::pow(x, 6)); });
  ForEachGaussLegendreNode(kGaussLegendre8X, kGaussLegendre8W, 0.0, 2.0,
                           [&](double x, double w) { sum8 += w * (std::pow(x, 15) + std::pow(x, 14)); });
  EXPECT_NEAR(sum4 / (256.0 / 8.0 + 128.0 / 7.0), 1.0, 1e-14);
  EXPECT_NEAR(sum8 / (65536.0 / 16.0 + 32768.0 / 15.0), 1.0, 1e-14);
}

// Adaptive Gauss-Kronrod meets its relative tolerance on a kink it is not told about and on an
// integrable endpoint singularity: int_0^1 |x - 1/3| dx = 5/18, int_0^1 sqrt(x) dx = 2/3. The
// error estimate |K15 - G7| overestimates, so the actual error must be below the 1e-9 asked.
TEST(IntegrateAdaptive, ReachesToleranceOnKinksAndSingularities) {
  Values<2> v = IntegrateAdaptive<2>(
      [](double x) { return Values<2>{std::abs(x - 1.0 / 3.0), std::sqrt(x)}; }, {0.0, 1.0}, 1e-9);
  EXPECT_NEAR(v[0] / (5.0 / 18.0), 1.0, 1e-9);
  EXPECT_NEAR(v[1] / (2.0 / 3.0), 1.0, 1e-9);
}

}  // namespace
}  // namespace aerial::reference
