#include "aerial/image/resample.h"

#include <gtest/gtest.h>

namespace aerial {
namespace {

// Texel centers at (i + 0.5) / size on both images, clamped at the edges, as a GPU's linear
// sampler reads them: a 2-texel row doubled is a, 3a/4 + b/4, a/4 + 3b/4, b.
TEST(ResizeBilinear, MatchesALinearSamplerOnTexelCenters) {
  ImageRgbF row{2, 1, {0, 10, 100, 1, 4, 20, 200, 1}};
  ImageRgbF wide = ResizeBilinear(row, 4, 1);
  const float expected[4][3] = {{0, 10, 100}, {1, 12.5, 125}, {3, 17.5, 175}, {4, 20, 200}};
  for (int x = 0; x < 4; ++x) {
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(wide.pixel(x, 0)[c], expected[x][c]) << x << " " << c;
    EXPECT_FLOAT_EQ(wide.pixel(x, 0)[3], 1.0f);
  }
}

TEST(ResizeBilinear, SameSizeIsTheSameImage) {
  ImageRgbF image{3, 2, {}};
  for (int i = 0; i < 24; ++i) image.rgba.push_back(float(i * i));
  EXPECT_EQ(ResizeBilinear(image, 3, 2).rgba, image.rgba);
}

}  // namespace
}  // namespace aerial
