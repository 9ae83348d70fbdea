#version 450
#extension GL_GOOGLE_include_directive : require
// One triangle over the sun's disc on the screen (sun_disc.frag): the square of twice the disc's
// angular radius around the sun's direction, projected, is inside the triangle that this makes of
// it. A sun behind the camera makes no triangle.
#include "frame.glsl"

void main() {
  vec4 sun = AERIAL_FRAME.view_projection * vec4(AERIAL_FRAME.sun_direction.xyz, 0.0);
  // A direction e a step of angle t off the sun's lands at (sun.xy + t a.xy) / (sun.w + t a.w) with
  // a = view_projection e: at most t (|a.xy| + |ndc| |a.w|) / sun.w from the sun's ndc, for e
  // across the sun's direction. Twice the disc's radius in the larger of two such directions.
  vec3 across = normalize(cross(AERIAL_FRAME.sun_direction.xyz,
                                abs(AERIAL_FRAME.sun_direction.z) < 0.9 ? vec3(0, 0, 1) : vec3(1, 0, 0)));
  vec3 other = cross(AERIAL_FRAME.sun_direction.xyz, across);
  vec4 a = AERIAL_FRAME.view_projection * vec4(across, 0.0), b = AERIAL_FRAME.view_projection * vec4(other, 0.0);
  float ndc = sun.w > 0.0 ? length(sun.xy / sun.w) : 0.0;
  float reach = 2.0 * tan(AERIAL_ATMOSPHERE.sun_angular_radius) *
                max(length(a.xy) + ndc * abs(a.w), length(b.xy) + ndc * abs(b.w));
  // The triangle (-1, -1), (3, -1), (-1, 3) around the square [-1, 1]^2 of half-side `reach`.
  vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2) * 2.0 - 1.0;
  gl_Position = sun.w > 0.0 ? vec4(sun.xy + corner * reach, 0.0, sun.w) : vec4(0.0);
}
