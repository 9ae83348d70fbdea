#version 450
#extension GL_GOOGLE_include_directive : require
// The engine's opaque meshes seen through the air: the lit surface L, attenuated and in-scattered
// by the segment to the camera that aerial's froxel volume holds at this pixel and distance, with
// the phase functions of this pixel's own view ray: L T + I_R P_R(nu) + I_M P_M(nu).
#include "aerial_perspective.glsl"
#include "bindings.glsl"
layout(location = 0) in vec3 relative_position;
layout(location = 1) in vec3 sun_radiance;
layout(location = 2) in vec3 sky_radiance;
layout(location = 3) in vec3 surface_normal;
// rgb: radiance at the camera; a: the distance to the surface (m), for the EXR's distance channel.
layout(location = 0) out vec4 color;

void main() {
  float distance = length(relative_position);
  Inscatter segment = GetAerialPerspective(rayleigh_froxels, mie_froxels, transmittance_froxels,
                                           gl_FragCoord.xy / AERIAL_FRAME.viewport.xy, distance);
  // The whole sun is seen: this example has no shadow map.
  vec3 surface = ShadeLambertian(LambertianRadiance(sun_radiance, sky_radiance), normalize(surface_normal), 1.0);
  color = vec4(ApplyAerialPerspective(surface, segment, ViewSunCosine(relative_position)), distance);
}
