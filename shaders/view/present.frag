#version 450
#extension GL_GOOGLE_include_directive : require
// The viewer's picture, drawn straight into the window's image: the renderer's linear radiance,
// times the white balance's gains and the exposure, through the same curve, encoding and dither as
// a PNG (tone_map.glsl). A frame of the window's size is read texel for texel; one rendered at a lower
// --render-scale is sampled bilinearly at the window pixel's center (upscaled). Which of the two
// is a pipeline's constant, so that each pixel makes one read (a CPU rasterizer would make both
// under a branch).
#include "display.glsl"
layout(constant_id = 2) const bool kResampled = false;
layout(set = 0, binding = 0) uniform sampler2D radiance_image;
layout(push_constant) uniform Push {
  vec2 target_size;  // the window's pixels
  float exposure;
  vec3 white_balance;  // gains per channel ({1, 1, 1}: none)
} push;
layout(location = 0) out vec4 color;  // 8-bit, RGBA or BGRA

void main() {
  vec3 radiance = kResampled ? textureLod(radiance_image, gl_FragCoord.xy / push.target_size, 0.0).rgb
                             : texelFetch(radiance_image, ivec2(gl_FragCoord.xy), 0).rgb;
  color = DitheredDisplayColor(ToneMapLinear(radiance * push.white_balance * push.exposure),
                               DitherSteps(uvec2(gl_FragCoord.xy)));
}
