#pragma once
// Where an opaque surface reads the froxel volume (opaque.vert, opaque_fragment.glsl). On most
// triangles its vertices read it and its fragments interpolate what they read (O'Neil 2005, GPU
// Gems 2 ch. 16: the scattering per vertex, the phase functions per pixel); on a CPU rasterizer,
// which runs a fragment shader on every 4x4 block a triangle touches, that replaces three
// trilinear taps per fragment.
//
// Interpolating between the vertices differs from the per-pixel read only where the air along
// the view ray changes in a way a straight line across the triangle cannot follow. Either of two
// conditions rules that out:
// - the triangle is thin in the air: its longest edge has an optical thickness (at the ground,
//   the densest air) of at most kMaxEdgeOpticalThickness, so inscatter and transmittance change
//   by at most about that fraction across it, and an interpolation's error is a fraction of that;
// - the triangle is small in the volume: it spans at most kMaxSliceSpan of the volume's depth
//   slices (the slices' quadratic spacing, froxel_depth.glsl, makes them thick only where the air
//   is far), so the per-pixel reads interpolate between the same two slices, and it rises at most
//   kMaxRiseOfScaleHeight of the air's smallest scale height, so the air along the rays to its
//   vertices is alike (a kilometre-high face far away sees air of different density at its top
//   and at its foot). Interpolating an exponential linearly over a rise of x scale heights
//   misses by at most x^2 / 8 of it: 3% of the haze's inscatter at half a scale height.
// A triangle that fails both, e.g. a ground quad reaching from the camera to the horizon, or a
// kilometres-high cliff face, is read per pixel.
#include "aerial/atmosphere.h"
#include "aerial/froxel_grid.h"

namespace aerial {

inline constexpr double kMaxEdgeOpticalThickness = 0.01;
inline constexpr double kMaxSliceSpan = 0.5;
inline constexpr double kMaxRiseOfScaleHeight = 0.5;

// How many of the grid's slices a triangle may span in depth, when none of its edges is longer
// than edge_m and none of its points is nearer the camera than distance_m: the depth coordinate
// slices * sqrt(d / far) grows fastest nearest the camera.
double SliceSpan(const FroxelGrid& grid, double edge_m, double distance_m);

// What the rule needs of the air: its largest extinction coefficient (m^-1) over the channels at
// the ground, and its smallest exponential scale height (m) among the scattering layers.
struct AirScales {
  double ground_extinction_per_m = 0.0;
  double smallest_scale_height_m = 0.0;
};
AirScales MakeAirScales(const AtmosphereParameters& atmosphere);

// For a triangle whose edges are at most edge_m long and rise at most rise_m, and whose points are
// at least distance_m from the camera.
bool ReadsFroxelsPerPixel(const FroxelGrid& grid, const AirScales& air, double edge_m, double rise_m,
                          double distance_m);

// The distance within which ReadsFroxelsPerPixel holds for triangles of these edges and rises, so
// that a chunk's choice is one comparison as the camera moves (the GPU's selection makes it): the
// rule changes with the distance only through SliceSpan, which never grows farther away. 0: never
// per pixel; infinity: at any distance.
double PerPixelReadsWithinM(const FroxelGrid& grid, const AirScales& air, double edge_m, double rise_m);

}  // namespace aerial
