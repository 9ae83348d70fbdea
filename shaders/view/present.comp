#version 450
#extension GL_GOOGLE_include_directive : require
// The viewer's picture: the renderer's linear radiance, times the exposure, through the same ACES
// and sRGB curves as a PNG (tone_map.glsl), into the 8-bit image the swapchain shows.
#include "tone_map.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform sampler2D radiance_image;
layout(set = 0, binding = 1) writeonly uniform image2D display;  // 8-bit UNORM, RGBA or BGRA
layout(push_constant) uniform Push { float exposure; } push;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(display)))) return;
  vec3 radiance = texelFetch(radiance_image, pixel, 0).rgb;
  imageStore(display, pixel, vec4(ToneMap(radiance * push.exposure), 1.0));
}
