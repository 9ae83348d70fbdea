#pragma once
// When a pass may take its variant for a high sun (AERIAL_SUN_HIGH_EVERYWHERE,
// shaders/include/transmittance.glsl). A CPU rasterizer runs both sides of every branch
// (shaders/include/definitions.glsl, "Control flow"), so a march's per-point choices between the
// sun's whole disc and its centre, and between J_ms's blends in and out of the Earth's shadow,
// cost it both sides at every step. Where the sun is high over every point a pass marches, a
// variant compiled with those choices made computes the same values without them: the froxel
// pass (froxel/froxel_pass_variant.h), the marched per-pixel path's mesh passes and sky
// (Renderer::MeshPipelinesFor, Renderer::SkyPipelineFor), and the sky-view lattice's correction
// (Renderer::SkyViewCorrectionPipelineFor).
#include "aerial/atmosphere.h"
#include "aerial/shader_abi/frame_block.h"

namespace aerial {

// The shaders read the sun's disc at its centre alone where x alpha, the centre's height above the
// cut-off cosine over the cut-off's sine, exceeds SUN_DISC_ONE_TAP_ELEVATION (0.1745,
// shaders/include/transmittance.glsl). For a cut-off at or below the horizontal, x alpha is at
// least the sine of the sun's elevation above the horizontal, so a sine above it suffices.
// tests/cpu_gpu_mapping_test.cpp holds it and the two functions below to their GLSL.
inline constexpr double kSunDiscOneTapSine = 0.1745;

// The tables' mu_s axis (mappings.glsl, GetUnitRangeFromMuS and GetMuSFromUnitRange) in double:
// x in [0, 1] puts texel centres 0 .. n - 1 at x (n - 1); mu_s_min is the atmosphere's.
double UnitRangeFromMuS(double mu_s, double mu_s_min);
double MuSFromUnitRange(double x, double mu_s_min);

// Whether a sun whose elevation above the horizontal of a camera at radius camera_radius_m has
// sine sun_sine is more than that above the horizontal, with a margin of 0.005 for the shaders'
// float rounding, at every point above the ground within distance_m of the camera. Then each of
// those points reads the disc's centre alone, and J_ms linearly in mu_s (its upper mu_s texel is
// above the horizon).
bool SunHighWithin(double camera_radius_m, double sun_sine, double distance_m, double bottom_radius_m);
// The same for the frame's camera and sun.
bool SunHighWithin(const FrameUniforms& frame, double distance_m, double bottom_radius_m);

// The longest view ray from radius r that meets no ground: it grazes the ground, then leaves the
// atmosphere.
double LongestSkyRayM(double r, double bottom_radius_m, double top_radius_m);

// The sine of the lowest sun that the per-pixel sky's correction of the Earth's shadow marches for
// a sun at mu_s (shaders/include/sky_lookup.glsl, GetSingleScatteringSuns): the mu_s texel below
// the two that the tables' read blends (UnitRangeFromMuS), taking a sun within 0.01 texel of a
// texel's centre on the lower side.
double LowestSkyCorrectionSunSine(double mu_s, double mu_s_min, int mu_s_texels);

// Whether every sun that the per-pixel sky marches is high (SunHighWithin) at every point of every
// sky ray of the frame's camera.
bool SunHighOverEverySkyRay(const FrameUniforms& frame, const AtmosphereParameters& atmosphere, int mu_s_texels);

}  // namespace aerial
