// The froxels' rows and columns (src/aerial/shader_abi/froxel_axes.h): the mapping against its
// defining properties, and the focus and spread a camera gets against the horizon, the far ground
// and the sun, computed here from the camera's own angles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "aerial/render/frame_uniforms.h"
#include "aerial/shader_abi/froxel_axes.h"

namespace aerial::testing {
namespace {

constexpr double kPlanetRadiusM = 6360e3;
constexpr double kDegree = std::numbers::pi / 180.0;

// The mapping covers [0, 1] with both ends fixed, rises everywhere, inverts, and is densest at the
// focus, 1 / (spread span) times the even rows there (a centred difference of 1e-6 screen heights;
// its truncation error is below 1e-9 of the density).
TEST(FroxelAxis, MapsTheScreenOntoTheRowsDensestAtTheFocus) {
  for (double focus : {0.0, 0.3, 0.5, 1.0})
    for (double spread : {0.02, kFroxelRowSpread, 0.5}) {
      const FroxelAxis rows{.focus = focus, .spread = spread};
      EXPECT_NEAR(rows.Coordinate(0.0), 0.0, 1e-12);
      EXPECT_NEAR(rows.Coordinate(1.0), 1.0, 1e-12);
      double previous = -1.0;
      for (int i = 0; i <= 100; ++i) {
        const double y = i / 100.0, v = rows.Coordinate(y);
        EXPECT_GT(v, previous) << focus << " " << spread << " " << y;
        EXPECT_NEAR(rows.ScreenPosition(v), y, 1e-12) << focus << " " << spread;
        previous = v;
      }
      const double h = 1e-6, at = std::clamp(focus, h, 1.0 - h);
      const double density = (rows.Coordinate(at + h) - rows.Coordinate(at - h)) / (2.0 * h);
      EXPECT_NEAR(density, 1.0 / (spread * rows.Span()), 1e-6 * density) << focus << " " << spread;
    }
}

// The packed form is what the shaders read: focus, spread, and the span and asinh(focus / spread)
// they would otherwise compute per read.
TEST(FroxelAxis, PacksFocusSpreadAndSpan) {
  const FroxelAxis rows{.focus = 0.6, .spread = 0.05};
  const std::array<float, 4> packed = rows.Packed();
  EXPECT_EQ(packed[0], 0.6f);
  EXPECT_EQ(packed[1], 0.05f);
  EXPECT_FLOAT_EQ(packed[2], float(std::asinh(0.4 / 0.05) + std::asinh(0.6 / 0.05)));
  EXPECT_FLOAT_EQ(packed[3], float(std::asinh(0.6 / 0.05)));
  const FroxelAxis unpacked = FroxelAxis::Unpack(packed);
  EXPECT_NEAR(unpacked.focus, 0.6, 1e-7);
  EXPECT_NEAR(unpacked.spread, 0.05, 1e-8);
}

// A camera of the given height, pitch and field of view, without roll, looking north.
// The sun behind the camera (south, 10 degrees below the horizon), so that its glow moves nothing.
FroxelAxes AxesOf(double height_m, double pitch_deg, double fov_deg, Sun sun = {100.0, 180.0}) {
  Scene scene;
  scene.camera.position = {0.0, 0.0, height_m};
  scene.camera.pitch_deg = pitch_deg;
  scene.camera.vertical_fov_deg = fov_deg;
  scene.sun = sun;
  return aerial::AxesOf(MakeFrameUniforms(scene, kPlanetRadiusM, 320, 180, FroxelGrid{}));
}
FroxelAxis RowsOf(double height_m, double pitch_deg, double fov_deg) {
  return AxesOf(height_m, pitch_deg, fov_deg).rows;
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
TEST(FroxelAxis, OnTheGroundTheRowsGatherAtTheHorizon) {
  for (double pitch : {-10.0, 0.0, 4.0, 15.0}) {
    const FroxelAxis rows = RowsOf(30.0, pitch, 50.0);
    const double dip_deg = std::acos(kPlanetRadiusM / (kPlanetRadiusM + 30.0)) / kDegree;
    EXPECT_NEAR(rows.focus, ScreenRowBelowHorizontal(dip_deg, pitch, 50.0), 1e-5) << pitch;
    EXPECT_NEAR(rows.spread, kFroxelRowSpread, 1e-8) << pitch;  // as packed in float
  }
}

// 2 km up, where the ground 20 km away is 5.8 degrees down: the band reaches down to that row.
// 30 km up, every ground pixel is farther than that: the band reaches the screen's bottom edge.
TEST(FroxelAxis, FromHighUpTheBandReachesDownToTheFarGround) {
  const double pitch = -3.0, fov = 50.0;
  {
    const FroxelAxis rows = RowsOf(2e3, pitch, fov);
    const double far_ground = ScreenRowBelowHorizontal(DepressionOfGroundDeg(2e3, kFroxelRowsFarGroundM), pitch, fov);
    EXPECT_NEAR(rows.spread, far_ground - rows.focus, 1e-5);
    EXPECT_GT(rows.spread, 1.5 * kFroxelRowSpread);
  }
  {
    const FroxelAxis rows = RowsOf(30e3, pitch, fov);
    const double dip_deg = std::acos(kPlanetRadiusM / (kPlanetRadiusM + 30e3)) / kDegree;
    EXPECT_NEAR(rows.focus, ScreenRowBelowHorizontal(dip_deg, pitch, fov), 1e-5);
    EXPECT_NEAR(rows.spread, 1.0 - rows.focus, 1e-5);
  }
}

// With the horizon off the screen the focus is the nearest edge: above the top when looking down
// (an aircraft's view of the ground, 30 km up: the whole screen is far ground, the band spans it),
// below the bottom when looking up.
TEST(FroxelAxis, WithTheHorizonOffTheScreenTheFocusIsTheNearestEdge) {
  const FroxelAxis down = RowsOf(30e3, -60.0, 50.0);
  EXPECT_EQ(down.focus, 0.0);
  EXPECT_NEAR(down.spread, 1.0, 1e-9);
  const FroxelAxis down_low = RowsOf(100.0, -60.0, 50.0);
  EXPECT_EQ(down_low.focus, 0.0);
  EXPECT_NEAR(down_low.spread, kFroxelRowSpread, 1e-8);
  const FroxelAxis up = RowsOf(100.0, 60.0, 50.0);
  EXPECT_EQ(up.focus, 1.0);
  EXPECT_NEAR(up.spread, kFroxelRowSpread, 1e-8);
}

// A level camera 30 m up (50 degrees high, 16:9) looking north, with the sun `azimuth_deg` east of
// north and `elevation_deg` up. Its screen position, from the pinhole's angles: x = 0.5 + tan(a) /
// (2 tan(h)) on the horizontal plane (h the half-width's angle), and y = 0.5 - tan(e) / (2 tan(25
// degrees) cos(a)) along the column through it.
constexpr double kFov = 50.0, kAspect = 320.0 / 180.0;
FroxelAxes LevelAxesWithSun(double elevation_deg, double azimuth_deg) {
  return AxesOf(30.0, 0.0, kFov, Sun{90.0 - elevation_deg, azimuth_deg});
}
double TanHalfWidth() { return std::tan(kFov / 2.0 * kDegree) * kAspect; }

// With the sun on the screen the columns gather at its column, kFroxelColumnSpread wide; the float
// matrices put the focus within 1e-6 of the pinhole's angle, 1e-5 the bound. The mapping's density
// there is 3 times even columns or more.
TEST(FroxelAxis, ColumnsGatherAtTheSunOnTheScreen) {
  for (double azimuth : {-20.0, -3.0, 0.0, 12.0}) {
    const FroxelAxis columns = LevelAxesWithSun(2.0, azimuth).columns;
    EXPECT_NEAR(columns.focus, 0.5 + std::tan(azimuth * kDegree) / (2.0 * TanHalfWidth()), 1e-5) << azimuth;
    EXPECT_NEAR(columns.spread, kFroxelColumnSpread, 1e-8) << azimuth;
    EXPECT_GT(1.0 / (columns.spread * columns.Span()), 3.0) << azimuth;
  }
}

// Off the screen the glow's weight halves every kFroxelGlowHalvingDeg from the screen's nearest
// point: a sun on the horizon 8 and 16 degrees beyond the right edge (the edge's ray is level, so
// those are the angles) doubles and quadruples the spread, the focus at the edge. Behind the camera
// the columns are even to within 1e-3 of the screen.
TEST(FroxelAxis, ColumnsSpreadAsTheSunLeavesTheScreen) {
  const double edge_deg = std::atan(TanHalfWidth()) / kDegree;
  for (int halvings : {1, 2}) {
    const FroxelAxis columns = LevelAxesWithSun(0.0, edge_deg + halvings * kFroxelGlowHalvingDeg).columns;
    EXPECT_NEAR(columns.focus, 1.0, 1e-9);
    EXPECT_NEAR(columns.spread, kFroxelColumnSpread * std::exp2(halvings), 1e-4 * columns.spread) << halvings;
  }
  const FroxelAxis behind = LevelAxesWithSun(10.0, 180.0).columns;
  for (double x : {0.1, 0.3, 0.5, 0.9}) EXPECT_NEAR(behind.Coordinate(x), x, 1e-3) << x;
}

// Under the sun's glow, a sun above the band of rows at the horizon (focus less spread) raises their
// focus by half its height above the band, up to kFroxelRowsRiseToSun; a sun within the band, or
// below the horizon, moves nothing. The horizon's row is the one the sun-less camera gets
// (OnTheGroundTheRowsGatherAtTheHorizon holds it).
TEST(FroxelAxis, RowsRiseTowardTheSunAboveTheirBand) {
  const double horizon = RowsOf(30.0, 0.0, kFov).focus;
  const double tan_half_height = std::tan(kFov / 2.0 * kDegree);
  for (double elevation : {3.0, 5.0, 20.0}) {
    const FroxelAxis rows = LevelAxesWithSun(elevation, 0.0).rows;
    const double sun_row = 0.5 - std::tan(elevation * kDegree) / (2.0 * tan_half_height);
    const double above_band = horizon - kFroxelRowSpread - sun_row;
    ASSERT_GT(above_band, 0.0) << elevation;
    EXPECT_NEAR(rows.focus, horizon - std::min(0.5 * above_band, kFroxelRowsRiseToSun), 1e-5) << elevation;
    EXPECT_NEAR(rows.spread, kFroxelRowSpread, 1e-8) << elevation;
  }
  for (double elevation : {1.0, -1.0}) EXPECT_NEAR(LevelAxesWithSun(elevation, 0.0).rows.focus, horizon, 1e-9);
}

}  // namespace
}  // namespace aerial::testing
