#version 450
#extension GL_GOOGLE_include_directive : require
// The per-pixel modes' sky (sky.frag): a full-screen triangle at depth 0 with the view ray through
// each corner (a pinhole camera's rays are affine in screen position before normalization, so
// interpolating them is exact).
#include "frame.glsl"
layout(location = 0) out vec3 view_ray;  // camera-relative world direction, not normalized

void main() {
  vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2) * 2.0 - 1.0;
  gl_Position = vec4(corner, 0.0, 1.0);
  vec4 world = frame.inverse_view_projection * vec4(corner, 0.5, 1.0);
  view_ray = world.xyz / world.w;
}
