#version 450
#extension GL_GOOGLE_include_directive : require
// Pass 6 (orders >= 2): multiple scattering of order n from its scattering density. The delta
// table keeps radiance (phase included) for the next order; the accumulated Rayleigh table receives
// it divided by the Rayleigh phase, so that render-time lookups multiply one phase back in
// (Bruneton 2017 "ComputeMultipleScatteringTexture": multiple scattering is nearly isotropic, and
// this keeps the Rayleigh/Mie split without a third table).
#include "scattering.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 2) uniform sampler3D scattering_density_texture;
layout(set = 0, binding = 3) writeonly uniform image3D delta_multiple_scattering_image;
layout(set = 0, binding = 4, rgba32f) uniform image3D rayleigh_accumulator;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (texel.x >= atmosphere.scattering_size.z * atmosphere.scattering_size.w ||
      texel.y >= atmosphere.scattering_size.y || texel.z >= atmosphere.scattering_size.x) return;
  float r, mu, mu_s, nu;
  bool ray_r_mu_intersects_ground;
  GetRMuMuSNuFromScatteringTexel(texel, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
  vec3 radiance = ComputeMultipleScattering(transmittance_texture, scattering_density_texture, r,
                                            mu, mu_s, nu, ray_r_mu_intersects_ground);
  imageStore(delta_multiple_scattering_image, texel, vec4(radiance, 0.0));
  imageStore(rayleigh_accumulator, texel,
             imageLoad(rayleigh_accumulator, texel) + vec4(radiance / RayleighPhaseFunction(nu), 0.0));
}
