#pragma once
// Which froxel pass a frame builds its volume with (shaders/frame/froxel.comp). A CPU rasterizer
// runs both sides of every branch (shaders/include/definitions.glsl, "Control flow"), so the
// pass's per-point choices between the sun's whole disc and its centre, and between J_ms's blends
// in and out of the Earth's shadow, cost it both sides at every march step. Where the sun is high
// over every froxel, a variant compiled with those choices made (kSunHigh) computes the same
// values without them.
#include "aerial/shader_abi/frame_block.h"

namespace aerial {

enum class FroxelPassVariant {
  kGeneral,  // any sun
  kSunHigh,  // the sun's centre alone, J_ms linear in mu_s: only where SunHighAtEveryFroxel
};

// The shaders read the sun's disc at its centre alone where x alpha, the centre's height above the
// cut-off cosine over the cut-off's sine, exceeds SUN_DISC_ONE_TAP_ELEVATION (0.1745,
// shaders/include/transmittance.glsl). For a cut-off at or below the horizontal, x alpha is at
// least the sine of the sun's elevation above the horizontal, so a sine above it suffices.
inline constexpr double kSunDiscOneTapSine = 0.1745;

// Whether the sun is more than that above the horizontal, with a margin of 0.005 for the shaders'
// float rounding, at every point within the froxels' far distance (frame.froxel_depth.x) of the
// camera. Then each of those points reads the disc's centre alone, and J_ms linearly in mu_s
// (its upper mu_s texel is above the horizon).
bool SunHighAtEveryFroxel(const FrameUniforms& frame, double bottom_radius_m);

// kSunHigh where SunHighAtEveryFroxel, else kGeneral.
FroxelPassVariant ChooseFroxelPassVariant(const FrameUniforms& frame, double bottom_radius_m);

}  // namespace aerial
