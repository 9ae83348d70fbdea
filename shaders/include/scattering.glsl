// Scattering: computing the single and multiple scattering tables and reading them (Bruneton 2017,
// functions.glsl "Single scattering", "Multiple scattering"). Tables store radiance WITHOUT phase:
// Rayleigh and Mie single scattering in separate tables, and multiple scattering divided by the
// Rayleigh phase and added to the Rayleigh table, so that multiplying by P_R(nu) restores it.
#ifndef AERIAL_SCATTERING_GLSL
#define AERIAL_SCATTERING_GLSL
#include "phase.glsl"
#include "transmittance.glsl"

// Integrand of single scattering at distance d along the ray: transmittance from the camera to the
// point, times sunlight reaching the point, times the density of each species there.
void ComputeSingleScatteringIntegrand(sampler2D transmittance_texture, float r, float mu,
                                      float mu_s, float nu, float d,
                                      bool ray_r_mu_intersects_ground, out vec3 rayleigh,
                                      out vec3 mie) {
  float r_d = RadiusAtDistance(r, mu, d);
  float mu_s_d = MuSAtDistance(r, mu_s, nu, d, r_d);
  vec3 transmittance =
      GetTransmittance(transmittance_texture, r, mu, d, ray_r_mu_intersects_ground) *
      GetTransmittanceToSun(transmittance_texture, r_d, mu_s_d);
  float altitude = r_d - atmosphere.bottom_radius;
  rayleigh = transmittance * GetProfileDensity(atmosphere.rayleigh_density, altitude);
  mie = transmittance * GetProfileDensity(atmosphere.mie_density, altitude);
}

// Single scattering (Bruneton 2008 eq. 11 without the phase function), by the trapezoidal rule
// over the distance to the nearest boundary.
void ComputeSingleScattering(sampler2D transmittance_texture, float r, float mu, float mu_s,
                             float nu, bool ray_r_mu_intersects_ground, out vec3 rayleigh,
                             out vec3 mie) {
  int steps = atmosphere.sample_counts.y;
  float dx = DistanceToNearestAtmosphereBoundary(r, mu, ray_r_mu_intersects_ground) / float(steps);
  vec3 rayleigh_sum = vec3(0.0);
  vec3 mie_sum = vec3(0.0);
  for (int i = 0; i <= steps; ++i) {
    vec3 rayleigh_i;
    vec3 mie_i;
    ComputeSingleScatteringIntegrand(transmittance_texture, r, mu, mu_s, nu, float(i) * dx,
                                     ray_r_mu_intersects_ground, rayleigh_i, mie_i);
    float weight = (i == 0 || i == steps) ? 0.5 : 1.0;
    rayleigh_sum += rayleigh_i * weight;
    mie_sum += mie_i * weight;
  }
  vec3 sun = atmosphere.solar_irradiance.rgb * dx;
  rayleigh = rayleigh_sum * sun * atmosphere.rayleigh_scattering.rgb;
  mie = mie_sum * sun * atmosphere.mie_scattering.rgb;
}

// Reads a 4D table packed in 3D (x = nu_index * MU_S + mu_s_index), interpolating linearly in nu
// between two slices; the other three axes use the sampler's trilinear filter. A table with one
// nu slice is the 3D variant.
vec3 GetScattering(sampler3D scattering_texture, float r, float mu, float mu_s, float nu,
                   bool ray_r_mu_intersects_ground) {
  vec4 uvwz = GetScatteringTextureUvwzFromRMuMuSNu(r, mu, mu_s, nu, ray_r_mu_intersects_ground);
  float nu_size = float(atmosphere.scattering_size.w);
  if (atmosphere.scattering_size.w == 1) {
    return texture(scattering_texture, uvwz.yzw).rgb;
  }
  float tex_coord_x = uvwz.x * (nu_size - 1.0);
  float tex_x = min(floor(tex_coord_x), nu_size - 2.0);
  float lerp = tex_coord_x - tex_x;
  vec3 uvw0 = vec3((tex_x + uvwz.y) / nu_size, uvwz.z, uvwz.w);
  vec3 uvw1 = vec3((tex_x + 1.0 + uvwz.y) / nu_size, uvwz.z, uvwz.w);
  return mix(texture(scattering_texture, uvw0).rgb, texture(scattering_texture, uvw1).rgb, lerp);
}

// Radiance of scattering order `order` arriving along (r, mu) with the sun at (mu_s, nu): order 1
// from the separate single scattering tables with their phase functions, higher orders from the
// multiple scattering table of that order (which holds radiance, phase included).
vec3 GetScatteringOfOrder(sampler3D single_rayleigh_texture, sampler3D single_mie_texture,
                          sampler3D multiple_scattering_texture, float r, float mu, float mu_s,
                          float nu, bool ray_r_mu_intersects_ground, int order) {
  if (order == 1) {
    vec3 rayleigh = GetScattering(single_rayleigh_texture, r, mu, mu_s, nu,
                                  ray_r_mu_intersects_ground);
    vec3 mie = GetScattering(single_mie_texture, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
    return rayleigh * RayleighPhaseFunction(nu) + mie * MiePhaseFunction(atmosphere.mie_phase_g, nu);
  }
  return GetScattering(multiple_scattering_texture, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
}

// Multiple scattering of order n (Bruneton 2008 eq. 12 integrated along the ray): the scattering
// density J of order n, attenuated back to the camera, by the trapezoidal rule.
vec3 ComputeMultipleScattering(sampler2D transmittance_texture, sampler3D scattering_density_texture,
                               float r, float mu, float mu_s, float nu,
                               bool ray_r_mu_intersects_ground) {
  int steps = atmosphere.sample_counts.y;
  float dx = DistanceToNearestAtmosphereBoundary(r, mu, ray_r_mu_intersects_ground) / float(steps);
  vec3 radiance_sum = vec3(0.0);
  for (int i = 0; i <= steps; ++i) {
    float d_i = float(i) * dx;
    float r_i = RadiusAtDistance(r, mu, d_i);
    float mu_i = MuAtDistance(r, mu, d_i, r_i);
    float mu_s_i = MuSAtDistance(r, mu_s, nu, d_i, r_i);
    vec3 density = GetScattering(scattering_density_texture, r_i, mu_i, mu_s_i, nu,
                                 ray_r_mu_intersects_ground);
    vec3 transmittance =
        GetTransmittance(transmittance_texture, r, mu, d_i, ray_r_mu_intersects_ground);
    float weight = (i == 0 || i == steps) ? 0.5 : 1.0;
    radiance_sum += density * transmittance * (weight * dx);
  }
  return radiance_sum;
}

#endif
