#pragma once
// The display curve of PNG previews and the viewer, one channel at a time. EXR output skips it
// entirely and keeps the radiance, so nothing quantitative should ever be read from a PNG.
#include <cstdint>
#include <vector>

#include "aerial/image.h"

namespace aerial {

// One colour channel of ToneMapToSrgb8's curve (aerial/image.h) before rounding: radiance already multiplied by the exposure,
// to the sRGB-encoded display value in [0, 1] (negative and NaN give 0). The viewer's GPU tone map,
// shaders/include/tone_map.glsl, mirrors it line by line.
double ToneMapChannel(double exposed_radiance);

}  // namespace aerial
