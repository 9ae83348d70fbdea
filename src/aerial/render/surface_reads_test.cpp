#include "aerial/render/surface_reads.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aerial {
namespace {

// Slice k's centre lies at far * ((k + 0.5) / depth)^2 (froxel_grid.h), written out here rather
// than taken from the grid, so that the test checks SliceSpan against the documented spacing.
double SliceCentreM(const FroxelGrid& grid, int k) {
  const double t = (k + 0.5) / grid.depth;
  return grid.far_m * t * t;
}

TEST(SurfaceReads, AnEdgeFromOneSliceCentreToTheNextSpansOneSlice) {
  const FroxelGrid grid;
  for (int k : {0, 5, 30}) {
    const double near = SliceCentreM(grid, k);
    const double edge = SliceCentreM(grid, k + 1) - near;
    // Both are the same closed-form mapping evaluated in double: agreement to rounding.
    EXPECT_NEAR(SliceSpan(grid, edge, near), 1.0, 1e-9) << "slice " << k;
  }
}

TEST(SurfaceReads, TheSameEdgeSpansFewerSlicesFartherAway) {
  const FroxelGrid grid;
  double previous = SliceSpan(grid, 100.0, 0.0);
  for (double distance : {10.0, 100.0, 1e3, 1e4, 1e5}) {
    const double span = SliceSpan(grid, 100.0, distance);
    EXPECT_LT(span, previous) << distance;
    previous = span;
  }
}

// The default atmosphere's densest extinction, Rayleigh's blue (3.31e-5 / m) plus Mie's
// (4.44e-6) plus ozone's (8.5e-8) at full density, and Mie's scale height, the smaller of the two
// (Bruneton 2017's values, parameters.cpp).
constexpr AirScales kEarth{.ground_extinction_per_m = 3.31e-5 + 4.44e-6 + 8.5e-8, .smallest_scale_height_m = 1200.0};

TEST(SurfaceReads, TheAirsScalesAreTheDensestExtinctionAndTheSmallestScaleHeight) {
  const AirScales air = MakeAirScales(AtmosphereParameters::Earth());
  // 1e-8 / m: the constant above rounds Rayleigh's 1.24062e-6 * 0.44^-4 = 3.3098e-5 to 3.31e-5.
  EXPECT_NEAR(air.ground_extinction_per_m, kEarth.ground_extinction_per_m, 1e-8);
  EXPECT_NEAR(air.smallest_scale_height_m, 1200.0, 1e-9);
}

TEST(SurfaceReads, AGroundQuadToTheHorizonIsReadPerPixelATerrainCellPerVertex) {
  const FroxelGrid grid;
  // A 40 km quad touching the camera reaches across 32 * sqrt(40 / 128) = 17.9 slices and an
  // optical thickness of 1.5: its vertices' reads stand for air they never sample.
  EXPECT_NEAR(SliceSpan(grid, 40e3, 0.0), 32.0 * std::sqrt(40.0 / 128.0), 1e-9);
  EXPECT_TRUE(ReadsFroxelsPerPixel(grid, kEarth, 40e3, 0.0, 0.0));
  // A 4 km cliff face 1 km away: optical thickness 0.15, 6.3 slices.
  EXPECT_TRUE(ReadsFroxelsPerPixel(grid, kEarth, 4e3, 4e3, 1e3));
  // A 90 m terrain cell under the camera spans 0.84 slices but only 0.0034 of optical thickness.
  EXPECT_FALSE(ReadsFroxelsPerPixel(grid, kEarth, 90.0, 40.0, 0.0));
  // A 1 km cell rising 300 m, 20 km away: optical thickness 0.038, but 0.31 slices and a rise of
  // a quarter scale height.
  EXPECT_FALSE(ReadsFroxelsPerPixel(grid, kEarth, 1e3, 300.0, 20e3));
  // A box 1.4 km tall 20 km away: 0.43 slices, but its top is in air a third as dense in haze
  // as its foot.
  EXPECT_TRUE(ReadsFroxelsPerPixel(grid, kEarth, 1.4e3, 1.4e3, 20e3));
}

TEST(SurfaceReads, EitherConditionAloneIsEnough) {
  const FroxelGrid grid;
  // The bound on slices: an edge just over half a slice at a slice centre is read per pixel when
  // the air is optically thick, and per vertex when the air is thin.
  const double near = SliceCentreM(grid, 8);
  const double one_slice = SliceCentreM(grid, 9) - near;
  const AirScales thick{.ground_extinction_per_m = 1.0 / (0.1 * one_slice), .smallest_scale_height_m = 1200.0};
  const AirScales thin{.ground_extinction_per_m = 0.005 / one_slice, .smallest_scale_height_m = 1200.0};
  EXPECT_FALSE(ReadsFroxelsPerPixel(grid, thick, 0.45 * one_slice, 0.0, near));
  EXPECT_TRUE(ReadsFroxelsPerPixel(grid, thick, 0.55 * one_slice, 0.0, near));
  EXPECT_FALSE(ReadsFroxelsPerPixel(grid, thin, 0.55 * one_slice, 0.0, near));
  // The bound on the rise: within half a slice, a triangle rising more than half the scale height
  // is read per pixel in thick air.
  EXPECT_FALSE(ReadsFroxelsPerPixel(grid, thick, 0.45 * one_slice, 590.0, near));
  EXPECT_TRUE(ReadsFroxelsPerPixel(grid, thick, 0.45 * one_slice, 610.0, near));
  // The bound on optical thickness: an edge of 20 slices is per vertex in air 0.009 thick along
  // it, per pixel in air 0.011 thick.
  const double edge = SliceCentreM(grid, 28) - near;
  EXPECT_FALSE(ReadsFroxelsPerPixel(grid, {0.009 / edge, 1200.0}, edge, edge, near));
  EXPECT_TRUE(ReadsFroxelsPerPixel(grid, {0.011 / edge, 1200.0}, edge, edge, near));
}

TEST(SurfaceReads, ADistanceBehindTheCameraCountsAsTheCamera) {
  const FroxelGrid grid;
  EXPECT_DOUBLE_EQ(SliceSpan(grid, 500.0, -50.0), SliceSpan(grid, 500.0, 0.0));
}

// The distance a chunk's choice is made by agrees with the rule itself either side of it, for
// ground cells of every size the terrain has, thin and thick in the air, low and high rises.
TEST(SurfaceReads, PerPixelReadsWithinTheDistanceTheRuleSays) {
  const FroxelGrid grid;
  const AirScales air = MakeAirScales(AtmosphereParameters::Earth());
  int within_the_volume = 0;
  for (double edge : {1.0, 25.0, 100.0, 400.0, 3200.0, 25600.0})
    for (double rise : {0.0, 100.0, 2000.0}) {
      const double within = PerPixelReadsWithinM(grid, air, edge, rise);
      for (double distance : {0.0, 1.0, 1e2, 1e3, 1e4, 1e5, 1e6})
        EXPECT_EQ(ReadsFroxelsPerPixel(grid, air, edge, rise, distance), distance < within)
            << "edge " << edge << " m, rise " << rise << " m, at " << distance << " m";
      if (within > 0.0 && std::isfinite(within)) {
        ++within_the_volume;
        // The bisection ends within a few ulps of where the rule flips.
        EXPECT_TRUE(ReadsFroxelsPerPixel(grid, air, edge, rise, within * (1.0 - 1e-9))) << edge << ", " << rise;
        EXPECT_FALSE(ReadsFroxelsPerPixel(grid, air, edge, rise, within)) << edge << ", " << rise;
      }
    }
  EXPECT_GT(within_the_volume, 3);
}

}  // namespace
}  // namespace aerial
