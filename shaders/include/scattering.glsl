// Scattering: computing the single and multiple scattering tables and reading them (Bruneton 2017,
// functions.glsl "Single scattering", "Multiple scattering"). Tables store radiance WITHOUT phase:
// Rayleigh and Mie single scattering in separate tables, and multiple scattering divided by the
// Rayleigh phase and added to the Rayleigh table, so that multiplying by P_R(nu) restores it.
#ifndef AERIAL_SCATTERING_GLSL
#define AERIAL_SCATTERING_GLSL
#include "phase.glsl"
#include "transmittance.glsl"

// The 3D tables (Elek 2009; Hillaire 2016) drop nu. Their one assumption: along a view ray the
// sun keeps the zenith angle it has at the camera, as in a plane-parallel atmosphere, instead of
// mu_s_d = (r mu_s + d nu) / r_d. Everything that depended on nu through the geometry then
// depends on (r, mu, mu_s) only; what is lost is the sun setting along the ray, i.e. the Earth's
// shadow cast on the atmosphere, and the sun's changing elevation over long (near-horizontal)
// paths. Phase functions still use each ray's true nu.
bool TablesDropNu() { return AERIAL_ATMOSPHERE.scattering_size.w == 1; }

// The orders beyond the last one computed, N, as a geometric series. Each order is the previous
// one through the same scattering operator, so the ratio of consecutive orders settles to a
// constant (the operator's dominant eigenvalue): the CPU reference measures 0.35-0.36 in blue from
// order 4 to 8 on a daylight ray. With that ratio q = L_N / L_{N-1}, taken per texel and channel,
// L_N + L_{N+1} + ... = L_N / (1 - q). q is capped at 0.9: an order that does not decay is
// rounding in values near zero, not physics (Earth's largest measured ratio is ~0.5).
vec3 SumSeriesFromLastOrder(vec3 last_order, vec3 previous_order) {
  vec3 ratio = mix(vec3(0.0), min(last_order / previous_order, vec3(0.9)),
                   greaterThan(previous_order, vec3(0.0)));
  return last_order / (1.0 - max(ratio, vec3(0.0)));
}

float SunCosineAlongRay(float r, float mu_s, float nu, float d, float r_d) {
  return TablesDropNu() ? mu_s : MuSAtDistance(r, mu_s, nu, d, r_d);
}

// Where single scattering is marched along a ray: sample i of `steps` at the ray's length times
// x^p, x = i / steps.
// With the sun near the camera's horizon its disc rises above (or sets below) each point's horizon
// in the first kilometres of the ray, and the sunlight reaching those points changes by orders of
// magnitude there (grazing slants, the disc cut by the horizon). Equal steps (12 km along a ray
// 2 degrees above the horizon) straddled it: looking 2 degrees up toward a sun at zenith 90.31
// degrees from the ground, the table's order 1 was 7.1 / 3.1 / 0.4% low. Quadratic spacing (p = 2)
// took it to 0.3%, but coarsened the far end of long rays, which the daylight horizon sky and
// twilight need (aerial_bench_sky: daylight sky on the ground 0.81 -> 0.95%, twilight 3.6 ->
// 14%). So p goes from 2, with the sun's centre on the camera's horizon, to 1 (equal steps) at
// SUN_NEAR_HORIZON_ELEVATION above or below it, continuously in the sun's angle. 3 degrees: 2
// left the low-sun sky 10 km up 4.4% off in red (3.5% at 3), 5 the low-sun sky on the ground
// 3.3% in red (3.0%) and the twilight sky's medians 50 km up at 0.5% (0.3%).
const float SUN_NEAR_HORIZON_ELEVATION = 0.0524;

float GetStepSpacingExponent(float r, float mu_s) {
  float elevation = asin(clamp(mu_s, -1.0, 1.0)) - asin(GetHorizonCosine(r));
  return 2.0 - clamp(abs(elevation) / SUN_NEAR_HORIZON_ELEVATION, 0.0, 1.0);
}

float GetStepDistance(float ray_length, int i, int steps, float spacing_exponent) {
  return ray_length * pow(float(i) / float(steps), spacing_exponent);
}

// Integrand of single scattering at radius r_d: the sunlight that reaches the camera through the
// sun's disc and then the view path (GetSunDiscSunlight), times the density of each species there.
void ComputeSingleScatteringIntegrandAt(float r_d, PathSunlight sunlight, out vec3 rayleigh,
                                        out vec3 mie) {
  float altitude = r_d - AERIAL_ATMOSPHERE.bottom_radius;
  rayleigh = sunlight.rayleigh * GetProfileDensity(AERIAL_ATMOSPHERE.rayleigh_density, altitude);
  mie = sunlight.mie * GetProfileDensity(AERIAL_ATMOSPHERE.mie_density, altitude);
}

// The same at distance d along the ray (r, mu), with the sunlight read from the sun band.
void ComputeSingleScatteringIntegrand(sampler2D transmittance_texture, sampler2D sun_band_texture,
                                      vec3 origin, float r, float mu, float mu_s, float nu,
                                      float d, bool ray_r_mu_intersects_ground, out vec3 rayleigh,
                                      out vec3 mie) {
  float r_d = RadiusAtDistance(r, mu, d);
  vec3 view = GetOpticalDepthFromOrigin(transmittance_texture, origin, r, mu, d,
                                        ray_r_mu_intersects_ground);
  ComputeSingleScatteringIntegrandAt(
      r_d, GetSunlightFromBand(transmittance_texture, sun_band_texture, r_d,
                               SunCosineAlongRay(r, mu_s, nu, d, r_d), view),
      rayleigh, mie);
}

// Single scattering (Bruneton 2008 eq. 11 without the phase function), integrated over the
// distance to the nearest boundary in steps spaced by GetStepSpacingExponent, with
// ExponentialStepIntegral.
void ComputeSingleScatteringInSteps(sampler2D transmittance_texture, sampler2D sun_band_texture,
                                     float r, float mu, float mu_s, float nu,
                                     bool ray_r_mu_intersects_ground, int steps, out vec3 rayleigh,
                                     out vec3 mie) {
  float ray_length = DistanceToNearestAtmosphereBoundary(r, mu, ray_r_mu_intersects_ground);
  float spacing_exponent = GetStepSpacingExponent(r, mu_s);
  vec3 origin = GetRayOpticalDepthOrigin(transmittance_texture, r, mu, ray_r_mu_intersects_ground);
  vec3 rayleigh_sum = vec3(0.0);
  vec3 mie_sum = vec3(0.0);
  vec3 rayleigh_previous;
  vec3 mie_previous;
  ComputeSingleScatteringIntegrand(transmittance_texture, sun_band_texture, origin, r, mu, mu_s,
                                   nu, 0.0, ray_r_mu_intersects_ground, rayleigh_previous,
                                   mie_previous);
  for (int i = 1; i <= steps; ++i) {
    vec3 rayleigh_i;
    vec3 mie_i;
    float d = GetStepDistance(ray_length, i, steps, spacing_exponent);
    float dx = d - GetStepDistance(ray_length, i - 1, steps, spacing_exponent);
    ComputeSingleScatteringIntegrand(transmittance_texture, sun_band_texture, origin, r, mu, mu_s,
                                     nu, d, ray_r_mu_intersects_ground, rayleigh_i, mie_i);
    rayleigh_sum += ExponentialStepIntegral(rayleigh_previous, rayleigh_i) * dx;
    mie_sum += ExponentialStepIntegral(mie_previous, mie_i) * dx;
    rayleigh_previous = rayleigh_i;
    mie_previous = mie_i;
  }
  vec3 sun = AERIAL_ATMOSPHERE.solar_irradiance.rgb;
  rayleigh = rayleigh_sum * sun * AERIAL_ATMOSPHERE.rayleigh_scattering.rgb;
  mie = mie_sum * sun * AERIAL_ATMOSPHERE.mie_scattering.rgb;
}

void ComputeSingleScattering(sampler2D transmittance_texture, sampler2D sun_band_texture, float r,
                             float mu, float mu_s, float nu, bool ray_r_mu_intersects_ground,
                             out vec3 rayleigh, out vec3 mie) {
  ComputeSingleScatteringInSteps(transmittance_texture, sun_band_texture, r, mu, mu_s, nu,
                                 ray_r_mu_intersects_ground, AERIAL_ATMOSPHERE.sample_counts.y, rayleigh,
                                 mie);
}

// Reads of a 4D table packed in 3D (x = nu_index * MU_S + mu_s_index) interpolate linearly in nu
// between two slices; the other three axes use the sampler's trilinear filter. A table with one
// nu slice is the 3D variant. The blend between the two slices is a vec2: x the lower slice's
// index, y the upper one's weight.
vec2 GetNominalNuBlend(ivec4 size, vec4 uvwz) {
  float nu_size = float(size.w);
  float tex_coord_x = uvwz.x * (nu_size - 1.0);
  float tex_x = min(floor(tex_coord_x), nu_size - 2.0);
  return vec2(tex_x, tex_coord_x - tex_x);
}

// The blend for the precomputation's per-order multiple scattering tables, which hold values at
// each texel's clamped nu (GetRMuMuSNuFromScatteringTexel; the density tables have an azimuth
// axis instead, GetUnitRangeFromViewSunAzimuth). Near the end of the allowed nu range the outer of
// the two nu slices holds the value at the range's end, not at its place on the axis; the weight
// between the slices is taken between where their values really are. Without this, the forward
// Mie peak is smeared toward the middle of the range and the multiple scattering seen toward the
// sun is too low by several percent.
vec2 GetClampedNuBlend(ivec4 size, vec4 uvwz, float mu, float mu_s, float nu) {
  if (size.w == 1) return vec2(0.0);
  float tex_x = GetNominalNuBlend(size, uvwz).x;
  float spread = GetNuSpread(mu, mu_s);
  float nu0 = clamp(GetNominalNuOfSlice(size, tex_x), mu * mu_s - spread, mu * mu_s + spread);
  float nu1 = clamp(GetNominalNuOfSlice(size, tex_x + 1.0), mu * mu_s - spread, mu * mu_s + spread);
  return vec2(tex_x, nu1 > nu0 ? clamp((nu - nu0) / (nu1 - nu0), 0.0, 1.0) : 0.5);
}

// uvw: the table coordinates of (mu_s, mu, r), i.e. uvwz.yzw. One read chosen by a select, the
// second only for the 4D tables (definitions.glsl, "Control flow").
vec3 GetScatteringBlended(sampler3D scattering_texture, ivec4 size, vec2 nu_blend, vec3 uvw) {
  bool one_slice = size.w == 1;
  float nu_size = float(size.w);
  vec3 uvw0 = one_slice ? uvw : vec3((nu_blend.x + uvw.x) / nu_size, uvw.y, uvw.z);
  vec3 scattering = ReadTable(scattering_texture, uvw0).rgb;
  if (!one_slice) {
    vec3 uvw1 = vec3((nu_blend.x + 1.0 + uvw.x) / nu_size, uvw.y, uvw.z);
    scattering = mix(scattering, ReadTable(scattering_texture, uvw1).rgb, nu_blend.y);
  }
  return scattering;
}

vec3 GetScatteringAt(sampler3D scattering_texture, ivec4 size, vec4 uvwz) {
  return GetScatteringBlended(scattering_texture, size, GetNominalNuBlend(size, uvwz), uvwz.yzw);
}

vec3 GetScattering(sampler3D scattering_texture, ivec4 size, float r, float mu, float mu_s,
                   float nu, bool ray_r_mu_intersects_ground) {
  return GetScatteringAt(
      scattering_texture, size,
      GetScatteringTextureUvwzFromRMuMuSNu(size, MU_AXIS_RAY_LENGTH, r, mu, mu_s, nu,
                                           ray_r_mu_intersects_ground));
}

// The multiple density J_ms in the Earth's shadow. Where the sun is below the horizon, the density
// of orders >= 2 is the light of the sunlit air above scattered once more, and it falls roughly
// exponentially as the sun goes down: at sun zenith 95 degrees, by a factor 1.6-1.8 from one mu_s
// texel to the next (0.52 degrees apart). A linear blend of a falling exponential overestimates it
// (by 3% midway at that ratio), and so does everything integrated from it: radiance to a point
// from the ground at sun zenith 95 was 11% high in blue. Between two mu_s texels whose upper one
// has the sun below the horizon, J_ms is blended exponentially, where the per-order densities are
// resampled into it and where radiance to a point and the froxel build march it; elsewhere, and in
// the other tables, linearly. Both blends agree on the texels, so the read stays continuous.
//  - The precompute's integration of order 2's density along the rays too
//    (multiple_scattering.comp), where most of the multiple scattering in the shadow comes from:
//    the low-sun sky on the ground 3.3% -> 2.1%, 10 km up 4.9% -> 3.2%, for a sixteenth more
//    precompute time. Every order would take the precompute over its 8 s target.
//  - Not for the 3D tables, which have no Earth's shadow: their low-sun radiance to a point on the
//    ground got worse that way (47% -> 54% at most in blue, aerial_bench_sky --lut 3d).
vec3 GetDensityBlended(sampler3D density_texture, ivec4 size, vec2 nu_blend, vec3 uvw) {
  float mu_s_size = float(size.z);
  vec2 blend = GetTexelBlend(uvw.x, mu_s_size);
  // The sun high (AERIAL_SUN_HIGH_EVERYWHERE): both texels hold a sun above the horizon.
  bool exponential = !AERIAL_SUN_HIGH_EVERYWHERE && size.w != 1 && blend.y != 0.0 &&
                     IsMuSTexelBelow(blend.x + 1.0, mu_s_size, 0.0);
  // Linear: one read at uvw. Exponential: the lower texel's centre, then the upper one's
  // (definitions.glsl, "Control flow").
  vec3 density = GetScatteringBlended(density_texture, size, nu_blend,
                                      exponential ? vec3((blend.x + 0.5) / mu_s_size, uvw.yz) : uvw);
  if (exponential) {
    vec3 upper = GetScatteringBlended(density_texture, size, nu_blend,
                                      vec3((blend.x + 1.5) / mu_s_size, uvw.yz));
    density = MixExponentially(density, upper, blend.y);
  }
  return density;
}

// The blend in mu_s (and nu): GetDensityBlended for J_ms (density), linear for the other tables.
vec3 GetTableBlended(sampler3D scattering_texture, ivec4 size, bool density, vec2 nu_blend,
                     vec3 uvw) {
  return density ? GetDensityBlended(scattering_texture, size, nu_blend, uvw)
                 : GetScatteringBlended(scattering_texture, size, nu_blend, uvw);
}

// The table coordinates of a density read (J_n, J_ms): linear in mu_s between two daylight texels
// (GetMuSTextureCoordLinearInDaylight), as the sky irradiance. The density's light reflected by
// the ground goes as mu_s T(mu_s), and the arctangent axis puts the daylight texels at sun zeniths
// 0, 54.2 and 66.8 degrees: blended in the axis coordinate, order 2's ground-reflected part of the
// radiance to a point on the ground read 7% high at sun zenith 45 (0.3% at 10 and 2% at 75). The
// density tables' mu axis is the view zenith angle (MU_AXIS_VIEW_ZENITH).
vec4 GetDensityTextureUvwz(ivec4 size, float r, float mu, float mu_s, float nu,
                           bool ray_r_mu_intersects_ground) {
  vec4 uvwz = GetScatteringTextureUvwzFromRMuMuSNu(size, MU_AXIS_VIEW_ZENITH, r, mu, mu_s, nu,
                                                   ray_r_mu_intersects_ground);
  uvwz.y = GetMuSTextureCoordLinearInDaylight(mu_s, size.z);
  return uvwz;
}

// A radiance table of one order (linear in the axis coordinates) at the clamped nu.
vec3 GetScatteringClampedNu(sampler3D scattering_texture, ivec4 size, int mu_axis, float r,
                            float mu, float mu_s, float nu, bool ray_r_mu_intersects_ground) {
  vec4 uvwz = GetScatteringTextureUvwzFromRMuMuSNu(size, mu_axis, r, mu, mu_s, nu,
                                                   ray_r_mu_intersects_ground);
  return GetScatteringBlended(scattering_texture, size, GetClampedNuBlend(size, uvwz, mu, mu_s, nu),
                              uvwz.yzw);
}

// A density table of one order (on the view zenith mu axis and the azimuth axis), exponential in
// mu_s in the Earth's shadow if asked (GetDensityBlended).
vec3 GetDensityOfOrder(sampler3D density_texture, ivec4 size, bool exponential_in_shadow, float r,
                       float mu, float mu_s, float nu, bool ray_r_mu_intersects_ground) {
  vec4 uvwz = GetDensityTextureUvwz(size, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
  return GetTableBlended(density_texture, size, exponential_in_shadow,
                         GetNominalNuBlend(size, uvwz), uvwz.yzw);
}

// Interpolates exponentially between the two nearest r slices instead of linearly. Scattering
// falls off roughly exponentially with altitude, and at the default 32 r slices a slice spans
// 2.1 km of altitude at 10 km (Mie's scale height is 1.2 km) and 2.3 km at 50 km: linear
// interpolation overestimated the inscatter seen by a high camera by up to 20% (Mie) and 2.4%
// (Rayleigh) with slices 1.6 and 3.5 km apart there. Where either slice is zero (night side) the
// interpolation falls back to linear.
vec3 GetScatteringBlendedExponentialInR(sampler3D scattering_texture, ivec4 size, bool density,
                                        vec2 nu_blend, vec4 uvwz) {
  float r_size = float(size.x);
  vec2 blend = GetTexelBlend(uvwz.w, r_size);
  vec3 s0 = GetTableBlended(scattering_texture, size, density, nu_blend,
                            vec3(uvwz.yz, (blend.x + 0.5) / r_size));
  // On a slice (a camera on the ground): uniform over a frame's pixels.
  if (blend.y == 0.0) return s0;
  vec3 s1 = GetTableBlended(scattering_texture, size, density, nu_blend,
                            vec3(uvwz.yz, (blend.x + 1.5) / r_size));
  return MixExponentially(s0, s1, blend.y);
}

// The render-time read of the final radiance tables.
vec3 GetScatteringExponentialInR(sampler3D scattering_texture, ivec4 size, float r, float mu,
                                 float mu_s, float nu, bool ray_r_mu_intersects_ground) {
  vec4 uvwz = GetScatteringTextureUvwzFromRMuMuSNu(size, MU_AXIS_RAY_LENGTH, r, mu, mu_s, nu,
                                                   ray_r_mu_intersects_ground);
  return GetScatteringBlendedExponentialInR(scattering_texture, size, false,
                                            GetNominalNuBlend(size, uvwz), uvwz);
}

// The render-time read of the multiple density table J_ms (the view zenith mu axis, the azimuth
// axis, exponential in r: the density follows the air's density), which holds it scaled.
vec3 GetMultipleScatteringDensity(sampler3D multiple_density_texture, float r, float mu,
                                  float mu_s, float nu, bool ray_r_mu_intersects_ground) {
  ivec4 size = AERIAL_ATMOSPHERE.multiple_density_size;
  vec4 uvwz = GetDensityTextureUvwz(size, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
  return GetScatteringBlendedExponentialInR(multiple_density_texture, size, true,
                                            GetNominalNuBlend(size, uvwz), uvwz) /
         AERIAL_ATMOSPHERE.multiple_density_scale;
}

// Radiance of scattering order `order` arriving along (r, mu) with the sun at (mu_s, nu): order 1
// from the separate single scattering tables with their phase functions, higher orders from the
// multiple scattering table of that order (which holds radiance, phase included).
vec3 GetScatteringOfOrder(sampler3D single_rayleigh_texture, sampler3D single_mie_texture,
                          sampler3D multiple_scattering_texture, float r, float mu, float mu_s,
                          float nu, bool ray_r_mu_intersects_ground, int order) {
  if (order == 1) {
    vec3 rayleigh = GetScattering(single_rayleigh_texture, AERIAL_ATMOSPHERE.scattering_size, r, mu, mu_s,
                                  nu, ray_r_mu_intersects_ground);
    vec3 mie = GetScattering(single_mie_texture, AERIAL_ATMOSPHERE.scattering_size, r, mu, mu_s, nu,
                             ray_r_mu_intersects_ground);
    return rayleigh * RayleighPhaseFunction(nu) + mie * MiePhaseFunction(AERIAL_ATMOSPHERE.mie_phase_g, nu);
  }
  return GetScatteringClampedNu(multiple_scattering_texture, AERIAL_ATMOSPHERE.density_size,
                                MU_AXIS_RAY_LENGTH, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
}

// Multiple scattering of order n (Bruneton 2008 eq. 12 integrated along the ray): the scattering
// density J of order n, attenuated back to the camera, in equal steps with
// ExponentialStepIntegral.
vec3 MultipleScatteringIntegrand(sampler2D transmittance_texture,
                                 sampler3D scattering_density_texture, vec3 origin, float r,
                                 float mu, float mu_s, float nu, float d,
                                 bool ray_r_mu_intersects_ground, bool density_blended) {
  float r_d = RadiusAtDistance(r, mu, d);
  float mu_d = MuAtDistance(r, mu, d, r_d);
  float mu_s_d = SunCosineAlongRay(r, mu_s, nu, d, r_d);
  return GetDensityOfOrder(scattering_density_texture, AERIAL_ATMOSPHERE.density_size, density_blended,
                           r_d, mu_d, mu_s_d, nu, ray_r_mu_intersects_ground) *
         GetTransmittanceFromOrigin(transmittance_texture, origin, r, mu, d,
                                    ray_r_mu_intersects_ground);
}

vec3 ComputeMultipleScattering(sampler2D transmittance_texture, sampler3D scattering_density_texture,
                               float r, float mu, float mu_s, float nu,
                               bool ray_r_mu_intersects_ground, bool density_blended) {
  int steps = AERIAL_ATMOSPHERE.multiple_scattering_steps.x;
  float dx = DistanceToNearestAtmosphereBoundary(r, mu, ray_r_mu_intersects_ground) / float(steps);
  vec3 origin = GetRayOpticalDepthOrigin(transmittance_texture, r, mu, ray_r_mu_intersects_ground);
  vec3 previous = MultipleScatteringIntegrand(transmittance_texture, scattering_density_texture,
                                              origin, r, mu, mu_s, nu, 0.0,
                                              ray_r_mu_intersects_ground, density_blended);
  vec3 radiance_sum = vec3(0.0);
  for (int i = 1; i <= steps; ++i) {
    vec3 current = MultipleScatteringIntegrand(transmittance_texture, scattering_density_texture,
                                               origin, r, mu, mu_s, nu, float(i) * dx,
                                               ray_r_mu_intersects_ground, density_blended);
    radiance_sum += ExponentialStepIntegral(previous, current);
    previous = current;
  }
  return radiance_sum * dx;
}

#endif
