#version 450
#extension GL_GOOGLE_include_directive : require
// The opaque surfaces' aerial perspective applied after them, once per pixel (deferred): the opaque
// pass wrote each pixel's surface radiance and distance from the camera (opaque_fragment.glsl,
// kAerialPerspectiveInFullScreenPass), and this pass computes the segment of air in front of it as
// the opaque fragments would have (froxels read at the pixel, or the per-pixel modes' march or
// table reads) and applies the phase functions of the pixel's own view ray. A CPU rasterizer runs
// a fragment for every 4x4 stamp that a triangle touches, several per covered pixel where the
// triangles are small; here each pixel runs once. Drawn over the screen at depth 0
// (fullscreen.vert) with a test that passes only where a surface was drawn (reversed Z), so sky
// pixels run the sky's shader alone. It binds the mesh passes' resources (renderer.cpp,
// kMeshSlots) and the surfaces' radiance after them.
#include "mesh_tables.glsl"
layout(set = 0, binding = 5) uniform sampler3D rayleigh_froxels;
layout(set = 0, binding = 6) uniform sampler3D mie_froxels;
layout(set = 0, binding = 7) uniform sampler3D transmittance_froxels;
layout(set = 0, binding = 14) uniform sampler2D surface_radiance;  // rgb: radiance, a: distance (m)
layout(location = 0) out vec4 color;

void main() {
  vec4 surface = texelFetch(surface_radiance, ivec2(gl_FragCoord.xy), 0);
  vec2 uv = gl_FragCoord.xy / AERIAL_FRAME.viewport.xy;
  vec3 ray = ViewRayFromScreen(uv);
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  Inscatter segment = kAerialPerPixel == AERIAL_FROXELS
                          ? GetAerialPerspective(rayleigh_froxels, mie_froxels, transmittance_froxels, uv, surface.a)
                          : GetMeshAerialPerspectivePerPixel(ray, r, mu, mu_s, nu, surface.a);
  color = vec4(ApplyAerialPerspective(surface.rgb, segment, nu), 1.0);
}
