// Render-time reads of the precomputed tables: sky inscatter to the boundary or to a point, and
// irradiance (Bruneton 2017, functions.glsl "Rendering"). Inscatter comes back WITHOUT phase, with
// Rayleigh and Mie separate, so that callers apply the phase functions per pixel.
#ifndef AERIAL_SKY_LOOKUP_GLSL
#define AERIAL_SKY_LOOKUP_GLSL
#include "inscatter_march.glsl"
#include "irradiance.glsl"

// The Rayleigh inscatter without phase. In 4D the table already holds the multiple scattering
// divided by P_R; in 3D its own table is added here divided by P_R of the query's nu, so that the
// caller's product with P_R(nu) restores it exactly (it is then isotropic in azimuth, which is the
// 3D approximation).
vec3 GetRayleighScattering(sampler3D rayleigh_texture, sampler3D multiple_texture, float r,
                           float mu, float mu_s, float nu, bool ray_r_mu_intersects_ground) {
  vec3 rayleigh = GetScatteringExponentialInR(rayleigh_texture, atmosphere.scattering_size, r, mu,
                                              mu_s, nu, ray_r_mu_intersects_ground);
  if (TablesDropNu()) {
    rayleigh += GetScatteringExponentialInR(multiple_texture, atmosphere.scattering_size, r, mu,
                                            mu_s, nu, ray_r_mu_intersects_ground) /
                RayleighPhaseFunction(nu);
  }
  return rayleigh;
}

// S(x, v): the scattering tables' Rayleigh and Mie inscatter (without phase) along the whole view
// ray (r, mu), to the ground or the top of the atmosphere, and its transmittance.
Inscatter GetSkyInscatter(sampler2D transmittance_texture, sampler3D rayleigh_texture,
                          sampler3D mie_texture, sampler3D multiple_texture, float r, float mu,
                          float mu_s, float nu) {
  bool ray_r_mu_intersects_ground = RayIntersectsGround(r, mu);
  Inscatter result;
  result.rayleigh = GetRayleighScattering(rayleigh_texture, multiple_texture, r, mu, mu_s, nu,
                                          ray_r_mu_intersects_ground);
  result.mie = GetScatteringExponentialInR(mie_texture, atmosphere.scattering_size, r, mu, mu_s,
                                           nu, ray_r_mu_intersects_ground);
  result.transmittance =
      ray_r_mu_intersects_ground
          ? GetTransmittance(transmittance_texture, r, mu,
                             DistanceToBottomAtmosphereBoundary(r, mu), true)
          : GetTransmittanceToTopAtmosphereBoundary(transmittance_texture, r, mu);
  return result;
}

// Inscatter over the first d meters of the view ray (r, mu), marched (inscatter_march.glsl) in
// equal steps. SEGMENT_STEPS: with 32, the result is within 0.012% of 256 steps (aerial probe on
// eight segments of 5-30 km, cameras from the ground to 50 km, sun zenith 0-95 degrees).
const int SEGMENT_STEPS = 32;

Inscatter GetSkyInscatterToPoint(sampler2D transmittance_texture,
                                 sampler3D multiple_density_texture, float r, float mu, float mu_s,
                                 float nu, float d) {
  InscatterMarch march = StartInscatterMarch(transmittance_texture, multiple_density_texture, r,
                                             mu, mu_s, nu);
  d = min(d, DistanceToNearestAtmosphereBoundary(r, mu, march.ray_r_mu_intersects_ground));
  for (int i = 1; i <= SEGMENT_STEPS; ++i) {
    AdvanceInscatterMarch(transmittance_texture, multiple_density_texture, march,
                          d * float(i) / float(SEGMENT_STEPS), 1.0);
  }
  return GetInscatterMarchResult(march);
}

vec3 ApplyPhaseFunctions(Inscatter inscatter, float nu) {
  return inscatter.rayleigh * RayleighPhaseFunction(nu) +
         inscatter.mie * MiePhaseFunction(atmosphere.mie_phase_g, nu);
}

// Radiance of the sun disc at the top of the atmosphere: irradiance over the disc's solid angle.
vec3 GetSolarRadiance() {
  return atmosphere.solar_irradiance.rgb /
         (PI * atmosphere.sun_angular_radius * atmosphere.sun_angular_radius);
}

#endif
