#version 450
#extension GL_GOOGLE_include_directive : require
// The viewer's picture, drawn straight into the window's image: the renderer's linear radiance,
// times the exposure, through the same ACES and sRGB curves as a PNG (tone_map.glsl). The
// radiance is sampled bilinearly at the window pixel's center, which upscales a frame rendered
// at a lower --render-scale and reads texel centers exactly at scale 1.
#include "tone_map.glsl"
layout(set = 0, binding = 0) uniform sampler2D radiance_image;
layout(push_constant) uniform Push {
  vec2 target_size;  // the window's pixels
  float exposure;
} push;
layout(location = 0) out vec4 color;  // 8-bit UNORM, RGBA or BGRA

void main() {
  vec3 radiance = textureLod(radiance_image, gl_FragCoord.xy / push.target_size, 0.0).rgb;
  color = vec4(ToneMap(radiance * push.exposure), 1.0);
}
