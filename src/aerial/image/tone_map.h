#pragma once
// The display transform of PNG pictures and the viewer. EXR output skips it entirely and keeps
// the radiance, so nothing quantitative should ever be read from a PNG.
#include <array>
#include <cstdint>
#include <vector>

#include "aerial/image.h"

namespace aerial {

// The display curve before the sRGB encoding: radiance already multiplied by the white balance
// and the exposure, to linear display values in [0, 1] (negative and NaN channels count as 0).
// Khronos PBR Neutral (2024): the identity but for a small toe up to 0.76, then the brightest
// channel compressed toward 1 with the colour scaled with it (its hue kept) and mixed toward
// white only as far as the compression goes. A per-channel filmic curve (ACES) bends each channel
// on its own, which turns an orange sunset band yellow-white and shifts the sky's hues.
// The viewer's GPU curve, shaders/include/tone_map.glsl, mirrors it line by line.
std::array<double, 3> DisplayCurve(const std::array<double, 3>& exposed_radiance);

// DisplayCurve, then the sRGB OETF: display values in [0, 1] before rounding to 8 bits.
std::array<double, 3> ToneMapColour(const std::array<double, 3>& exposed_radiance);

// The dither added to a display value before it is rounded to 8 bits, in 8-bit steps: triangular
// noise over (-1, 1) from an integer hash of the pixel, so that smooth gradients (a sky) show no
// bands and the same frame always gives the same bytes. The viewer's present pass
// (shaders/include/tone_map.glsl, Dither) computes the same numbers.
double DitherSteps(uint32_t x, uint32_t y);

}  // namespace aerial
