#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque geometry seen through the air: L T + I_R P_R(nu) + I_M P_M(nu), with L the lit surface
// radiance from the vertices (opaque.vert), its sun part times the sun's visibility here
// (shadow.glsl), (I_R, I_M, T) read from the froxel volume at the fragment's screen position and
// distance (per-pixel mode: from the tables) and nu from the fragment's own view ray. Geometry is
// drawn nearest first, so early depth tests skip this work for hidden fragments.
#include "froxel.glsl"
#include "surface.glsl"
#define SHADOW_BINDING 8
#include "shadow.glsl"
layout(set = 0, binding = 2) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 4) uniform sampler3D multiple_density_texture;
layout(set = 0, binding = 5) uniform sampler3D rayleigh_froxels;
layout(set = 0, binding = 6) uniform sampler3D mie_froxels;
layout(set = 0, binding = 7) uniform sampler3D transmittance_froxels;
layout(location = 0) in vec3 relative_position;
layout(location = 1) in vec3 sun_radiance;
layout(location = 2) in vec3 sky_radiance;
layout(location = 3) in vec3 surface_normal;
layout(location = 0) out vec4 color;

void main() {
  float distance = length(relative_position);
  vec3 ray = relative_position / distance;
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  Inscatter segment;
  if (kAerialPerPixel == 1) {
    segment = GetSkyInscatterToPoint(transmittance_texture, multiple_density_texture, r, mu,
                                     mu_s, nu, distance);
  } else {
    segment = SampleFroxels(rayleigh_froxels, mie_froxels, transmittance_froxels,
                            gl_FragCoord.xy / frame.viewport.xy, distance,
                            float(frame.froxel_size.z), frame.froxel_depth.x);
  }
  vec3 surface_radiance = ShadeLambertian(LambertianRadiance(sun_radiance, sky_radiance),
                                          SunVisibility(relative_position, normalize(surface_normal)));
  color = vec4(surface_radiance * segment.transmittance + ApplyPhaseFunctions(segment, nu), 1.0);
}
