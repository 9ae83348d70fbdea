#pragma once
// Where the froxel rows sit on the screen: gathered around the horizon.
//
// Near the horizon a view ray runs tens of kilometres through the air close to the ground, and a
// row of froxels there spans hundreds of metres of height at its far end (a 32-row grid over a
// 50 degree field is 1.6 degrees a row: 1.4 km at 50 km). The mountains' shadows in the air and the
// air's density change over less than that, so rows spread evenly over the screen blur them: at
// evening even rows leave the froxels 4.4% off the per-pixel march beyond 1 km, 94% of it in the
// distant ground at the horizon, and four times as many even rows 1.0%. Rows far above the horizon see
// the sky, which reads its own table, and rows far below it see nearby ground through little air;
// so the rows are moved toward the horizon instead of added (as the sky-view table gathers its
// rows at the horizon, Hillaire 2020).
//
// The mapping from a screen row y (uv y, 0 at the top) to the froxels' row coordinate v (texture
// y, texel centres at (j + 0.5) / H) is
//   v(y) = (asinh((y - focus) / spread) + asinh(focus / spread)) / span,
//   span = asinh((1 - focus) / spread) + asinh(focus / spread),
// so v(0) = 0 and v(1) = 1; its density at the focus is 1 / (spread span) times the even rows'
// and falls off as 1 / |y - focus| beyond the spread. Its inverse is
//   y(v) = focus + spread sinh(v span - asinh(focus / spread)).
// shaders/include/froxel_rows.glsl is the GLSL side; tests/cpu_gpu_mapping_test.cpp holds the two
// together.
#include <array>

#include "aerial/shader_abi/frame_block.h"

namespace aerial {

// The half-width, in screen heights, of the band of rows around the horizon: there the rows are
// 3.3 times as dense as even rows at a centred focus, and 0.33 times at the screen's edges. Froxel
// vs per-pixel beyond 1 km at 320x180, 32x32x32 (Render.FroxelMatchesPerPixel*), even rows / a
// spread of 0.03 / 0.05 / 0.08 / 0.12: noon without shadows 0.31 / 0.09 / 0.11 / 0.33 / 0.80%,
// evening 4.39 / 1.20 / 1.27 / 1.24 / 1.78%, sunrise 4.43 / 2.89 / 2.81 / 2.81 / 2.95%, sunset
// 15.7 / 8.2 / 7.3 / 9.2 / 9.3%. Focusing higher, on the mountains rather than the sea-level
// horizon, helped sunrise by 0.3% and cost every other view more.
inline constexpr double kFroxelRowSpread = 0.05;
// Where the band below the horizon ends: at the screen row where the sea-level ground is this far
// (a camera on the ground sees none so far and keeps kFroxelRowSpread). The far ground's error was
// in the distant ground at 30-100 km (evening) and 10-30 km (sunrise); from 30 km up (the
// high-altitude preset) every ground pixel is farther than this and the rows stay near even (a
// spread of half the screen), where gathering them at the horizon would take its froxel vs
// per-pixel sky from 0.87% to 1.50%.
inline constexpr double kFroxelRowsFarGroundM = 20e3;

struct FroxelRows {
  double focus = 0.5;  // the screen row where the rows are densest (uv y)
  double spread = kFroxelRowSpread;

  double Span() const;
  double RowCoordinate(double screen_y) const;  // froxel texture y of a screen row
  double ScreenRow(double row_coordinate) const;  // the inverse

  // As FrameUniforms::froxel_rows holds them: focus, spread, span and asinh(focus / spread), the
  // last two so that the shaders do not compute them per read.
  std::array<float, 4> Packed() const;
  static FroxelRows Unpack(const std::array<float, 4>& packed);
};

// The rows of a frame: focused where the sea-level horizon (the direction of the camera's ray
// tangent to the planet of radius planet_radius_m) crosses the screen's vertical centre line, or
// at the screen's edge nearest to it when the horizon is off the screen, and spread at least down
// to the far ground (kFroxelRowsFarGroundM). Reads the frame's camera_planet_position and
// inverse_view_projection.
FroxelRows FroxelRowsAroundHorizon(const FrameUniforms& frame, double planet_radius_m);

}  // namespace aerial
