#version 450
#extension GL_GOOGLE_include_directive : require
// The viewer's picture, drawn straight into the window's image: the renderer's linear radiance,
// times the white balance's gains and the exposure, through the same ACES and sRGB curves as a PNG
// (tone_map.glsl). The radiance of a frame rendered at a lower --render-scale is sampled
// bilinearly at the window pixel's center (upscaled).
#include "display.glsl"
layout(set = 0, binding = 0) uniform sampler2D radiance_image;
layout(push_constant) uniform Push {
  vec2 target_size;  // the window's pixels
  float exposure;
  vec3 white_balance;  // gains per channel ({1, 1, 1}: none)
} push;
layout(location = 0) out vec4 color;  // 8-bit, RGBA or BGRA

void main() {
  // A frame of the window's size is read texel for texel (no filtering to pay for).
  vec3 radiance = ivec2(push.target_size) == textureSize(radiance_image, 0)
                      ? texelFetch(radiance_image, ivec2(gl_FragCoord.xy), 0).rgb
                      : textureLod(radiance_image, gl_FragCoord.xy / push.target_size, 0.0).rgb;
  color = DisplayColor(ToneMapLinear(radiance * push.white_balance * push.exposure));
}
