// Render-time reads of the precomputed tables: sky inscatter to the boundary or to a point, and
// irradiance (Bruneton 2017, functions.glsl "Rendering"). Inscatter comes back WITHOUT phase, with
// Rayleigh and Mie separate, so that callers apply the phase functions per pixel.
#ifndef AERIAL_SKY_LOOKUP_GLSL
#define AERIAL_SKY_LOOKUP_GLSL
#include "irradiance.glsl"

struct Inscatter {
  vec3 rayleigh;       // multiply by RayleighPhaseFunction(nu)
  vec3 mie;            // multiply by MiePhaseFunction(g, nu)
  vec3 transmittance;  // over the same segment
};

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

// S(x, v): the scattering tables' Rayleigh and Mie inscatter (without phase) of the view ray
// (r, mu), to the ground or the top of the atmosphere. The transmittance is left at 1.
Inscatter GetRayScattering(sampler3D rayleigh_texture, sampler3D mie_texture,
                           sampler3D multiple_texture, float r, float mu, float mu_s, float nu,
                           bool ray_r_mu_intersects_ground) {
  Inscatter result;
  result.rayleigh = GetRayleighScattering(rayleigh_texture, multiple_texture, r, mu, mu_s, nu,
                                          ray_r_mu_intersects_ground);
  result.mie = GetScatteringExponentialInR(mie_texture, atmosphere.scattering_size, r, mu, mu_s,
                                           nu, ray_r_mu_intersects_ground);
  result.transmittance = vec3(1.0);
  return result;
}

// Inscatter along the whole view ray (r, mu), to the ground or the top of the atmosphere.
Inscatter GetSkyInscatter(sampler2D transmittance_texture, sampler3D rayleigh_texture,
                          sampler3D mie_texture, sampler3D multiple_texture, float r, float mu,
                          float mu_s, float nu) {
  bool ray_r_mu_intersects_ground = RayIntersectsGround(r, mu);
  Inscatter result = GetRayScattering(rayleigh_texture, mie_texture, multiple_texture, r, mu, mu_s,
                                      nu, ray_r_mu_intersects_ground);
  result.transmittance =
      ray_r_mu_intersects_ground
          ? GetTransmittance(transmittance_texture, r, mu,
                             DistanceToBottomAtmosphereBoundary(r, mu), true)
          : GetTransmittanceToTopAtmosphereBoundary(transmittance_texture, r, mu);
  return result;
}

// Inscatter over the first d meters of the view ray: S(x, v) - T(x, p) S(p, v) (Bruneton 2008
// eq. 16), given S(x, v) (GetRayScattering), which callers marching along one ray read once.
// Both lookups use the camera ray's ground flag, so they read the same half of the table even
// when rounding puts p on the other side of the horizon.
Inscatter GetSkyInscatterToPointFrom(Inscatter ray_scattering, sampler2D transmittance_texture,
                                     sampler3D rayleigh_texture, sampler3D mie_texture,
                                     sampler3D multiple_texture, float r, float mu, float mu_s,
                                     float nu, float d) {
  bool ray_r_mu_intersects_ground = RayIntersectsGround(r, mu);
  d = min(d, DistanceToNearestAtmosphereBoundary(r, mu, ray_r_mu_intersects_ground));
  float r_p = RadiusAtDistance(r, mu, d);
  float mu_p = MuAtDistance(r, mu, d, r_p);
  float mu_s_p = MuSAtDistance(r, mu_s, nu, d, r_p);
  Inscatter beyond = GetRayScattering(rayleigh_texture, mie_texture, multiple_texture, r_p, mu_p,
                                      mu_s_p, nu, ray_r_mu_intersects_ground);
  Inscatter result;
  result.transmittance =
      GetTransmittance(transmittance_texture, r, mu, d, ray_r_mu_intersects_ground);
  result.rayleigh = max(ray_scattering.rayleigh - result.transmittance * beyond.rayleigh, vec3(0.0));
  result.mie = max(ray_scattering.mie - result.transmittance * beyond.mie, vec3(0.0));
  return result;
}

Inscatter GetSkyInscatterToPoint(sampler2D transmittance_texture, sampler3D rayleigh_texture,
                                 sampler3D mie_texture, sampler3D multiple_texture, float r,
                                 float mu, float mu_s, float nu, float d) {
  Inscatter ray_scattering = GetRayScattering(rayleigh_texture, mie_texture, multiple_texture, r,
                                              mu, mu_s, nu, RayIntersectsGround(r, mu));
  return GetSkyInscatterToPointFrom(ray_scattering, transmittance_texture, rayleigh_texture,
                                    mie_texture, multiple_texture, r, mu, mu_s, nu, d);
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
