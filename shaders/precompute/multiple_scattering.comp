#version 450
#extension GL_GOOGLE_include_directive : require
// Pass 6 (orders >= 2): multiple scattering of order n from its scattering density, at the
// density resolution. The result holds radiance (phase included): the next order's incident
// radiance reads it, and pass 7 adds it to the Rayleigh table.
#include "scattering.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1) uniform sampler2D transmittance_texture;
layout(set = 0, binding = 2) uniform sampler3D scattering_density_texture;
layout(set = 0, binding = 3) writeonly uniform image3D delta_multiple_scattering_image;
// 1 for order 2: its density is the sunlit air's single scattering scattered once more, which in
// the Earth's shadow falls exponentially as the sun goes down, and is read blended so there
// (GetDensityBlended, scattering.glsl). A constant, not a push constant: lavapipe runs both sides
// of a branch its SIMD lanes reach, and the blend cost every order its 2.5x then.
layout(constant_id = 0) const int kDensityExponentialInShadow = 0;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (!IsScatteringTexel(AERIAL_ATMOSPHERE.density_size, texel)) return;
  float r, mu, mu_s, nu;
  bool ray_r_mu_intersects_ground;
  GetRMuMuSNuFromScatteringTexel(AERIAL_ATMOSPHERE.density_size, MU_AXIS_RAY_LENGTH, texel, r, mu,
                                 mu_s, nu, ray_r_mu_intersects_ground);
  vec3 radiance = ComputeMultipleScattering(transmittance_texture, scattering_density_texture, r,
                                            mu, mu_s, nu, ray_r_mu_intersects_ground,
                                            kDensityExponentialInShadow == 1);
  imageStore(delta_multiple_scattering_image, texel, vec4(radiance, 0.0));
}
