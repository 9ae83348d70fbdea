#include "aerial/image/resample.h"

#include <gtest/gtest.h>

#include "aerial/error.h"

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

namespace aerial {
namespace {

// Each output pixel is the mean of its block: a 4x2 image by 2 is two pixels.
TEST(DownsampleBox, AveragesEachBlock) {
  ImageRgbF image{4, 2, {}};
  for (int i = 0; i < 8; ++i) image.rgba.insert(image.rgba.end(), {float(i), 2.0f * i, 100.0f, i < 4 ? 1.0f : 0.0f});
  ImageRgbF small = DownsampleBox(image, 2);
  ASSERT_EQ(small.width, 2);
  ASSERT_EQ(small.height, 1);
  // Pixels 0, 1, 4, 5 and 2, 3, 6, 7.
  EXPECT_FLOAT_EQ(small.pixel(0, 0)[0], 2.5f);
  EXPECT_FLOAT_EQ(small.pixel(1, 0)[1], 9.0f);
  EXPECT_FLOAT_EQ(small.pixel(1, 0)[2], 100.0f);
  EXPECT_FLOAT_EQ(small.pixel(0, 0)[3], 0.5f);
  EXPECT_EQ(DownsampleBox(image, 1).rgba, image.rgba);
  EXPECT_THROW(DownsampleBox(image, 3), Error);
}

}  // namespace
}  // namespace aerial
