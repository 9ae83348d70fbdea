#include "aerial/render/sun_high_variant.h"

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

}  // namespace
}  // namespace aerial
