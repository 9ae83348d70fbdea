#version 450
#extension GL_GOOGLE_include_directive : require
// The sky's full-screen triangle (fullscreen.vert), with what its fragments share worked out once
// per vertex instead of once per pixel: the view ray through each corner (a pinhole camera's rays
// are affine in screen position before normalization, so interpolating them is exact), the
// camera's local frame that the sky-view table is laid out in (sky_view.glsl), and the horizon the
// table was made for (its alpha, sky_view.comp): read by every vertex, the same texel.
#include "sky_view.glsl"
layout(set = 0, binding = 7) uniform sampler2D rayleigh_sky;
layout(location = 0) out vec3 view_ray;  // camera-relative world direction, not normalized
layout(location = 1) flat out vec3 up;
layout(location = 2) flat out vec3 toward_sun;
layout(location = 3) flat out float table_horizon;  // the table's horizon's zenith angle

void main() {
  vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2) * 2.0 - 1.0;
  gl_Position = vec4(corner, 0.0, 1.0);
  vec4 world = AERIAL_FRAME.inverse_view_projection * vec4(corner, 0.5, 1.0);
  view_ray = world.xyz / world.w;
  vec3 side;
  GetSkyViewFrame(up, toward_sun, side);
  table_horizon = texelFetch(rayleigh_sky, ivec2(0), 0).a;
}
