#include "froxel/froxel_pass_variant.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace aerial {
namespace {

constexpr double kR = 6360e3;

// A camera on the ground with the sun elevation_deg above its horizontal, froxels to far_m.
FrameUniforms Frame(double elevation_deg, double far_m) {
  double e = elevation_deg * std::numbers::pi / 180.0;
  FrameUniforms frame{};
  frame.camera_planet_position = {0.0f, 0.0f, float(kR + 2.0), 0.0f};
  frame.sun_direction = {float(std::cos(e)), 0.0f, float(std::sin(e)), 0.0f};
  frame.froxel_depth = {float(far_m), 0.0f, 0.0f, 0.0f};
  return frame;
}

// The froxels' farthest point, 128 km away, sees the planet's centre 1.153 degrees from the
// camera, so the sun's elevation there may be that much lower: the variant needs the camera's
// sun at 10.04 (the shaders' one-tap sine, 0.1745) + 0.29 (the margin) + 1.15 = 11.49 degrees.
TEST(FroxelPassVariant, TheSunHighOverEveryFroxelAllowsTheVariant) {
  EXPECT_TRUE(SunHighAtEveryFroxel(Frame(90.0, 128e3), kR));
  EXPECT_TRUE(SunHighAtEveryFroxel(Frame(11.6, 128e3), kR));
  EXPECT_EQ(ChooseFroxelPassVariant(Frame(45.0, 128e3), kR), FroxelPassVariant::kSunHigh);
}

TEST(FroxelPassVariant, ASunWithinTheMarginOfAnyFroxelsHorizonDoesNot) {
  EXPECT_FALSE(SunHighAtEveryFroxel(Frame(11.3, 128e3), kR));
  EXPECT_FALSE(SunHighAtEveryFroxel(Frame(5.0, 128e3), kR));
  EXPECT_FALSE(SunHighAtEveryFroxel(Frame(-3.0, 128e3), kR));
  EXPECT_EQ(ChooseFroxelPassVariant(Frame(2.0, 128e3), kR), FroxelPassVariant::kGeneral);
}

// Nearer froxels turn the horizontal less: at 10 km, 0.09 degrees.
TEST(FroxelPassVariant, TheFroxelsFarDistanceSetsTheMargin) {
  EXPECT_TRUE(SunHighAtEveryFroxel(Frame(10.5, 10e3), kR));
  EXPECT_FALSE(SunHighAtEveryFroxel(Frame(10.5, 128e3), kR));
  EXPECT_FALSE(SunHighAtEveryFroxel(Frame(10.2, 10e3), kR));
}

TEST(FroxelPassVariant, ADegenerateFrameTakesTheGeneralPass) {
  FrameUniforms no_sun = Frame(45.0, 128e3);
  no_sun.sun_direction = {0.0f, 0.0f, 0.0f, 0.0f};
  EXPECT_FALSE(SunHighAtEveryFroxel(no_sun, kR));
  FrameUniforms no_camera = Frame(45.0, 128e3);
  no_camera.camera_planet_position = {0.0f, 0.0f, 0.0f, 0.0f};
  EXPECT_FALSE(SunHighAtEveryFroxel(no_camera, kR));
}

}  // namespace
}  // namespace aerial
