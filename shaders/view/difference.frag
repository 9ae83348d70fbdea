#version 450
#extension GL_GOOGLE_include_directive : require
// Debug view of the difference between the frames rendered with the 3D and the 4D tables (same
// scene, camera and options): per pixel the largest relative channel difference
// e = max_c |L3_c - L4_c| / max_c L4_c, shown on MATLAB's "hot" colour map (in linear display
// values): black at 0, through red and yellow, to white at full_scale and above.
layout(set = 0, binding = 0) uniform sampler2D radiance_4d;
layout(set = 0, binding = 1) uniform sampler2D radiance_3d;
#include "display.glsl"
layout(push_constant) uniform Push {
  vec2 target_size;  // the window's pixels
  float full_scale;
} push;
layout(location = 0) out vec4 color;  // 8-bit, RGBA or BGRA

void main() {
  vec2 uv = gl_FragCoord.xy / push.target_size;
  vec3 l4 = textureLod(radiance_4d, uv, 0.0).rgb;
  vec3 l3 = textureLod(radiance_3d, uv, 0.0).rgb;
  vec3 difference = abs(l3 - l4);
  float reference = max(max(l4.r, l4.g), l4.b);
  float e = max(max(difference.r, difference.g), difference.b) / max(reference, 1e-20);
  float t = clamp(e / push.full_scale, 0.0, 1.0);
  color = DisplayColor(clamp(vec3(3.0 * t, 3.0 * t - 1.0, 3.0 * t - 2.0), 0.0, 1.0));
}
