#pragma once
// Where the froxels' rows and columns sit on the screen: the rows gathered around the horizon, the
// columns around the sun's glow.
//
// Rows. Near the horizon a view ray runs tens of kilometres through the air close to the ground,
// and a row of froxels there spans hundreds of metres of height at its far end (a 32-row grid over
// a 50 degree field is 1.6 degrees a row: 1.4 km at 50 km). The mountains' shadows in the air and
// the air's density change over less than that, so rows spread evenly over the screen blur them:
// at evening even rows leave the froxels 4.4% off the per-pixel march beyond 1 km, 94% of it in the
// distant ground at the horizon, and four times as many even rows 1.0%. Rows far above the horizon
// see the sky, which reads its own table, and rows far below it see nearby ground through little
// air; so the rows are moved toward the horizon instead of added (as the sky-view table gathers its
// rows at the horizon, Hillaire 2020).
//
// Columns. Toward a low sun the shadows that the ridges under it cast in the air are lit by Mie's
// forward peak, tens to hundreds of times the light of the rest of the view (Cornette-Shanks with
// g = 0.8 is 525 times its value at 90 degrees toward the sun, 254 times at 10 degrees from it, 78
// at 20), so an error of the froxels''
// interpolation across those shadows' edges is multiplied as much: at sunrise 87% of the froxels'
// error beyond 1 km lay in the ground 10-30 km away within 0.12 screen widths of the sun's column,
// between its row and the horizon's. There the columns gather at the sun's column and the rows'
// focus rises toward the sun's row; away from the glow both stay as they were.
//
// Each axis maps a screen coordinate s (uv, 0 at the left or top) to the froxels' coordinate v
// along it (texture coordinate, texel centres at (j + 0.5) / N) by
//   v(s) = (asinh((s - focus) / spread) + asinh(focus / spread)) / span,
//   span = asinh((1 - focus) / spread) + asinh(focus / spread),
// so v(0) = 0 and v(1) = 1; its density at the focus is 1 / (spread span) times the even froxels'
// and falls off as 1 / |s - focus| beyond the spread (a large spread is near even). Its inverse is
//   s(v) = focus + spread sinh(v span - asinh(focus / spread)).
// shaders/include/froxel_axes.glsl is the GLSL side; tests/cpu_gpu_mapping_test.cpp holds the two
// together.
#include <array>

#include <glm/glm.hpp>

#include "aerial/shader_abi/frame_block.h"

namespace aerial {

// The half-width, in screen heights, of the band of rows around the horizon: there the rows are
// 3.3 times as dense as even rows at a centred focus, and 0.33 times at the screen's edges. Froxel
// vs per-pixel beyond 1 km at 320x180, 32x32x32 (Render.FroxelMatchesPerPixel*), even columns,
// even rows / a spread of 0.03 / 0.05 / 0.08 / 0.12: noon without shadows 0.31 / 0.09 / 0.11 /
// 0.33 / 0.80%, evening 4.39 / 1.20 / 1.27 / 1.24 / 1.78%, sunrise 4.43 / 2.89 / 2.81 / 2.81 /
// 2.95%, sunset 15.7 / 8.2 / 7.3 / 9.2 / 9.3%. Focusing higher, on the mountains rather than the
// sea-level horizon, everywhere, helped sunrise by 0.3% and cost every other view more. These
// figures and the columns' below rank the layouts; the kept layout's own figures are those of
// Render.FroxelMatchesPerPixel* (render_test.cpp).
inline constexpr double kFroxelRowSpread = 0.05;
// Where the band below the horizon ends: at the screen row where the sea-level ground is this far
// (a camera on the ground sees none so far and keeps kFroxelRowSpread). The far ground's error was
// in the distant ground at 30-100 km (evening) and 10-30 km (sunrise); from 30 km up (the
// high-altitude preset) every ground pixel is farther than this and the rows stay near even (a
// spread of half the screen), where gathering them at the horizon would take its froxel vs
// per-pixel sky from 0.87% to 1.50%.
inline constexpr double kFroxelRowsFarGroundM = 20e3;

// The columns' half-width at the sun's glow, in screen widths, and how fast the glow fades out of
// the view: the sun's angular distance from the nearest point of the screen halves its weight
// every kFroxelGlowHalvingDeg (the forward peak above halves every 8-10 degrees near the sun). The
// columns' spread is kFroxelColumnSpread over that weight, at most 100 times it (near even for a
// sun behind the camera). Where the sun is above the band of rows at the horizon (focus and
// spread), the rows' focus rises by that weight times half the sun's height above the band, at
// most kFroxelRowsRiseToSun.
// Froxel vs per-pixel beyond 1 km, 32x32x32 at 320x180: sunrise 2.81% with even columns and the
// rows at the horizon; 2.32% with the columns at the sun (at a fixed focus of 0.45: 2.31 / 2.36 /
// 2.39% at a spread of 0.03 / 0.05 / 0.1); 1.78% with the rows' focus risen (0.052 screen heights;
// half the whole way from the horizon, 0.077, gave 1.74%, but it also moved the rows at sunset,
// whose sun is in the band, taking its froxels without shadows from 0.42% to 1.01%). Evening, its
// sun 20 degrees off the screen: 1.27% -> 1.20%. Sunset with shadows, whose error lies along the
// far ridge across a third of the screen's width: 7.27% -> 7.68% (a spread of 0.08: 7.47%, and
// sunrise 1.84%).
inline constexpr double kFroxelColumnSpread = 0.05;
inline constexpr double kFroxelGlowHalvingDeg = 8.0;
inline constexpr double kFroxelRowsRiseToSun = 2.0 * kFroxelRowSpread;

struct FroxelAxis {
  double focus = 0.5;  // the screen coordinate where the froxels are densest (uv x or y)
  double spread = kFroxelRowSpread;

  double Span() const;
  double Coordinate(double screen) const;  // froxel texture coordinate of a screen coordinate
  double ScreenPosition(double coordinate) const;  // the inverse

  // As FrameUniforms::froxel_rows and froxel_columns hold them: focus, spread, span and
  // asinh(focus / spread), the last two so that the shaders do not compute them per read.
  std::array<float, 4> Packed() const;
  static FroxelAxis Unpack(const std::array<float, 4>& packed);
};

struct FroxelAxes {
  FroxelAxis columns{.focus = 0.5, .spread = kFroxelColumnSpread};
  FroxelAxis rows;

  glm::dvec2 Coordinates(glm::dvec2 screen) const;  // froxel texture xy of a screen position
  glm::dvec2 ScreenPosition(glm::dvec2 coordinates) const;  // the inverse
};

// The rows and columns of a frame. The rows are focused where the sea-level horizon (the direction
// of the camera's ray tangent to the planet of radius planet_radius_m) crosses the screen's
// vertical centre line, or at the screen's edge nearest to it when the horizon is off the screen,
// and spread at least down to the far ground (kFroxelRowsFarGroundM); under the sun's glow their
// focus rises toward the sun, and the columns gather at the sun's column (kFroxelColumnSpread).
// Reads the frame's camera_planet_position, sun_direction, view_projection and
// inverse_view_projection.
FroxelAxes PlaceFroxelAxes(const FrameUniforms& frame, double planet_radius_m);
// The axes a frame's block holds (FrameUniforms::froxel_columns and froxel_rows).
FroxelAxes AxesOf(const FrameUniforms& frame);

}  // namespace aerial
