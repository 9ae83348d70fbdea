#include "aerial/validation/image_metrics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aerial::validation {
namespace {

// A bright pixel 10% off and a dark one 100% off: the energy-weighted error is the bright pixel's
// (the per-pixel RMS of the same errors would be 71%); masked to the dark pixel, it is 100%.
TEST(EnergyWeightedRelativeRmse, WeighsErrorsByTheReferencesEnergy) {
  ImageRgbF expected{2, 1, {10, 10, 10, 1, 0.01f, 0.01f, 0.01f, 1}};
  ImageRgbF actual{2, 1, {11, 11, 11, 1, 0.02f, 0.02f, 0.02f, 1}};
  double both = std::sqrt((3 * 1.0 + 3 * 1e-4) / (3 * 100.0 + 3 * 1e-4));
  EXPECT_NEAR(EnergyWeightedRelativeRmse(actual, expected), both, 1e-7);
  EXPECT_NEAR(both, 0.1, 1e-5);
  std::vector<bool> dark = {false, true};
  EXPECT_NEAR(EnergyWeightedRelativeRmse(actual, expected, &dark), 1.0, 1e-6);
}

TEST(CompareSamples, RmsAndMaximumOfRelativeErrors) {
  // Channel errors 10%, 0, 0 and 20%, 0, 0: RMS over 6 values sqrt((0.01 + 0.04) / 6).
  std::vector<PixelSample> samples = {{{1.1, 2.0, 3.0}, {1.0, 2.0, 3.0}, 4, 5},
                                      {{0.8, 2.0, 3.0}, {1.0, 2.0, 3.0}, 6, 7}};
  ErrorStats e = CompareSamples(samples);
  EXPECT_EQ(e.pixels, 2);
  EXPECT_NEAR(e.per_pixel_rel_rmse, std::sqrt(0.05 / 6.0), 1e-12);
  EXPECT_NEAR(e.rel_max, 0.2, 1e-12);
  EXPECT_EQ(e.max_x, 6);
  EXPECT_EQ(e.max_y, 7);
}

TEST(CompareSamples, FloorBoundsTheErrorOfNearBlackPixels) {
  // Mean |expected| of channel 0 is (1000 + 0) / 2 = 500, so its floor is 0.5: the black pixel's
  // error of 0.1 counts as 0.1 / 0.5 = 20%, not infinity.
  std::vector<PixelSample> samples = {{{1000.0, 1.0, 1.0}, {1000.0, 1.0, 1.0}, 0, 0},
                                      {{0.1, 1.0, 1.0}, {0.0, 1.0, 1.0}, 1, 0}};
  EXPECT_NEAR(CompareSamples(samples).rel_max, 0.2, 1e-12);
}

TEST(CompareSamples, EmptyClassHasNoPixels) {
  ErrorStats e = CompareSamples({});
  EXPECT_EQ(e.pixels, 0);
  EXPECT_EQ(e.rel_max, 0.0);
}

TEST(CompareImages, SplitsSkyAndOpaqueBySurfaceAlpha) {
  ImageRgbF surface{2, 1, {0, 0, 0, -1, 0, 0, 0, 50}};  // left: sky, right: a surface 50 m away
  ImageRgbF expected{2, 1, {1, 1, 1, 1, 2, 2, 2, 1}};
  ImageRgbF actual{2, 1, {1, 1, 1.5f, 1, 2, 2, 2, 1}};
  ErrorStats sky = CompareImages(actual, expected, surface, PixelClass::kSky);
  ErrorStats opaque = CompareImages(actual, expected, surface, PixelClass::kOpaque);
  EXPECT_EQ(sky.pixels, 1);
  EXPECT_NEAR(sky.rel_max, 0.5, 1e-7);
  EXPECT_EQ(opaque.pixels, 1);
  EXPECT_EQ(opaque.rel_max, 0.0);
  std::vector<float> map = ErrorMap(actual, expected, surface);
  EXPECT_NEAR(map[0], 0.5f, 1e-6f);
  EXPECT_EQ(map[1], 0.0f);
}

}  // namespace
}  // namespace aerial::validation
