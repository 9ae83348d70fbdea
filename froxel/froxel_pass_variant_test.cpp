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

// The bound is taken at the froxels' far distance: 11.49 degrees at 128 km, 10.42 at 10 km
// (SunHighWithin's tests).
TEST(FroxelPassVariant, TheFroxelsFarDistanceSetsTheMargin) {
  EXPECT_TRUE(SunHighAtEveryFroxel(Frame(11.6, 128e3), kR));
  EXPECT_FALSE(SunHighAtEveryFroxel(Frame(11.3, 128e3), kR));
  EXPECT_TRUE(SunHighAtEveryFroxel(Frame(10.5, 10e3), kR));
  EXPECT_FALSE(SunHighAtEveryFroxel(Frame(10.5, 128e3), kR));
}

TEST(FroxelPassVariant, TheVariantIsChosenWhereTheSunIsHighOverEveryFroxel) {
  EXPECT_EQ(ChooseFroxelPassVariant(Frame(45.0, 128e3), kR), FroxelPassVariant::kSunHigh);
  EXPECT_EQ(ChooseFroxelPassVariant(Frame(2.0, 128e3), kR), FroxelPassVariant::kGeneral);
}

}  // namespace
}  // namespace aerial
