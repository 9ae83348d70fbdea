#version 450
#extension GL_GOOGLE_include_directive : require
// The sky's full-screen triangle (fullscreen.vert), with what its fragments share worked out once
// per vertex instead of once per pixel: the view ray through each corner (a pinhole camera's rays
// are affine in screen position before normalization, so interpolating them is exact), the
// camera's local frame that the sky-view table is laid out in (sky_view.glsl) and its horizon.
#include "sky_view.glsl"
layout(location = 0) out vec3 view_ray;  // camera-relative world direction, not normalized
layout(location = 1) flat out vec3 up;
layout(location = 2) flat out vec3 toward_sun;
layout(location = 3) flat out vec2 horizon;  // x: its zenith angle, y: its cos (mu below: ground)

void main() {
  vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2) * 2.0 - 1.0;
  gl_Position = vec4(corner, 0.0, 1.0);
  vec4 world = AERIAL_FRAME.inverse_view_projection * vec4(corner, 0.5, 1.0);
  view_ray = world.xyz / world.w;
  vec3 side;
  GetSkyViewFrame(up, toward_sun, side);
  float theta_h = HorizonZenithAngle(length(AERIAL_FRAME.camera_planet_position.xyz));
  horizon = vec2(theta_h, cos(theta_h));
}
