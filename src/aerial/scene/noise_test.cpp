#include "aerial/scene/noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace aerial {
namespace {

// The tables' gradient against the cosine and sine of its angle, over 2^24 / 4099 angles spread
// through every coarse and fine table entry, and the ends. Four table values and three operations
// each round by at most half a unit in the last place of a number below 2 (2.2e-16): 1.6e-15 at
// worst (measured: 8.3e-16).
TEST(UnitGradient, IsTheCosineAndSineOfTheHashsAngle) {
  double worst = 0.0, worst_norm = 0.0;
  auto check = [&](uint32_t k) {
    uint32_t h = k << 8;
    double angle = 2.0 * std::numbers::pi * UnitFromHash(h);
    std::array<double, 2> g = UnitGradient(h);
    worst = std::max({worst, std::fabs(g[0] - std::cos(angle)), std::fabs(g[1] - std::sin(angle))});
    worst_norm = std::max(worst_norm, std::fabs(std::hypot(g[0], g[1]) - 1.0));
  };
  for (uint32_t k = 0; k < (1u << 24); k += 4099) check(k);
  for (uint32_t k : {1u, 4095u, 4096u, 4097u, (1u << 24) - 1}) check(k);
  EXPECT_LT(worst, 1.6e-15);
  EXPECT_LT(worst_norm, 1.6e-15);
  // The low 8 bits of the hash do not choose the gradient, as they do not choose UnitFromHash.
  EXPECT_EQ(UnitGradient(0x12345600u), UnitGradient(0x123456ffu));
}

// Gradient noise is zero at the lattice points and within the 2D extreme sqrt(2)/2 elsewhere.
TEST(GradientNoise, ZeroOnTheLatticeAndBoundedBetween) {
  double largest = 0.0;
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j) {
      double x = -50.0 + i * 0.5137, y = 20.0 + j * 0.4871;
      largest = std::max(largest, std::fabs(GradientNoise(x, y, 7)));
    }
  EXPECT_LE(largest, std::sqrt(0.5) + 1e-12);
  EXPECT_GT(largest, 0.3) << "the noise varies";
  for (int i = -3; i <= 3; ++i) EXPECT_EQ(GradientNoise(i, 2 * i, 11), 0.0);
}

}  // namespace
}  // namespace aerial
