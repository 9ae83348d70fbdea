#version 450
#extension GL_GOOGLE_include_directive : require
// The aerial perspective of the opaque surfaces applied after them, once per pixel (deferred):
// the opaque pass wrote each pixel's surface radiance and distance from the camera
// (opaque_fragment.glsl, kFroxelsInFullScreenPass), and this pass reads the froxels there and
// applies the phase functions of the pixel's own view ray, as the opaque fragments do when they
// read the froxels per pixel. Drawn over the screen at depth 0 (fullscreen.vert) with a test that
// passes only where a surface was drawn (reversed Z), so sky pixels run the sky's shader alone.
#include "aerial_perspective.glsl"
layout(set = 0, binding = 2) uniform sampler3D rayleigh_froxels;
layout(set = 0, binding = 3) uniform sampler3D mie_froxels;
layout(set = 0, binding = 4) uniform sampler3D transmittance_froxels;
layout(set = 0, binding = 5) uniform sampler2D surface_radiance;  // rgb: radiance, a: distance (m)
layout(location = 0) out vec4 color;

void main() {
  vec4 surface = texelFetch(surface_radiance, ivec2(gl_FragCoord.xy), 0);
  vec2 uv = gl_FragCoord.xy / AERIAL_FRAME.viewport.xy;
  Inscatter segment = GetAerialPerspective(rayleigh_froxels, mie_froxels, transmittance_froxels, uv, surface.a);
  color = vec4(ApplyAerialPerspective(surface.rgb, segment, ViewSunCosine(ViewRayFromScreen(uv))), 1.0);
}
