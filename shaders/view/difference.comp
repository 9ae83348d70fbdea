#version 450
#extension GL_GOOGLE_include_directive : require
// Debug view of the difference between the frames rendered with the 3D and the 4D tables (same
// scene, camera and options): per pixel the largest relative channel difference
// e = max_c |L3_c - L4_c| / max_c L4_c, shown on MATLAB's "hot" colour map in display values:
// black at 0, through red and yellow, to white at full_scale and above.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform sampler2D radiance_4d;
layout(set = 0, binding = 1) uniform sampler2D radiance_3d;
layout(set = 0, binding = 2) writeonly uniform image2D display;  // 8-bit UNORM, RGBA or BGRA
layout(push_constant) uniform Push { float full_scale; } push;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(display)))) return;
  vec3 l4 = texelFetch(radiance_4d, pixel, 0).rgb;
  vec3 l3 = texelFetch(radiance_3d, pixel, 0).rgb;
  vec3 difference = abs(l3 - l4);
  float reference = max(max(l4.r, l4.g), l4.b);
  float e = max(max(difference.r, difference.g), difference.b) / max(reference, 1e-20);
  float t = clamp(e / push.full_scale, 0.0, 1.0);
  imageStore(display, pixel, vec4(clamp(vec3(3.0 * t, 3.0 * t - 1.0, 3.0 * t - 2.0), 0.0, 1.0), 1.0));
}
