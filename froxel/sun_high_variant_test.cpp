#include "froxel/sun_high_variant.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace aerial {
namespace {

constexpr double kR = 6360e3;

// A camera on the ground with the sun elevation_deg above its horizontal.
FrameUniforms Frame(double elevation_deg) {
  double e = elevation_deg * std::numbers::pi / 180.0;
  FrameUniforms frame{};
  frame.camera_planet_position = {0.0f, 0.0f, float(kR + 2.0), 0.0f};
  frame.sun_direction = {float(std::cos(e)), 0.0f, float(std::sin(e)), 0.0f};
  return frame;
}

// A point 128 km away sees the planet's centre 1.153 degrees from the camera, so the sun's
// elevation there may be that much lower: the variant needs the camera's sun at 10.04 (the
// shaders' one-tap sine, 0.1745) + 0.29 (the margin) + 1.15 = 11.49 degrees.
TEST(SunHighWithin, TheSunHighOverEveryPointAllowsTheVariant) {
  EXPECT_TRUE(SunHighWithin(Frame(90.0), 128e3, kR));
  EXPECT_TRUE(SunHighWithin(Frame(11.6), 128e3, kR));
}

TEST(SunHighWithin, ASunWithinTheMarginOfAnyPointsHorizonDoesNot) {
  EXPECT_FALSE(SunHighWithin(Frame(11.3), 128e3, kR));
  EXPECT_FALSE(SunHighWithin(Frame(5.0), 128e3, kR));
  EXPECT_FALSE(SunHighWithin(Frame(-3.0), 128e3, kR));
}

// Nearer points turn the horizontal less: at 10 km, 0.09 degrees; at 0 km, none. A distance
// beyond the planet's radius bounds nothing (any horizontal may be turned by 90 degrees).
TEST(SunHighWithin, TheDistanceSetsTheMargin) {
  EXPECT_TRUE(SunHighWithin(Frame(10.5), 10e3, kR));
  EXPECT_FALSE(SunHighWithin(Frame(10.5), 128e3, kR));
  EXPECT_FALSE(SunHighWithin(Frame(10.2), 10e3, kR));
  EXPECT_TRUE(SunHighWithin(Frame(10.4), 0.0, kR));
  EXPECT_FALSE(SunHighWithin(Frame(89.0), 2.0 * kR, kR));
}

TEST(SunHighWithin, ADegenerateFrameOrDistanceTakesTheGeneralPass) {
  FrameUniforms no_sun = Frame(45.0);
  no_sun.sun_direction = {0.0f, 0.0f, 0.0f, 0.0f};
  EXPECT_FALSE(SunHighWithin(no_sun, 128e3, kR));
  FrameUniforms no_camera = Frame(45.0);
  no_camera.camera_planet_position = {0.0f, 0.0f, 0.0f, 0.0f};
  EXPECT_FALSE(SunHighWithin(no_camera, 128e3, kR));
  EXPECT_FALSE(SunHighWithin(Frame(45.0), std::nan(""), kR));
  EXPECT_FALSE(SunHighWithin(Frame(45.0), -1.0, kR));
}

// The grazing ray from the ground to the top of a 60 km atmosphere: sqrt(6420^2 - 6360^2) km.
TEST(SunHighWithin, TheLongestSkyRayGrazesTheGround) {
  EXPECT_NEAR(LongestSkyRayM(kR, kR, 6420e3), 875671.17, 0.01);
  EXPECT_NEAR(LongestSkyRayM(kR + 50e3, kR, 6420e3), std::sqrt(6410e3 * 6410e3 - kR * kR) + 875671.17, 0.01);
}

// Earth's tables' mu_s axis (mu_s_min -0.5) with the default 36 texels: texel 19 holds mu_s
// -0.0678530, texel 33 0.3936658 (sun elevation 23.18 degrees), from mappings.glsl's formula
// evaluated apart from this code.
TEST(SunHighWithin, TheSkysLowestMarchedSunIsTheTexelBelowTheReadsPair) {
  // Midway between texels 20 and 21 (mu_s -0.0501489): the read blends them, the march adds 19.
  EXPECT_NEAR(LowestSkyCorrectionSunSine(-0.0501489144, -0.5, 36), -0.0678529917, 1e-7);
  // The sun at zenith 20 degrees (between texels 34 and 35): texel 33.
  EXPECT_NEAR(LowestSkyCorrectionSunSine(std::cos(20.0 * std::numbers::pi / 180.0), -0.5, 36), 0.3936658312, 1e-7);
  // At the axis' first texel there is none below: the first.
  EXPECT_NEAR(LowestSkyCorrectionSunSine(-0.5, -0.5, 36), -0.5, 1e-9);
}

// Noon (sun zenith 20 degrees) with the default 36 mu_s texels: texel 33's sun, 23.18 degrees up,
// stays above 10.33 over the 7.91 degrees of arc of the longest sky ray. With 16 texels the node is
// 9.8 degrees up; at sun zenith 55 degrees 16.4 degrees: too low for that arc.
TEST(SunHighWithin, TheSkyVariantNeedsItsLowestMarchedSunHighOverTheLongestRay) {
  const AtmosphereParameters earth = AtmosphereParameters::Earth();
  EXPECT_TRUE(SunHighOverEverySkyRay(Frame(70.0), earth, 36));
  EXPECT_FALSE(SunHighOverEverySkyRay(Frame(70.0), earth, 16));
  EXPECT_FALSE(SunHighOverEverySkyRay(Frame(35.0), earth, 36));
  FrameUniforms no_sun = Frame(70.0);
  no_sun.sun_direction = {0.0f, 0.0f, 0.0f, 0.0f};
  EXPECT_FALSE(SunHighOverEverySkyRay(no_sun, earth, 36));
}

}  // namespace
}  // namespace aerial
