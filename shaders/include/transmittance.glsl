// Transmittance: computing the table and reading it (Bruneton 2017, functions.glsl "Transmittance").
#ifndef AERIAL_TRANSMITTANCE_GLSL
#define AERIAL_TRANSMITTANCE_GLSL
#include "mappings.glsl"
#include "table_read.glsl"

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
  return ReadTable(transmittance_texture, GetTransmittanceTextureUvFromRMu(r, mu)).rgb;
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

// Sunlight from the whole solar disc (angular radius alpha). Near the horizon the disc's parts
// reach r through slants of very different lengths, and the part below the horizon not at all:
// the centre's transmittance times the visible fraction is then 13%, 25% and 62% low (red, green,
// blue) on the ground with the centre on the horizon, and up to 11x low at 10 km (measured against
// the reference's exact disc, src/aerial/reference/solar_disc.h, which this follows). Parts of the
// disc at elevation y alpha above its centre (y in [-1, 1]) have the chord weight sqrt(1 - y^2).
//  - More than 10 degrees (37 radii) above the cut-off, the centre's value is the disc's to 1.2e-4
//    and is used alone.
//  - A whole disc: Gauss-Chebyshev of the second kind (Abramowitz & Stegun 25.4.40), 2 taps at
//    y = +-1/2 above 5 radii, 3 taps (y = 0, +-1/sqrt 2) below; against the reference's disc, at
//    most 2.6e-4 and 1e-3 off on the ground and at 10 km.
//  - A disc cut by the horizon: with y = cos t the visible parts are t in [0, t_h], and four
//    Gauss-Legendre taps in t, normalized by the same rule's integral of the weight, give the
//    average over the visible part, times that part's exact area.
//
// cut_off_cosine: the zenith cosine below which the disc does not count (the horizon, or for a
// horizontal surface also its plane); cosine_weighted: average T max(mu, 0) instead of T.
const float SUN_DISC_ONE_TAP_ELEVATION = 0.1745;  // 10 degrees

// The zenith cosine of the disc's point y disc radii above its centre, to O(alpha^4) = 1e-9.
float GetDiscPointCosine(float mu_s, float sin_s, float y) {
  float y_alpha = y * atmosphere.sun_angular_radius;
  return mu_s * (1.0 - 0.5 * y_alpha * y_alpha) + sin_s * y_alpha;
}

vec3 GetTransmittanceAtDiscPoint(sampler2D transmittance_texture, float r, float mu_s, float sin_s,
                                 float y) {
  return GetTransmittanceToTopAtmosphereBoundary(transmittance_texture, r,
                                                 GetDiscPointCosine(mu_s, sin_s, y));
}

// Elevation of the disc centre above the cut-off, in disc radii (to first order in the angle).
float GetSunElevationInDiscRadii(float mu_s, float cut_off_cosine) {
  float sin_cut_off = sqrt(max(1.0 - cut_off_cosine * cut_off_cosine, 0.0));
  return (mu_s - cut_off_cosine) / (sin_cut_off * atmosphere.sun_angular_radius);
}

// Visible fraction of a uniform disc cut by a straight line x radii below its centre.
float GetSunDiscVisibleFraction(float x) {
  return x >= 1.0 ? 1.0 : clamp(0.5 + (x * sqrt(1.0 - x * x) + asin(x)) / PI, 0.0, 1.0);
}

vec3 GetSunDiscAverage(sampler2D transmittance_texture, float r, float mu_s, float cut_off_cosine,
                       bool cosine_weighted) {
  float alpha = atmosphere.sun_angular_radius;
  float x = GetSunElevationInDiscRadii(mu_s, cut_off_cosine);
  if (x <= -1.0) return vec3(0.0);
  if (x * alpha > SUN_DISC_ONE_TAP_ELEVATION)
    return GetTransmittanceToTopAtmosphereBoundary(transmittance_texture, r, mu_s) *
           (cosine_weighted ? mu_s : 1.0);
  float sin_s = sqrt(max(1.0 - mu_s * mu_s, 0.0));
  if (x >= 1.0 && !cosine_weighted) {
    if (x > 5.0)
      return 0.5 * (GetTransmittanceAtDiscPoint(transmittance_texture, r, mu_s, sin_s, 0.5) +
                    GetTransmittanceAtDiscPoint(transmittance_texture, r, mu_s, sin_s, -0.5));
    return 0.25 * (GetTransmittanceAtDiscPoint(transmittance_texture, r, mu_s, sin_s, 0.70710678) +
                   GetTransmittanceAtDiscPoint(transmittance_texture, r, mu_s, sin_s, -0.70710678)) +
           0.5 * GetTransmittanceToTopAtmosphereBoundary(transmittance_texture, r, mu_s);
  }
  float visible = GetSunDiscVisibleFraction(x);
  float t_h = acos(max(-x, -1.0));
  const vec2 node = vec2(0.3399810436, 0.8611363116);  // Gauss-Legendre, 4 points on [-1, 1]
  const vec2 weight = vec2(0.6521451549, 0.3478548451);
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  for (int i = 0; i < 4; ++i) {
    float t = 0.5 * t_h * (1.0 + (i < 2 ? -node[i] : node[i - 2]));
    float w = weight[i % 2] * sin(t) * sin(t);
    float mu = GetDiscPointCosine(mu_s, sin_s, cos(t));
    sum += w * GetTransmittanceToTopAtmosphereBoundary(transmittance_texture, r, mu) *
           (cosine_weighted ? max(mu, 0.0) : 1.0);
    weights += w;
  }
  return sum / weights * visible;
}

// -sqrt(1 - (R / r)^2), from the horizon distance without cancellation.
float GetHorizonCosine(float r) { return -sqrt(SquaredHorizonDistance(r)) / r; }

// Transmittance of sunlight to radius r, over the part of the disc above the horizon.
vec3 GetTransmittanceToSun(sampler2D transmittance_texture, float r, float mu_s) {
  return GetSunDiscAverage(transmittance_texture, r, mu_s, GetHorizonCosine(r), false);
}

// ---- The sun band: GetTransmittanceToSun tabulated for the precomputation. ----
// The single scattering passes evaluate the disc's average at every step of every ray. Near each
// point's horizon that is 2 to 4 table reads with trigonometry, and on lavapipe it took 1.7 of the
// single scattering pass's 2.7 s (the lanes of a SIMD group, neighbouring mu_s texels, take
// different branches, and each runs them all). It depends on (r, mu_s) alone, so a pass
// (precompute/sun_band.comp) tabulates it where it differs from the centre's value: x, the
// centre's elevation above the horizon in disc radii, from -1 to SUN_DISC_ONE_TAP_ELEVATION (37.4
// radii), uniformly on the u axis; r on the transmittance table's rho/H mapping on the v axis (its
// rows).
// The band holds the optical depth of the visible part's average, -ln(average / visible), which
// is smooth where the visible fraction is not; a read multiplies by the exact visible fraction.
float GetSunBandMaxElevationInDiscRadii() {
  return SUN_DISC_ONE_TAP_ELEVATION / atmosphere.sun_angular_radius;
}

vec2 GetSunBandTextureUv(ivec2 size, float r, float x) {
  return vec2(GetTextureCoordFromUnitRange((x + 1.0) / (GetSunBandMaxElevationInDiscRadii() + 1.0),
                                           size.x),
              GetTextureCoordFromUnitRange(GetTransmittanceUnitRangeFromR(r), size.y));
}

void GetRMuSFromSunBandTextureUv(ivec2 size, vec2 uv, out float r, out float mu_s) {
  r = GetRFromTransmittanceUnitRange(GetUnitRangeFromTextureCoord(uv.y, size.y));
  // At x = -1 the visible part is a vanishing sliver whose 4 taps graze the horizon itself; the
  // first texel is taken half a texel above, where they do not.
  float x_range = GetSunBandMaxElevationInDiscRadii() + 1.0;
  float x = max(-1.0 + GetUnitRangeFromTextureCoord(uv.x, size.x) * x_range,
                -1.0 + 0.5 * x_range / float(size.x - 1));
  float cut_off = GetHorizonCosine(r);
  mu_s = cut_off + x * sqrt(1.0 - cut_off * cut_off) * atmosphere.sun_angular_radius;
}

// GetTransmittanceToSun, read from the sun band where the disc takes more than its centre.
vec3 GetTransmittanceToSunFromBand(sampler2D transmittance_texture, sampler2D sun_band_texture,
                                   float r, float mu_s) {
  float x = GetSunElevationInDiscRadii(mu_s, GetHorizonCosine(r));
  if (x <= -1.0) return vec3(0.0);
  if (x > GetSunBandMaxElevationInDiscRadii())
    return GetTransmittanceToTopAtmosphereBoundary(transmittance_texture, r, mu_s);
  vec2 uv = GetSunBandTextureUv(textureSize(sun_band_texture, 0), r, x);
  return exp(-ReadTable(sun_band_texture, uv).rgb) * GetSunDiscVisibleFraction(x);
}

#endif
