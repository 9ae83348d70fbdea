// Ground irradiance: the direct sun term (computed, never tabulated at render time) and the
// indirect sky term (Bruneton 2017, functions.glsl "Ground irradiance").
#ifndef AERIAL_IRRADIANCE_GLSL
#define AERIAL_IRRADIANCE_GLSL
#include "scattering.glsl"

// Direct irradiance on a horizontal surface: the sun's disc above both the horizon and the
// surface's plane, each part with its own transmittance and cosine (GetSunDiscAverage; this
// replaces Bruneton 2017's average cosine (mu_s + alpha)^2 / (4 alpha) of "ComputeDirectIrradiance").
vec3 ComputeDirectIrradiance(sampler2D transmittance_texture, float r, float mu_s) {
  return atmosphere.solar_irradiance.rgb *
         GetSunDiscAverage(transmittance_texture, r, mu_s, max(GetHorizonCosine(r), 0.0), true);
}

// Indirect irradiance of order `order`: the radiance of that order integrated over the upper
// hemisphere with the cosine weight, by the midpoint rule in zenith and azimuth. The sky is
// symmetric about the vertical plane through the sun, so azimuths cover [0, pi] and count twice.
vec3 ComputeIndirectIrradiance(sampler3D single_rayleigh_texture, sampler3D single_mie_texture,
                               sampler3D multiple_scattering_texture, float r, float mu_s,
                               int order) {
  int zenith_samples = atmosphere.sample_counts.z;
  int azimuth_samples = atmosphere.sample_counts.w;
  float d_theta = 0.5 * PI / float(zenith_samples);
  float d_phi = PI / float(azimuth_samples);
  vec3 omega_s = vec3(sqrt(max(1.0 - mu_s * mu_s, 0.0)), 0.0, mu_s);
  vec3 irradiance = vec3(0.0);
  for (int j = 0; j < zenith_samples; ++j) {
    float theta = (float(j) + 0.5) * d_theta;
    for (int i = 0; i < azimuth_samples; ++i) {
      float phi = (float(i) + 0.5) * d_phi;
      vec3 omega = vec3(cos(phi) * sin(theta), sin(phi) * sin(theta), cos(theta));
      float domega = 2.0 * d_theta * d_phi * sin(theta);  // twice: the mirrored azimuth
      float nu = dot(omega, omega_s);
      irradiance += GetScatteringOfOrder(single_rayleigh_texture, single_mie_texture,
                                         multiple_scattering_texture, r, omega.z, mu_s, nu,
                                         false, order) *
                    omega.z * domega;
    }
  }
  return irradiance;
}

vec3 GetIrradiance(sampler2D irradiance_texture, float r, float mu_s) {
  return textureLod(irradiance_texture, GetIrradianceTextureUvFromRMuS(r, mu_s), 0.0).rgb;
}

#endif
