#include "aerial/image/tone_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

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

// The curve (undithered: the dither differs from pixel to pixel by design).
TEST(ToneMap, MonotonicOverSkyRange) {
  const std::vector<uint8_t> out = ToneMapToSrgb8(GreyRow(Sweep()), {.dither = false});
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

// Reference values computed by hand from Khronos PBR Neutral's constants and the sRGB OETF,
// undithered: 0.18 -> less the toe's 0.04, 0.14 -> sRGB 0.41004 -> 104.56; 1.0 -> 0.96, past the
// shoulder's start 0.76 -> 1 - 0.24^2 / 0.44 = 0.86909 -> 0.94009 -> 239.72. Both are more than
// 0.05 from a rounding boundary, so exact equality is safe.
TEST(ToneMap, MatchesPublishedCurve) {
  const std::vector<uint8_t> out = ToneMapToSrgb8(GreyRow({0.18f, 1.0f}), {.dither = false});
  EXPECT_EQ(out[0], 105);
  EXPECT_EQ(out[4], 240);
}

// HSV hue, degrees.
double Hue(const std::array<double, 3>& c) {
  double high = std::max({c[0], c[1], c[2]}), low = std::min({c[0], c[1], c[2]});
  if (high - low <= 0.0) return 0.0;
  double h = high == c[0] ? (c[1] - c[2]) / (high - low) : high == c[1] ? 2.0 + (c[2] - c[0]) / (high - low)
                                                                       : 4.0 + (c[0] - c[1]) / (high - low);
  return std::fmod(60.0 * h + 360.0, 360.0);
}

// The curve keeps a colour's hue at every exposure, from the identity part through the shoulder:
// a sunset's orange, a sky's blue and a twilight's pink, 1/8 to 16 times over white. A curve
// applied to each channel alone (the ACES fit used before) turns the orange 23 degrees toward
// yellow and the blue 17 degrees toward cyan at 2x; 0.5 degree is a wide margin for rounding.
TEST(ToneMap, KeepsHueThroughTheShoulder) {
  for (std::array<double, 3> colour : {std::array<double, 3>{1.0, 0.45, 0.12}, {0.25, 0.45, 1.0}, {1.0, 0.75, 0.8}}) {
    for (double scale = 0.125; scale <= 16.0; scale *= 2.0) {
      std::array<double, 3> exposed = {colour[0] * scale, colour[1] * scale, colour[2] * scale};
      std::array<double, 3> display = DisplayCurve(exposed);
      EXPECT_NEAR(Hue(display), Hue(colour), 0.5) << colour[0] << ", " << colour[1] << ", " << colour[2] << " x "
                                                   << scale;
      // And it stays a colour: the shoulder mixes toward white only as far as it compresses.
      EXPECT_LT(std::min({display[0], display[1], display[2]}), std::max({display[0], display[1], display[2]}));
    }
  }
}

// The dither: a flat image between two 8-bit codes comes out as a mix of both whose mean is the
// value (within 0.02 step over 16K pixels, the triangular noise's standard error being 0.003),
// where plain rounding gives one code everywhere (a band, on a gradient). Black stays black.
TEST(ToneMap, DitherKeepsTheMeanOfAFlatArea) {
  // Linear 0.1 (past the toe's 0.08) -> 0.06 -> sRGB 0.27170 -> 69.28 of 255.
  ImageRgbF flat{128, 128, std::vector<float>(128 * 128 * 4, 0.1f)};
  std::vector<uint8_t> dithered = ToneMapToSrgb8(flat, {}), plain = ToneMapToSrgb8(flat, {.dither = false});
  double mean = 0.0;
  std::set<uint8_t> codes;
  for (size_t i = 0; i < dithered.size(); i += 4) {
    mean += dithered[i];
    codes.insert(dithered[i]);
    EXPECT_EQ(plain[i], 69);
  }
  mean /= double(dithered.size() / 4);
  EXPECT_NEAR(mean, 69.28, 0.02);
  EXPECT_GE(codes.size(), 2u);
  EXPECT_LE(codes.size(), 3u);  // at most one step either side
  EXPECT_EQ(ToneMapToSrgb8(GreyRow({0.0f}), {})[0], 0);
}

// The dither's values over a 256x256 block are triangular noise on (-1, 1): mean 0, variance 1/6
// and three quarters within half a step of 0 (a uniform noise of the same span has variance 1/3 and
// half). 65536 samples: the standard errors are 0.0016 (mean), 0.0007 (variance) and 0.0017
// (fraction), so the bounds are 3 to 6 of them.
TEST(ToneMap, DitherIsTriangularNoise) {
  double sum = 0.0, squares = 0.0, near = 0.0;
  const int n = 256;
  for (uint32_t y = 0; y < n; ++y) {
    for (uint32_t x = 0; x < n; ++x) {
      double d = DitherSteps(x, y);
      ASSERT_GT(d, -1.0);
      ASSERT_LT(d, 1.0);
      sum += d, squares += d * d, near += std::abs(d) < 0.5 ? 1.0 : 0.0;
    }
  }
  const double count = double(n) * n;
  EXPECT_NEAR(sum / count, 0.0, 0.005);
  EXPECT_NEAR(squares / count, 1.0 / 6.0, 0.004);
  EXPECT_NEAR(near / count, 0.75, 0.008);
}

// A clipped highlight (the sun's disc, a bright cloud) is white in every pixel: the curve only
// nears 1 (here 0.9988 linear), and the dither must not scatter 254s over it.
TEST(ToneMap, ClippedHighlightsHaveNoSpecks) {
  ImageRgbF bright{64, 64, std::vector<float>(64 * 64 * 4, 50.0f)};
  std::vector<uint8_t> out = ToneMapToSrgb8(bright, {});
  for (size_t i = 0; i < out.size(); i += 4) ASSERT_EQ(out[i], 255) << "pixel " << i / 4;
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
