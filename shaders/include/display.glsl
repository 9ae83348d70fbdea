// What the viewer's display passes write: linear display values in [0, 1], sRGB-encoded by the
// target when its format is an _SRGB one (on a CPU rasterizer the format's conversion costs less
// than the 1/2.4 power in the shader), by the shader otherwise.
#ifndef AERIAL_DISPLAY_GLSL
#define AERIAL_DISPLAY_GLSL
#include "tone_map.glsl"

// 1 when the target's format encodes sRGB itself: a specialization constant of the pipeline.
layout(constant_id = 1) const int kTargetEncodesSrgb = 0;

vec4 DisplayColor(vec3 linear_display) {
  return vec4(kTargetEncodesSrgb == 1 ? linear_display : SrgbOetf(linear_display), 1.0);
}

// Linear display values from here up encode to within half an 8-bit step of 1, so round to white
// without the dither: the sRGB EOTF of 1 - 0.5 / 255 (kDitheredBelow in tone_map.cpp).
const float kDitheredBelowLinear = 0.99554525;

// DisplayColor with the PNG's dither of `steps` 8-bit steps (DitherSteps) added to the encoded
// values, black and white (whatever rounds to 255: the curve only nears 1) left alone. An _SRGB target encodes after the shader, so there the
// dither is moved into linear values by the encoding's slope, d linear / d encoded, taken as
// 2 sqrt(linear) (a gamma of 2) but never under the linear toe's 1 / 12.92: within a fraction of
// a step of the encoded dither, without a power per pixel.
vec4 DitheredDisplayColor(vec3 linear_display, float steps) {
  vec3 inside = vec3(greaterThan(linear_display, vec3(0.0))) * vec3(lessThan(linear_display, vec3(kDitheredBelowLinear)));
  if (kTargetEncodesSrgb == 1) {
    vec3 slope = max(2.0 * sqrt(linear_display), vec3(1.0 / 12.92));
    return vec4(linear_display + inside * slope * (steps / 255.0), 1.0);
  }
  return vec4(SrgbOetf(linear_display) + inside * (steps / 255.0), 1.0);
}

#endif
