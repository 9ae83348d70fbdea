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

#endif
