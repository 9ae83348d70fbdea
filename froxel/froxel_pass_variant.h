#pragma once
// Which froxel pass a frame builds its volume with (shaders/frame/froxel.comp): the general one,
// or its variant for a sun high over every froxel (sun_high_variant.h says why it is faster on
// a CPU rasterizer and when it computes the same values).
#include "froxel/sun_high_variant.h"

namespace aerial {

enum class FroxelPassVariant {
  kGeneral,  // any sun
  kSunHigh,  // the sun's centre alone, J_ms linear in mu_s: only where SunHighAtEveryFroxel
};

// SunHighWithin the froxels' far distance (frame.froxel_depth.x).
bool SunHighAtEveryFroxel(const FrameUniforms& frame, double bottom_radius_m);

// kSunHigh where SunHighAtEveryFroxel, else kGeneral.
FroxelPassVariant ChooseFroxelPassVariant(const FrameUniforms& frame, double bottom_radius_m);

}  // namespace aerial
