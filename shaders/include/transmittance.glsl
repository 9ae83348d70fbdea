// Transmittance: computing the table and reading it (Bruneton 2017, functions.glsl "Transmittance").
#ifndef AERIAL_TRANSMITTANCE_GLSL
#define AERIAL_TRANSMITTANCE_GLSL
#include "mappings.glsl"
#include "table_read.glsl"

// Extinction coefficient at radius r: sum of Rayleigh, Mie and ozone, each scaled by its density.
vec3 GetExtinction(float r) {
  float altitude = r - AERIAL_ATMOSPHERE.bottom_radius;
  return AERIAL_ATMOSPHERE.rayleigh_scattering.rgb *
             GetProfileDensity(AERIAL_ATMOSPHERE.rayleigh_density, altitude) +
         AERIAL_ATMOSPHERE.mie_extinction.rgb * GetProfileDensity(AERIAL_ATMOSPHERE.mie_density, altitude) +
         AERIAL_ATMOSPHERE.absorption_extinction.rgb *
             GetProfileDensity(AERIAL_ATMOSPHERE.absorption_density, altitude);
}

// The transmittance table stores the optical depth tau(r, mu) to the top boundary, and readers
// exponentiate: bilinear interpolation of tau (nearly linear in the table coordinates) is more
// accurate than interpolation of T = exp(-tau), which is convex; near the horizon the difference
// is several tenths of a percent. tau is integrated with the trapezoidal rule (Bruneton 2017
// "ComputeOpticalLengthToTopAtmosphereBoundary").
vec3 ComputeOpticalDepthToTopAtmosphereBoundary(float r, float mu) {
  int steps = AERIAL_ATMOSPHERE.sample_counts.x;
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

// The sunlight a path of optical depth tau (per channel) lets through, per unit of sunlight, as
// Rayleigh and Mie scatter it and as it falls on a surface. For rgb tables that is exp(-tau). The
// channels of spectral tables are colours, and each wavelength is attenuated by its own optical
// depth, a linear function of the channels' (g_j . tau, the three constituents' column densities
// being common to all): the light is summed over the precompute's wavelengths,
// sum_j w_j exp(-g_j . tau) (aerial/spectrum/spectral_sunlight.h).
struct PathSunlight {
  vec3 rayleigh;
  vec3 mie;
  vec3 direct;
};

PathSunlight GetPathSunlight(vec3 optical_depth) {
  // The count is a uniform, but the loop's bound must not depend on uniforms alone: lavapipe 22.3
  // inlines such uniforms and compiles the pipeline anew at each bind (docs/colour.md, "What it
  // costs"). optical_depth is never negative.
  int terms = optical_depth.x >= 0.0 ? AERIAL_ATMOSPHERE.spectral_sunlight_terms.x : 0;
  vec3 rgb_tables = exp(-optical_depth) * float(terms == 0);
  PathSunlight light = PathSunlight(rgb_tables, rgb_tables, rgb_tables);
  vec3 log2_transmittance = optical_depth * -1.4426950409;
  for (int j = 0; j < terms; ++j) {
    // min: a wavelength's optical depth is >= 0 (rounding in the tables could make it < 0).
    float t = exp2(min(dot(AERIAL_ATMOSPHERE.spectral_sunlight_exponent[j].xyz, log2_transmittance), 0.0));
    light.rayleigh += AERIAL_ATMOSPHERE.spectral_sunlight_rayleigh[j].xyz * t;
    light.mie += AERIAL_ATMOSPHERE.spectral_sunlight_mie[j].xyz * t;
    light.direct += AERIAL_ATMOSPHERE.spectral_sunlight_direct[j].xyz * t;
  }
  return light;
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

vec3 GetOpticalDepthFromOrigin(sampler2D transmittance_texture, vec3 origin, float r, float mu,
                               float d, bool ray_r_mu_intersects_ground) {
  float r_d = RadiusAtDistance(r, mu, d);
  float mu_d = MuAtDistance(r, mu, d, r_d);
  // One read, at the reversed ray for a ray that hits the ground (definitions.glsl, "Control flow").
  vec3 tau_d = GetOpticalDepthToTopAtmosphereBoundary(transmittance_texture, r_d,
                                                      ray_r_mu_intersects_ground ? -mu_d : mu_d);
  return max(ray_r_mu_intersects_ground ? tau_d - origin : origin - tau_d, vec3(0.0));
}

vec3 GetTransmittanceFromOrigin(sampler2D transmittance_texture, vec3 origin, float r, float mu,
                                float d, bool ray_r_mu_intersects_ground) {
  return exp(-GetOpticalDepthFromOrigin(transmittance_texture, origin, r, mu, d,
                                        ray_r_mu_intersects_ground));
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

// True in a shader whose every point has the sun more than SUN_DISC_ONE_TAP_ELEVATION above its
// horizontal: the variants for such frames of the froxel pass, the sky-view lattice's correction
// and the marched per-pixel path's mesh passes and sky (aerial/render/sun_high_variant.h), which
// define it as a specialization constant before their includes. The disc is then its centre alone and J_ms is blended linearly
// in mu_s (GetDensityBlended), their tests compiled out.
#ifndef AERIAL_SUN_HIGH_EVERYWHERE
#define AERIAL_SUN_HIGH_EVERYWHERE false
#endif

// The zenith cosine of the disc's point y disc radii above its centre, to O(alpha^4) = 1e-9.
float GetDiscPointCosine(float mu_s, float sin_s, float y) {
  float y_alpha = y * AERIAL_ATMOSPHERE.sun_angular_radius;
  return mu_s * (1.0 - 0.5 * y_alpha * y_alpha) + sin_s * y_alpha;
}

// Elevation of the disc centre above the cut-off, in disc radii (to first order in the angle).
float GetSunElevationInDiscRadii(float mu_s, float cut_off_cosine) {
  float sin_cut_off = sqrt(max(1.0 - cut_off_cosine * cut_off_cosine, 0.0));
  return (mu_s - cut_off_cosine) / (sin_cut_off * AERIAL_ATMOSPHERE.sun_angular_radius);
}

// Visible fraction of a uniform disc cut by a straight line x radii below its centre.
float GetSunDiscVisibleFraction(float x) {
  return x >= 1.0 ? 1.0 : clamp(0.5 + (x * sqrt(1.0 - x * x) + asin(x)) / PI, 0.0, 1.0);
}

// Tap i of a disc read in `taps` taps (2 to 4; 1: the centre alone): the zenith cosine of its
// point and its weight, to be normalized by the taps' sum (Gauss-Chebyshev weights already sum
// to 1). t_h: the visible part of a cut disc, y = cos t for t in [0, t_h]. Each tap's node is
// worked out by selects as the tap is read, in a loop of `taps` passes (definitions.glsl, "Control
// flow"): on a CPU rasterizer a SIMD group of points that take the centre alone (the sun more than
// 10 degrees above the cut-off) pays for one pass and the masked one that ends the loop, where
// the centre's early return before the taps' branch cost it both: five reads and the trigonometry.
void GetSunDiscTap(int i, int taps, float mu_s, float sin_s, float t_h, out float mu, out float w) {
  // A whole disc: y = +-1/2 (2 taps), or +-1/sqrt 2 and 0 (3 taps).
  float y = taps == 2 ? 0.5 : 0.70710678;
  float whole_y = i == 0 ? y : (i == 1 ? -y : 0.0);
  float whole_w = taps == 2 ? 0.5 : (i == 2 ? 0.5 : 0.25);
  // A cut disc: Gauss-Legendre in t, 4 points on [-1, 1].
  const vec4 node = vec4(-0.3399810436, -0.8611363116, 0.3399810436, 0.8611363116);
  const vec4 weight = vec4(0.6521451549, 0.3478548451, 0.6521451549, 0.3478548451);
  float t = 0.5 * t_h * (1.0 + node[i]);
  float sin_t = sin(t);
  bool cut = taps == 4;
  mu = taps == 1 ? mu_s : GetDiscPointCosine(mu_s, sin_s, cut ? cos(t) : whole_y);
  w = taps == 1 ? 1.0 : (cut ? weight[i] * sin_t * sin_t : whole_w);
}

// Adds tap i of the disc's `taps` (GetSunDiscTap) to a sum of weighted sunlight and to the sum of
// the weights: the tap's GetPathSunlight through its own slant and then `path`.
void AddSunDiscTap(sampler2D transmittance_texture, int i, int taps, float r, float mu_s, float sin_s,
                   float t_h, bool cosine_weighted, vec3 path, inout PathSunlight light, inout float weights) {
  float mu, w;
  GetSunDiscTap(i, taps, mu_s, sin_s, t_h, mu, w);
  PathSunlight tap = GetPathSunlight(path + GetOpticalDepthToTopAtmosphereBoundary(transmittance_texture, r, mu));
  weights += w;
  w *= cosine_weighted ? max(mu, 0.0) : 1.0;
  light.rayleigh += w * tap.rayleigh;
  light.mie += w * tap.mie;
  light.direct += w * tap.direct;
}

// The sunlight through the disc's paths to radius r, followed by a path of optical depth `path`
// (toward the camera, or none), per unit of sunlight: the taps' GetPathSunlight, each through its
// own slant, averaged by their weights and times the visible fraction (each also times its
// point's cosine where cosine_weighted). In spectral tables each wavelength thus crosses each
// tap's slant with its own optical depth; the channels' mean optical depth over the taps, with
// their spread about it as one factor per channel, left the radiance to a point 10 km up at
// twilight 0.0033 off in u'v' instead of 0.0017 (aerial_bench_colour, docs/colour.md).
// The first tap (the centre, for a sun high over the cut-off) is read before the loop over the
// others, which a high sun never enters, so that the sunlight sum's own loop is not nested in a
// loop wherever the sun is high: the marched per-pixel path at noon took 6-8% more time with every
// tap in the loop (aerial_bench_render, docs/speed.md).
PathSunlight GetSunDiscSunlight(sampler2D transmittance_texture, float r, float mu_s,
                                float cut_off_cosine, bool cosine_weighted, vec3 path) {
  PathSunlight light = PathSunlight(vec3(0.0), vec3(0.0), vec3(0.0));
  float x = GetSunElevationInDiscRadii(mu_s, cut_off_cosine);
  if (x <= -1.0) return light;
  // x alpha >= mu_s for a cut-off at or below the horizontal: AERIAL_SUN_HIGH_EVERYWHERE implies it.
  bool one_tap = AERIAL_SUN_HIGH_EVERYWHERE || x * AERIAL_ATMOSPHERE.sun_angular_radius > SUN_DISC_ONE_TAP_ELEVATION;
  bool whole = x >= 1.0 && !cosine_weighted;
  int taps = one_tap ? 1 : (whole ? (x > 5.0 ? 2 : 3) : 4);
  float sin_s = sqrt(max(1.0 - mu_s * mu_s, 0.0));
  float t_h = acos(clamp(-x, -1.0, 1.0));
  float weights = 0.0;
  AddSunDiscTap(transmittance_texture, 0, taps, r, mu_s, sin_s, t_h, cosine_weighted, path, light, weights);
  for (int i = 1; i < taps; ++i)
    AddSunDiscTap(transmittance_texture, i, taps, r, mu_s, sin_s, t_h, cosine_weighted, path, light, weights);
  float scale = (taps == 4 ? GetSunDiscVisibleFraction(x) : 1.0) / max(weights, 1e-30);
  return PathSunlight(light.rayleigh * scale, light.mie * scale, light.direct * scale);
}

// -sqrt(1 - (R / r)^2), from the horizon distance without cancellation.
float GetHorizonCosine(float r) { return -sqrt(SquaredHorizonDistance(r)) / r; }

// The sunlight through the part of the disc above the horizon of radius r, then `path`.
PathSunlight GetSunlightAt(sampler2D transmittance_texture, float r, float mu_s, vec3 path) {
  return GetSunDiscSunlight(transmittance_texture, r, mu_s, GetHorizonCosine(r), false, path);
}

// The sun's direct irradiance (W/m^2/nm) at radius r, per unit area normal to the sun (times its
// cosine where cosine_weighted), from the disc above cut_off_cosine.
vec3 GetDirectSunlight(sampler2D transmittance_texture, float r, float mu_s, float cut_off_cosine,
                       bool cosine_weighted) {
  return AERIAL_ATMOSPHERE.solar_irradiance.rgb *
         GetSunDiscSunlight(transmittance_texture, r, mu_s, cut_off_cosine, cosine_weighted, vec3(0.0)).direct;
}

// The disc's average transmittance to radius r, channel by channel, for rgb tables (the sun band,
// which the precompute's rgb groups tabulate): their direct sunlight is exp(-tau).
vec3 GetTransmittanceToSun(sampler2D transmittance_texture, float r, float mu_s) {
  return GetSunlightAt(transmittance_texture, r, mu_s, vec3(0.0)).direct;
}

// ---- The sun band: GetTransmittanceToSun tabulated for the precomputation. ----
// The single scattering passes evaluate the disc's average at every step of every ray. Near each
// point's horizon that is 2 to 4 table reads with trigonometry, most of the single scattering
// pass's time on lavapipe (the lanes of a SIMD group, neighbouring mu_s texels, take different
// branches, and each runs them all). It depends on (r, mu_s) alone, so a pass
// (precompute/sun_band.comp) tabulates it where it differs from the centre's value: x, the
// centre's elevation above the horizon in disc radii, from -1 to SUN_DISC_ONE_TAP_ELEVATION (37.4
// radii), uniformly on the u axis; r on the transmittance table's rho/H mapping on the v axis (its
// rows).
// The band holds the optical depth of the visible part's average, -ln(average / visible), which
// is smooth where the visible fraction is not; a read multiplies by the exact visible fraction.
float GetSunBandMaxElevationInDiscRadii() {
  return SUN_DISC_ONE_TAP_ELEVATION / AERIAL_ATMOSPHERE.sun_angular_radius;
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
  mu_s = cut_off + x * sqrt(1.0 - cut_off * cut_off) * AERIAL_ATMOSPHERE.sun_angular_radius;
}

// GetSunlightAt, with the disc read from the sun band where it takes more than its centre: the
// visible part's average optical depth, times the visible fraction.
PathSunlight GetSunlightFromBand(sampler2D transmittance_texture, sampler2D sun_band_texture,
                                 float r, float mu_s, vec3 path) {
  float x = GetSunElevationInDiscRadii(mu_s, GetHorizonCosine(r));
  bool in_band = x <= GetSunBandMaxElevationInDiscRadii();
  vec2 uv = GetSunBandTextureUv(textureSize(sun_band_texture, 0), r, x);
  vec3 optical_depth = in_band ? ReadTable(sun_band_texture, uv).rgb
                               : GetOpticalDepthToTopAtmosphereBoundary(transmittance_texture, r, mu_s);
  float weight = x <= -1.0 ? 0.0 : (in_band ? GetSunDiscVisibleFraction(x) : 1.0);
  PathSunlight light = GetPathSunlight(path + optical_depth);
  return PathSunlight(light.rayleigh * weight, light.mie * weight, light.direct * weight);
}

#endif
