#include "aerial/bench/heatmap.h"

#include <gtest/gtest.h>

#include "aerial/bench/picture_test_util.h"

namespace aerial::bench {
namespace {

TEST(NiceCeiling, OneTwoFiveSteps) {
  EXPECT_DOUBLE_EQ(NiceCeiling(0.013), 0.02);
  EXPECT_DOUBLE_EQ(NiceCeiling(0.05), 0.05);
  EXPECT_DOUBLE_EQ(NiceCeiling(0.051), 0.1);
  EXPECT_DOUBLE_EQ(NiceCeiling(3.0), 5.0);
}

TEST(FormatPercent, NoTrailingZeros) {
  EXPECT_EQ(FormatPercent(0.025), "2.5%");
  EXPECT_EQ(FormatPercent(0.0), "0%");
  EXPECT_EQ(FormatPercent(2.0), "200%");
}

TEST(HeatColor, EndsOfInfernoAndClamped) {
  EXPECT_EQ(HeatColor(0.0), (Rgb{0, 0, 4}));
  EXPECT_EQ(HeatColor(1.0), (Rgb{252, 255, 164}));
  EXPECT_EQ(HeatColor(7.0), (Rgb{252, 255, 164}));
}

// Each value over the scale through HeatColor, in order; above the scale clamps to its top.
TEST(HeatMapRgba8, EachValueOverTheScale) {
  std::vector<uint8_t> rgba8 = HeatMapRgba8({0.0f, 0.25f, 0.5f, 2.0f}, 0.5);
  Picture map{4, 1, rgba8};
  ASSERT_EQ(rgba8.size(), size_t(16));
  EXPECT_EQ(map.At(0, 0), HeatColor(0.0));
  EXPECT_EQ(map.At(1, 0), HeatColor(0.5));
  EXPECT_EQ(map.At(2, 0), HeatColor(1.0));
  EXPECT_EQ(map.At(3, 0), HeatColor(1.0));
  for (size_t i = 3; i < rgba8.size(); i += 4) EXPECT_EQ(rgba8[i], 255) << "opaque";
}

}  // namespace
}  // namespace aerial::bench
