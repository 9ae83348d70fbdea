// The froxel rows' placement (src/aerial/shader_abi/froxel_rows.h): the mapping
// against its defining properties, and the focus and spread a camera gets against the horizon and
// the far ground computed here from the camera's own angles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "aerial/render/frame_uniforms.h"
#include "aerial/shader_abi/froxel_rows.h"

namespace aerial::testing {
namespace {

constexpr double kPlanetRadiusM = 6360e3;
constexpr double kDegree = std::numbers::pi / 180.0;

// The mapping covers [0, 1] with both ends fixed, rises everywhere, inverts, and is densest at the
// focus, 1 / (spread span) times the even rows there (a centred difference of 1e-6 screen heights;
// its truncation error is below 1e-9 of the density).
TEST(FroxelRows, MapsTheScreenOntoTheRowsDensestAtTheFocus) {
  for (double focus : {0.0, 0.3, 0.5, 1.0})
    for (double spread : {0.02, kFroxelRowSpread, 0.5}) {
      const FroxelRows rows{.focus = focus, .spread = spread};
      EXPECT_NEAR(rows.RowCoordinate(0.0), 0.0, 1e-12);
      EXPECT_NEAR(rows.RowCoordinate(1.0), 1.0, 1e-12);
      double previous = -1.0;
      for (int i = 0; i <= 100; ++i) {
        const double y = i / 100.0, v = rows.RowCoordinate(y);
        EXPECT_GT(v, previous) << focus << " " << spread << " " << y;
        EXPECT_NEAR(rows.ScreenRow(v), y, 1e-12) << focus << " " << spread;
        previous = v;
      }
      const double h = 1e-6, at = std::clamp(focus, h, 1.0 - h);
      const double density = (rows.RowCoordinate(at + h) - rows.RowCoordinate(at - h)) / (2.0 * h);
      EXPECT_NEAR(density, 1.0 / (spread * rows.Span()), 1e-6 * density) << focus << " " << spread;
    }
}

// The packed form is what the shaders read: focus, spread, and the span and asinh(focus / spread)
// they would otherwise compute per read.
TEST(FroxelRows, PacksFocusSpreadAndSpan) {
  const FroxelRows rows{.focus = 0.6, .spread = 0.05};
  const std::array<float, 4> packed = rows.Packed();
  EXPECT_EQ(packed[0], 0.6f);
  EXPECT_EQ(packed[1], 0.05f);
  EXPECT_FLOAT_EQ(packed[2], float(std::asinh(0.4 / 0.05) + std::asinh(0.6 / 0.05)));
  EXPECT_FLOAT_EQ(packed[3], float(std::asinh(0.6 / 0.05)));
  const FroxelRows unpacked = FroxelRows::Unpack(packed);
  EXPECT_NEAR(unpacked.focus, 0.6, 1e-7);
  EXPECT_NEAR(unpacked.spread, 0.05, 1e-8);
}

// A camera of the given height, pitch and field of view, without roll, looking north.
FroxelRows RowsOf(double height_m, double pitch_deg, double fov_deg) {
  Scene scene;
  scene.camera.position = {0.0, 0.0, height_m};
  scene.camera.pitch_deg = pitch_deg;
  scene.camera.vertical_fov_deg = fov_deg;
  return FroxelRows::Unpack(MakeFrameUniforms(scene, kPlanetRadiusM, 320, 180, FroxelGrid{}).froxel_rows);
}

// The screen row of a direction `below_deg` under the horizontal, on the centre column of a
// pinhole camera pitched up by pitch_deg (rows grow downward).
double ScreenRowBelowHorizontal(double below_deg, double pitch_deg, double fov_deg) {
  return 0.5 + std::tan((pitch_deg + below_deg) * kDegree) / (2.0 * std::tan(fov_deg * kDegree / 2.0));
}

// How far below the horizontal, from height h, the sea-level ground is at distance d:
// R^2 = (R + h)^2 + d^2 - 2 (R + h) d sin(depression).
double DepressionOfGroundDeg(double height_m, double distance_m) {
  const double r = kPlanetRadiusM + height_m;
  return std::asin((r * r + distance_m * distance_m - kPlanetRadiusM * kPlanetRadiusM) / (2.0 * r * distance_m)) /
         kDegree;
}

// On the ground (30 m up, the presets' eye): the focus is the horizon's row, acos(R / (R + h))
// below the horizontal, and the sea-level ground there is nearer than kFroxelRowsFarGroundM, so
// the spread is the default. The float matrices put the rows within 1e-6; 1e-5 is the bound.
// Forgetting the horizon's dip (0.18 degrees) would move the focus by 2.7e-3.
TEST(FroxelRows, OnTheGroundTheRowsGatherAtTheHorizon) {
  for (double pitch : {-10.0, 0.0, 4.0, 15.0}) {
    const FroxelRows rows = RowsOf(30.0, pitch, 50.0);
    const double dip_deg = std::acos(kPlanetRadiusM / (kPlanetRadiusM + 30.0)) / kDegree;
    EXPECT_NEAR(rows.focus, ScreenRowBelowHorizontal(dip_deg, pitch, 50.0), 1e-5) << pitch;
    EXPECT_NEAR(rows.spread, kFroxelRowSpread, 1e-8) << pitch;  // as packed in float
  }
}

// 2 km up, where the ground 20 km away is 5.8 degrees down: the band reaches down to that row.
// 30 km up, every ground pixel is farther than that: the band reaches the screen's bottom edge.
TEST(FroxelRows, FromHighUpTheBandReachesDownToTheFarGround) {
  const double pitch = -3.0, fov = 50.0;
  {
    const FroxelRows rows = RowsOf(2e3, pitch, fov);
    const double far_ground = ScreenRowBelowHorizontal(DepressionOfGroundDeg(2e3, kFroxelRowsFarGroundM), pitch, fov);
    EXPECT_NEAR(rows.spread, far_ground - rows.focus, 1e-5);
    EXPECT_GT(rows.spread, 1.5 * kFroxelRowSpread);
  }
  {
    const FroxelRows rows = RowsOf(30e3, pitch, fov);
    const double dip_deg = std::acos(kPlanetRadiusM / (kPlanetRadiusM + 30e3)) / kDegree;
    EXPECT_NEAR(rows.focus, ScreenRowBelowHorizontal(dip_deg, pitch, fov), 1e-5);
    EXPECT_NEAR(rows.spread, 1.0 - rows.focus, 1e-5);
  }
}

// With the horizon off the screen the focus is the nearest edge: above the top when looking down
// (an aircraft's view of the ground, 30 km up: the whole screen is far ground, the band spans it),
// below the bottom when looking up.
TEST(FroxelRows, WithTheHorizonOffTheScreenTheFocusIsTheNearestEdge) {
  const FroxelRows down = RowsOf(30e3, -60.0, 50.0);
  EXPECT_EQ(down.focus, 0.0);
  EXPECT_NEAR(down.spread, 1.0, 1e-9);
  const FroxelRows down_low = RowsOf(100.0, -60.0, 50.0);
  EXPECT_EQ(down_low.focus, 0.0);
  EXPECT_NEAR(down_low.spread, kFroxelRowSpread, 1e-8);
  const FroxelRows up = RowsOf(100.0, 60.0, 50.0);
  EXPECT_EQ(up.focus, 1.0);
  EXPECT_NEAR(up.spread, kFroxelRowSpread, 1e-8);
}

}  // namespace
}  // namespace aerial::testing
