#include "aerial/image/tone_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "aerial/error.h"

namespace aerial {
namespace {

// One row, grey pixels (R = G = B = value, A = 1).
ImageRgbF GreyRow(const std::vector<float>& values) {
  ImageRgbF image{static_cast<int>(values.size()), 1, {}};
  for (float v : values) image.rgba.insert(image.rgba.end(), {v, v, v, 1.0f});
  return image;
}

// Log-spaced radiance over 1e-6..1e4, the range a sky render produces.
std::vector<float> Sweep() {
  std::vector<float> values;
  for (int i = 0; i <= 400; ++i) values.push_back(static_cast<float>(std::pow(10.0, -6 + i / 40.0)));
  return values;
}

TEST(ToneMap, ZeroMapsToZero) {
  const std::vector<uint8_t> out = ToneMapToSrgb8(GreyRow({0.0f}), {});
  EXPECT_EQ(out, (std::vector<uint8_t>{0, 0, 0, 255}));
}

TEST(ToneMap, MonotonicOverSkyRange) {
  const std::vector<uint8_t> out = ToneMapToSrgb8(GreyRow(Sweep()), {});
  for (size_t i = 4; i < out.size(); i += 4)
    for (size_t c = 0; c < 3; ++c) EXPECT_LE(out[i - 4 + c], out[i + c]) << "pixel " << i / 4;
  EXPECT_EQ(out[0], 0);                // 1e-6 is black in 8 bits
  EXPECT_EQ(out[out.size() - 4], 255);  // 1e4 saturates
}

// Exposure multiplies radiance before anything else. Scaling by 2 is exact in float and double,
// so the two paths must agree bit for bit: no tolerance.
TEST(ToneMap, ExposureScalesRadiance) {
  std::vector<float> doubled = Sweep();
  for (float& v : doubled) v *= 2.0f;
  EXPECT_EQ(ToneMapToSrgb8(GreyRow(Sweep()), {.exposure = 2.0}),
            ToneMapToSrgb8(GreyRow(doubled), {.exposure = 1.0}));
  // And it brightens: mid grey 0.18 at exposure 4 is brighter than at 1.
  EXPECT_GT(ToneMapToSrgb8(GreyRow({0.18f}), {.exposure = 4.0})[0],
            ToneMapToSrgb8(GreyRow({0.18f}), {.exposure = 1.0})[0]);
}

// Reference values computed by hand from Narkowicz's constants and the sRGB OETF:
// 0.18 -> ACES 0.26690 -> sRGB 0.55346 -> 141.13; 1.0 -> 0.80380 -> 0.90823 -> 231.60.
// Both are far (> 0.1) from a rounding boundary, so exact equality is safe.
TEST(ToneMap, MatchesPublishedCurve) {
  const std::vector<uint8_t> out = ToneMapToSrgb8(GreyRow({0.18f, 1.0f}), {});
  EXPECT_EQ(out[0], 141);
  EXPECT_EQ(out[4], 232);
}

TEST(ToneMap, AlphaIsCoverageNotLight) {
  ImageRgbF image = GreyRow({0.5f});
  image.rgba[3] = 0.5f;
  // 0.5 * 255 = 127.5 rounds away from zero; exposure must not touch it.
  EXPECT_EQ(ToneMapToSrgb8(image, {.exposure = 8.0})[3], 128);
}

TEST(ToneMap, NonFiniteRadianceIsBlackOrWhite) {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<uint8_t> out = ToneMapToSrgb8(GreyRow({nan, -1.0f, inf}), {});
  EXPECT_EQ(out[0], 0);
  EXPECT_EQ(out[4], 0);
  EXPECT_EQ(out[8], 255);
}

TEST(ToneMap, RejectsNonPositiveExposure) {
  for (double exposure : {0.0, -1.0, std::nan("")}) {
    try {
      ToneMapToSrgb8(GreyRow({1.0f}), {.exposure = exposure});
      ADD_FAILURE() << "expected aerial::Error for exposure " << exposure;
    } catch (const Error& e) {
      EXPECT_EQ(e.field(), "exposure");
    }
  }
}

TEST(ToneMap, RejectsBufferOfWrongLength) {
  ImageRgbF image{2, 2, std::vector<float>(3)};
  EXPECT_THROW(ToneMapToSrgb8(image, {}), Error);
}

}  // namespace
}  // namespace aerial
