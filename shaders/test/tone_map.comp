#version 450
#extension GL_GOOGLE_include_directive : require
// The viewer's tone map (tone_map.glsl) as float, for the test against the CPU's ToneMapChannel
// (the 8-bit display image would hide differences below 1/255).
#include "tone_map.glsl"
layout(local_size_x = 64) in;
layout(set = 0, binding = 0) uniform sampler2D radiance_image;  // a width x 1 ramp
layout(set = 0, binding = 1) writeonly uniform image2D display_values;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.x, 0);
  if (pixel.x >= imageSize(display_values).x) return;
  imageStore(display_values, pixel, vec4(ToneMap(texelFetch(radiance_image, pixel, 0).rgb), 1.0));
}
