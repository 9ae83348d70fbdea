// Ground irradiance: the direct sun term (computed, never tabulated at render time) and the
// indirect sky term (Bruneton 2017, functions.glsl "Ground irradiance").
#ifndef AERIAL_IRRADIANCE_GLSL
#define AERIAL_IRRADIANCE_GLSL
#include "scattering.glsl"

// Direct irradiance on a horizontal surface: the sun's disc above both the horizon and the
// surface's plane, each part with its own transmittance and cosine (GetSunDiscSunlight; this
// replaces Bruneton 2017's average cosine (mu_s + alpha)^2 / (4 alpha) of "ComputeDirectIrradiance").
vec3 ComputeDirectIrradiance(sampler2D transmittance_texture, float r, float mu_s) {
  return GetDirectSunlight(transmittance_texture, r, mu_s, max(GetHorizonCosine(r), 0.0), true);
}

// The radiance of order `order` arriving at (r, mu_s) from direction omega (zenith cosine
// omega.z), nu = omega . omega_s: the tables' value, or with `exact_single` single scattering
// integrated along the direction (ComputeSingleScatteringInSteps, 32 steps).
vec3 GetIrradianceIntegrand(sampler2D transmittance_texture, sampler2D sun_band_texture,
                            sampler3D single_rayleigh_texture, sampler3D single_mie_texture,
                            sampler3D multiple_scattering_texture,
                            float r, float mu_s, vec3 omega, float nu, int order,
                            bool exact_single) {
  if (!exact_single)
    return GetScatteringOfOrder(single_rayleigh_texture, single_mie_texture,
                                multiple_scattering_texture, r, omega.z, mu_s, nu, false, order);
  vec3 rayleigh;
  vec3 mie;
  ComputeSingleScatteringInSteps(transmittance_texture, sun_band_texture, r, omega.z, mu_s, nu,
                                 false, 32, rayleigh, mie);
  return rayleigh * RayleighPhaseFunction(nu) + mie * MiePhaseFunction(AERIAL_ATMOSPHERE.mie_phase_g, nu);
}

// Indirect irradiance of order `order`: the radiance of that order integrated over the upper
// hemisphere with the cosine weight. The sky is symmetric about the vertical plane through the
// sun, so azimuths cover [0, pi] (midpoint rule) and count twice. The zenith cosine is mapped as
// mu = (1 + cos psi) / 2, d mu = sin(psi) / 2 d psi, with the midpoint rule in psi over [0, pi]
// (the nodes of Fejer's first rule on [0, 1], with the midpoint rule's weights): they crowd toward
// both the zenith and the horizon, where the sky brightens steeply and the midpoint rule in the
// zenith angle reads high. Order 1 on the ground with the sun at the zenith, 32 zenith nodes,
// against Gauss-Legendre with 256 nodes in numpy: Rayleigh only, +0.16 / +0.10 / +0.05% (red /
// green / blue) with even zenith angles, +0.03 / +0.03 / +0.04% with this rule; with Mie's aureole
// around the zenith too, +0.16 / +0.10 / +0.06% and +0.12 / +0.08 / +0.06%.
vec3 IntegrateIrradiance(sampler2D transmittance_texture, sampler2D sun_band_texture,
                         sampler3D single_rayleigh_texture, sampler3D single_mie_texture,
                         sampler3D multiple_scattering_texture,
                         float r, float mu_s, int order, bool exact_single, int zenith_samples,
                         int azimuth_samples) {
  float d_psi = PI / float(zenith_samples);
  float d_phi = PI / float(azimuth_samples);
  vec3 omega_s = vec3(sqrt(max(1.0 - mu_s * mu_s, 0.0)), 0.0, mu_s);
  vec3 irradiance = vec3(0.0);
  for (int j = 0; j < zenith_samples; ++j) {
    float psi = (float(j) + 0.5) * d_psi;
    float mu = 0.5 * (1.0 + cos(psi));
    float sin_theta = sqrt(1.0 - mu * mu);
    // d omega = d mu d phi, counted twice for the mirrored azimuth: 2 (sin(psi) / 2) d psi d phi.
    float domega = sin(psi) * d_psi * d_phi;
    for (int i = 0; i < azimuth_samples; ++i) {
      float phi = (float(i) + 0.5) * d_phi;
      vec3 omega = vec3(cos(phi) * sin_theta, sin(phi) * sin_theta, mu);
      irradiance += GetIrradianceIntegrand(transmittance_texture, sun_band_texture,
                                           single_rayleigh_texture, single_mie_texture,
                                           multiple_scattering_texture, r, mu_s, omega,
                                           dot(omega, omega_s), order, exact_single) *
                    mu * domega;
    }
  }
  return irradiance;
}

// The ground irradiance of radiance order `order` on the full grid (sample_counts.zw). Order 1
// gets a control variate: near and below the horizon the single scattering tables are
// interpolated in mu_s across the edge of the Earth's shadow, where single scattering changes
// faster than their texels follow (13-27% off at sun zenith 95 degrees on the sky seen from the
// ground), so the table's integral on the full grid is corrected by the difference between
// single scattering integrated along each direction and the table, both on a grid of a quarter of
// each axis. The difference is smooth in direction where the table is right, so the coarse grid
// integrates it well. Measured (aerial_bench_sky): low-sun sky irradiance from 3.6-5.3% to
// 1.9-2.5% at most, twilight on the ground 9.6% to 5.8%; the coarse grid at 8x8 is as accurate as
// 16x16 or the exact single scattering on the full 32x32 grid, at a ninth of its cost.
vec3 ComputeIndirectIrradiance(sampler2D transmittance_texture, sampler2D sun_band_texture,
                               sampler3D single_rayleigh_texture, sampler3D single_mie_texture,
                               sampler3D multiple_scattering_texture,
                               float r, float mu_s, int order) {
  int zenith_samples = AERIAL_ATMOSPHERE.sample_counts.z;
  int azimuth_samples = AERIAL_ATMOSPHERE.sample_counts.w;
  vec3 irradiance = IntegrateIrradiance(transmittance_texture, sun_band_texture,
                                        single_rayleigh_texture, single_mie_texture,
                                        multiple_scattering_texture, r, mu_s, order, false,
                                        zenith_samples, azimuth_samples);
  if (order != 1) return irradiance;
  int coarse_zenith = max(zenith_samples / 4, 1);
  int coarse_azimuth = max(azimuth_samples / 4, 1);
  vec3 exact = IntegrateIrradiance(transmittance_texture, sun_band_texture, single_rayleigh_texture,
                                   single_mie_texture, multiple_scattering_texture, r, mu_s, 1,
                                   true, coarse_zenith, coarse_azimuth);
  vec3 table = IntegrateIrradiance(transmittance_texture, sun_band_texture, single_rayleigh_texture,
                                   single_mie_texture, multiple_scattering_texture, r, mu_s, 1,
                                   false, coarse_zenith, coarse_azimuth);
  return max(irradiance + exact - table, vec3(0.0));
}

// One row of the table at mu_s's coordinate u, for a point whose horizon has the zenith cosine
// `horizon`: where both mu_s texels have the sun below it, the ground in the Earth's shadow, the
// irradiance falls exponentially as the sun sinks and is read so between them (a chord lies above
// a convex curve): read linearly, twilight's irradiance on the ground was 3.6% high in luminance
// against the 48-wavelength reference (1.8% so; aerial_bench_colour). Elsewhere one bilinear read
// (definitions.glsl, "Control flow"). 50 km up the sun sets 7 degrees below the horizontal, and a
// read exponential from the horizontal down made twilight's irradiance there 6.5% off instead of
// 0.1% (aerial_bench_sky).
vec3 GetIrradianceRow(sampler2D irradiance_texture, float u, float v, float horizon) {
  float columns = float(AERIAL_ATMOSPHERE.irradiance_size.x);
  vec2 blend = GetTexelBlend(u, columns);
  bool exponential = blend.y != 0.0 && IsMuSTexelBelow(blend.x + 1.0, columns, horizon);
  vec3 e = ReadTable(irradiance_texture, vec2(exponential ? (blend.x + 0.5) / columns : u, v)).rgb;
  // The upper texel in a loop that runs once or not at all, not behind an if, which a CPU
  // rasterizer would run for every lane (definitions.glsl, "Control flow").
  for (int i = 0; i < (exponential ? 1 : 0); ++i)
    e = MixExponentially(e, ReadTable(irradiance_texture, vec2((blend.x + 1.5) / columns, v)).rgb, blend.y);
  return e;
}

// The sky irradiance, each row read by GetIrradianceRow and exponentially in r between the two
// nearest rows: it falls off roughly exponentially with altitude (to half over 3.5 km at 50 km up,
// where the rows were 3.5 km apart before the r axis was warped; 2.2 km now), so linear
// interpolation overestimates it between rows: by 2.4% at 50 km on the default table then (3.7%
// off the reference there, 1.3% on the rows themselves; aerial_bench_sky and aerial probe at the
// rows' altitudes).
vec3 GetIrradiance(sampler2D irradiance_texture, float r, float mu_s) {
  vec2 uv = GetIrradianceTextureUvFromRMuS(r, mu_s);
  float rows = float(AERIAL_ATMOSPHERE.irradiance_size.y);
  vec2 blend = GetTexelBlend(uv.y, rows);
  float horizon = GetHorizonCosine(r);
  vec3 e0 = GetIrradianceRow(irradiance_texture, uv.x, (blend.x + 0.5) / rows, horizon);
  if (blend.y == 0.0) return e0;
  vec3 e1 = GetIrradianceRow(irradiance_texture, uv.x, (blend.x + 1.5) / rows, horizon);
  return MixExponentially(e0, e1, blend.y);
}

#endif
