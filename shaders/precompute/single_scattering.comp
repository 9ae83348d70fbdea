#version 450
#extension GL_GOOGLE_include_directive : require
// Pass 3: single scattering, Rayleigh and Mie in separate tables, without phase. The Rayleigh part
// also seeds the accumulated Rayleigh table that the multiple scattering orders add to.
#include "scattering.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 2) writeonly uniform image3D delta_rayleigh_image;
layout(set = 0, binding = 3) writeonly uniform image3D single_mie_image;
layout(set = 0, binding = 4) writeonly uniform image3D rayleigh_accumulator;
layout(set = 0, binding = 5) uniform sampler2D sun_band_texture;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (!IsScatteringTexel(AERIAL_ATMOSPHERE.scattering_size, texel)) return;
  float r, mu, mu_s, nu;
  bool ray_r_mu_intersects_ground;
  GetRMuMuSNuFromScatteringTexel(AERIAL_ATMOSPHERE.scattering_size, MU_AXIS_RAY_LENGTH, texel, r, mu,
                                 mu_s, nu, ray_r_mu_intersects_ground);
  vec3 rayleigh;
  vec3 mie;
  ComputeSingleScattering(transmittance_texture, sun_band_texture, r, mu, mu_s, nu,
                          ray_r_mu_intersects_ground, rayleigh, mie);
  imageStore(delta_rayleigh_image, texel, vec4(rayleigh, 0.0));
  imageStore(single_mie_image, texel, vec4(mie, 0.0));
  imageStore(rayleigh_accumulator, texel, vec4(rayleigh, 0.0));
}
