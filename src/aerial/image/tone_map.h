#pragma once
// Linear radiance to 8-bit display values, for PNG previews. EXR output skips this entirely and
// keeps the radiance, so nothing quantitative should ever be read from a PNG.
#include <cstdint>
#include <vector>

#include "aerial/image.h"

namespace aerial {

// Per channel: exposure, then the ACES filmic fit (Narkowicz 2015), then the sRGB OETF
// (IEC 61966-2-1), rounded to 8 bits. Alpha is coverage, not light: it is only clamped to [0, 1]
// and scaled. Returns RGBA8, row-major, top row first. Throws Error("image size") on a malformed
// image and Error("exposure") unless exposure is finite and > 0.
std::vector<uint8_t> ToneMapToSrgb8(const ImageRgbF& image, const ToneMapOptions& options);

// One colour channel of that curve before rounding: radiance already multiplied by the exposure,
// to the sRGB-encoded display value in [0, 1] (negative and NaN give 0). The viewer's GPU tone map,
// shaders/include/tone_map.glsl, mirrors it line by line.
double ToneMapChannel(double exposed_radiance);

}  // namespace aerial
