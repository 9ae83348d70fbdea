// The exposure's arithmetic (Lagarde & de Rousiers 2014, sec. 5.1) and the meter's clipped
// log-average, on images whose answer is known.
#include "aerial/image/exposure.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "aerial/image.h"

namespace aerial {
namespace {

// An image of n pixels of one radiance (the same in the three channels).
ImageRgbF Grey(int n, float radiance) {
  ImageRgbF image{n, 1, std::vector<float>(4 * size_t(n), radiance)};
  for (int i = 0; i < n; ++i) image.rgba[4 * size_t(i) + 3] = 1.0f;
  return image;
}

TEST(Exposure, LuminanceOfAFlatSpectrumIsItsRadianceTimes683TimesTheIntegralOfV) {
  // 1 W/m^2/sr/nm flat over the visible: 683 lm/W x 106.857 nm = 72,983 cd/m^2; the Rec. 709
  // weights sum to 1.
  float one[3] = {1.0f, 1.0f, 1.0f};
  EXPECT_NEAR(LuminanceOfRadiance(one), 72983.3, 0.1);
}

// The sun's colour times its white balance is grey, at the sun's mean level; a white sun is left
// alone.
TEST(Exposure, WhiteBalanceMakesTheSunWhite) {
  std::array<double, 3> sun = {2.0, 1.77, 1.70};
  std::array<double, 3> gains = WhiteBalanceForSun(sun);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sun[c] * gains[c], (2.0 + 1.77 + 1.70) / 3.0, 1e-12);
  for (double gain : WhiteBalanceForSun({1.5, 1.5, 1.5})) EXPECT_DOUBLE_EQ(gain, 1.0);
}

// A dark channel is a valid rgb sun: its gain is finite (before, 1 / 0 = inf failed a PNG render
// after all its work), and the other channels are balanced as before.
TEST(Exposure, WhiteBalanceIsDefinedForASunWithADarkChannel) {
  std::array<double, 3> gains = WhiteBalanceForSun({1.0, 0.0, 2.0});
  EXPECT_DOUBLE_EQ(gains[0], 1.0);
  EXPECT_DOUBLE_EQ(gains[1], kMaxWhiteBalanceGain);
  EXPECT_DOUBLE_EQ(gains[2], 0.5);
  ImageRgbF image{.width = 1, .height = 1, .rgba = {0.5f, 0.0f, 0.25f, 1.0f}};
  EXPECT_NO_THROW(ToneMapToSrgb8(image, {.exposure = 1.0, .white_balance = gains}));
  for (double gain : WhiteBalanceForSun({0.0, 0.0, 0.0})) EXPECT_EQ(gain, 1.0);
}

TEST(Exposure, MultiplierAndEv100AreInverse) {
  for (double ev100 : {-4.0, 0.0, 9.5, 15.0})
    EXPECT_NEAR(Ev100FromRadianceMultiplier(RadianceMultiplierFromEv100(ev100)), ev100, 1e-12);
  // Saturation-based speed: the luminance 1.2 * 2^EV100 maps to 1.
  double ev100 = 12.0;
  double luminance = 1.2 * std::exp2(ev100);
  float one[3] = {1.0f, 1.0f, 1.0f};
  double radiance = luminance / LuminanceOfRadiance(one);
  EXPECT_NEAR(radiance * RadianceMultiplierFromEv100(ev100), 1.0, 1e-6);
}

TEST(Exposure, AutomaticExposureTakesAnEvenImageToMidGrey) {
  // Whatever the scene's brightness, a grey image comes out at 0.18 of the curve's input: its
  // highlight is its average, which mid grey keeps far under the white point.
  for (float radiance : {1e-5f, 0.03f, 2.0f}) {
    ImageRgbF image = Grey(10, radiance);
    EXPECT_NEAR(double(radiance) * Exposure{}.MultiplierFor(image), kMeteredGrey, 1e-6) << radiance;
  }
}

// A sky 16 times brighter than the ground over 40% of the frame, orange (its red channel the
// brightest): the average alone would take the sky's red to 0.18 x 16 x 1.6 / 1.25 = 3.6, four
// times past the curve's white; the highlight-weighted meter takes it to the white point exactly,
// through the white balance's gain.
TEST(Exposure, TheHighlightKeepsABrightSkyUnderTheWhitePoint) {
  ImageRgbF image = Grey(100, 0.001f);
  for (int i = 60; i < 100; ++i) {
    float* p = &image.rgba[4 * size_t(i)];
    p[0] = 0.016f * 1.6f, p[1] = 0.016f, p[2] = 0.016f * 0.5f;
  }
  const std::array<double, 3> gains = {0.9, 1.0, 1.1};
  MeterReading reading = ReadMeter(image, gains);
  EXPECT_NEAR(reading.highlight, kRadiancePerNmToLuminance * 0.016 * 1.6 * 0.9, 1e-3);
  double multiplier = Exposure{}.MultiplierFor(image, gains);
  EXPECT_NEAR(0.016 * 1.6 * 0.9 * multiplier, kHighlightWhite, 1e-5);
  double grey = kMeteredGrey * kRadiancePerNmToLuminance / reading.average_luminance;
  EXPECT_LT(multiplier, grey / 2.0);
}

// ... but by no more than kMaxHighlightStops under the average's exposure: a sky a thousand times
// brighter than the ground leaves the ground three stops under mid grey, not lost to black.
TEST(Exposure, TheHighlightLowersTheExposureByAtMostThreeStops) {
  ImageRgbF image = Grey(100, 0.001f);
  for (int i = 60; i < 100; ++i) std::fill_n(&image.rgba[4 * size_t(i)], 3, 1.0f);
  MeterReading reading = ReadMeter(image, {1.0, 1.0, 1.0});
  double grey = kMeteredGrey * kRadiancePerNmToLuminance / reading.average_luminance;
  EXPECT_NEAR(Exposure{}.MultiplierFor(image) / grey, std::exp2(-kMaxHighlightStops), 1e-9);
}

TEST(Exposure, TheMeterReadsTheMiddleOfTheImage) {
  // 10 pixels: 3 black, 4 at one radiance, 3 a million times brighter. The middle 40% (ranks 3 to
  // 6) are the four: the meter reads them alone, where the plain log-average would be 10^(6 x
  // 0.3) = 63 times brighter, and a zero pixel would not drag it to 0.
  ImageRgbF image = Grey(10, 0.01f);
  for (int i = 0; i < 3; ++i) std::fill_n(&image.rgba[4 * size_t(i)], 3, 0.0f);
  for (int i = 7; i < 10; ++i) std::fill_n(&image.rgba[4 * size_t(i)], 3, 1e4f);
  float middle[3] = {0.01f, 0.01f, 0.01f};
  EXPECT_NEAR(LogAverageLuminance(image) / LuminanceOfRadiance(middle), 1.0, 1e-9);
}

TEST(Exposure, FixedExposuresIgnoreTheImage) {
  ImageRgbF bright = Grey(4, 10.0f), dark = Grey(4, 1e-4f);
  Exposure ev{.mode = Exposure::Mode::kEv100, .value = 13.0};
  EXPECT_EQ(ev.MultiplierFor(bright), ev.MultiplierFor(dark));
  EXPECT_NEAR(ev.MultiplierFor(bright), RadianceMultiplierFromEv100(13.0), 1e-12);
  Exposure multiplier{.mode = Exposure::Mode::kMultiplier, .value = 8.0};
  EXPECT_EQ(multiplier.MultiplierFor(dark), 8.0);
  EXPECT_NEAR(multiplier.FixedEv100(), Ev100FromRadianceMultiplier(8.0), 1e-12);
}

}  // namespace
}  // namespace aerial
