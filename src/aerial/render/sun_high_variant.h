#pragma once
// When a pass may take its variant for a high sun (AERIAL_SUN_HIGH_EVERYWHERE,
// shaders/include/transmittance.glsl). A CPU rasterizer runs both sides of every branch
// (shaders/include/definitions.glsl, "Control flow"), so a march's per-point choices between the
// sun's whole disc and its centre, and between J_ms's blends in and out of the Earth's shadow,
// cost it both sides at every step. Where the sun is high over every point the pass marches, a
// variant compiled with those choices made computes the same values without them: the froxel
// pass (froxel/froxel_pass_variant.h) and the marched per-pixel path's opaque pass
// (Renderer::Record).
#include "aerial/shader_abi/frame_block.h"

namespace aerial {

// The shaders read the sun's disc at its centre alone where x alpha, the centre's height above the
// cut-off cosine over the cut-off's sine, exceeds SUN_DISC_ONE_TAP_ELEVATION (0.1745,
// shaders/include/transmittance.glsl). For a cut-off at or below the horizontal, x alpha is at
// least the sine of the sun's elevation above the horizontal, so a sine above it suffices.
inline constexpr double kSunDiscOneTapSine = 0.1745;

// Whether the sun is more than that above the horizontal, with a margin of 0.005 for the shaders'
// float rounding, at every point above the ground within distance_m of the frame's camera. Then
// each of those points reads the disc's centre alone, and J_ms linearly in mu_s (its upper mu_s
// texel is above the horizon).
bool SunHighWithin(const FrameUniforms& frame, double distance_m, double bottom_radius_m);

}  // namespace aerial
