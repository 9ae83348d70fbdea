// Transmittance: computing the table and reading it (Bruneton 2017, functions.glsl "Transmittance").
#ifndef AERIAL_TRANSMITTANCE_GLSL
#define AERIAL_TRANSMITTANCE_GLSL
#include "mappings.glsl"

// Extinction coefficient at radius r: sum of Rayleigh, Mie and ozone, each scaled by its density.
vec3 GetExtinction(float r) {
  float altitude = r - atmosphere.bottom_radius;
  return atmosphere.rayleigh_scattering.rgb *
             GetProfileDensity(atmosphere.rayleigh_density, altitude) +
         atmosphere.mie_extinction.rgb * GetProfileDensity(atmosphere.mie_density, altitude) +
         atmosphere.absorption_extinction.rgb *
             GetProfileDensity(atmosphere.absorption_density, altitude);
}

// The transmittance table stores the optical depth tau(r, mu) to the top boundary, and readers
// exponentiate: bilinear interpolation of tau (nearly linear in the table coordinates) is more
// accurate than interpolation of T = exp(-tau), which is convex; near the horizon the difference
// is several tenths of a percent. tau is integrated with the trapezoidal rule (Bruneton 2017
// "ComputeOpticalLengthToTopAtmosphereBoundary").
vec3 ComputeOpticalDepthToTopAtmosphereBoundary(float r, float mu) {
  int steps = atmosphere.sample_counts.x;
  float dx = DistanceToTopAtmosphereBoundary(r, mu) / float(steps);
  vec3 optical_depth = vec3(0.0);
  for (int i = 0; i <= steps; ++i) {
    float d_i = float(i) * dx;
    float r_i = sqrt(d_i * d_i + 2.0 * r * mu * d_i + r * r);
    float weight = (i == 0 || i == steps) ? 0.5 : 1.0;
    optical_depth += GetExtinction(r_i) * (weight * dx);
  }
  return optical_depth;
}

vec3 GetOpticalDepthToTopAtmosphereBoundary(sampler2D transmittance_texture, float r, float mu) {
  return textureLod(transmittance_texture, GetTransmittanceTextureUvFromRMu(r, mu), 0.0).rgb;
}

vec3 GetTransmittanceToTopAtmosphereBoundary(sampler2D transmittance_texture, float r, float mu) {
  return exp(-GetOpticalDepthToTopAtmosphereBoundary(transmittance_texture, r, mu));
}

// Transmittance over the first d meters of a ray, from the difference of two optical depths to
// the top boundary. For rays that hit the ground both are taken on the reversed ray (-mu), which
// never hits the ground, so the table is only read for rays that reach the top boundary (Bruneton
// 2017 "GetTransmittance").
//
// Integrators that march one ray call GetRayOpticalDepthOrigin once and then
// GetTransmittanceFromOrigin per step: the camera's term does not change along the ray, which
// halves the table reads of the single and multiple scattering passes.
vec3 GetRayOpticalDepthOrigin(sampler2D transmittance_texture, float r, float mu,
                              bool ray_r_mu_intersects_ground) {
  return GetOpticalDepthToTopAtmosphereBoundary(transmittance_texture, r,
                                                ray_r_mu_intersects_ground ? -mu : mu);
}

vec3 GetTransmittanceFromOrigin(sampler2D transmittance_texture, vec3 origin, float r, float mu,
                                float d, bool ray_r_mu_intersects_ground) {
  float r_d = RadiusAtDistance(r, mu, d);
  float mu_d = MuAtDistance(r, mu, d, r_d);
  if (ray_r_mu_intersects_ground) {
    vec3 tau_d = GetOpticalDepthToTopAtmosphereBoundary(transmittance_texture, r_d, -mu_d);
    return exp(-max(tau_d - origin, vec3(0.0)));
  }
  vec3 tau_d = GetOpticalDepthToTopAtmosphereBoundary(transmittance_texture, r_d, mu_d);
  return exp(-max(origin - tau_d, vec3(0.0)));
}

vec3 GetTransmittance(sampler2D transmittance_texture, float r, float mu, float d,
                      bool ray_r_mu_intersects_ground) {
  vec3 origin = GetRayOpticalDepthOrigin(transmittance_texture, r, mu, ray_r_mu_intersects_ground);
  return GetTransmittanceFromOrigin(transmittance_texture, origin, r, mu, d,
                                    ray_r_mu_intersects_ground);
}

// Fraction of the sun disc (angular radius alpha) above the horizon seen from radius r. With x the
// elevation of the disc center above the horizon in units of alpha, the visible area of a uniform
// disc cut by a straight horizon is 1/2 + (x sqrt(1 - x^2) + asin x) / pi.
float GetSunVisibleFraction(float r, float mu_s) {
  float sin_theta_h = atmosphere.bottom_radius / r;
  float cos_theta_h = -sqrt(max(1.0 - sin_theta_h * sin_theta_h, 0.0));
  float x = (mu_s - cos_theta_h) / (sin_theta_h * atmosphere.sun_angular_radius);
  if (abs(x) >= 1.0) return x > 0.0 ? 1.0 : 0.0;  // whole disc above or below: skip the asin
  // Clamped: near x = -1 the float asin rounds the fraction a few ulps below zero.
  return clamp(0.5 + (x * sqrt(1.0 - x * x) + asin(x)) / PI, 0.0, 1.0);
}

// Transmittance of sunlight to radius r, including the part of the sun hidden by the planet.
vec3 GetTransmittanceToSun(sampler2D transmittance_texture, float r, float mu_s) {
  return GetTransmittanceToTopAtmosphereBoundary(transmittance_texture, r, mu_s) *
         GetSunVisibleFraction(r, mu_s);
}

#endif
