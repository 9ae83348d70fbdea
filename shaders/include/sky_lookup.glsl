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
  vec3 rayleigh = GetScatteringExponentialInR(rayleigh_texture, AERIAL_ATMOSPHERE.scattering_size, r, mu,
                                              mu_s, nu, ray_r_mu_intersects_ground);
  if (TablesDropNu()) {
    // Linear in mu_s in daylight, as the 4D tables' multiple scattering is blended there
    // (GetMultipleScatteringBlendCorrection).
    ivec4 size = AERIAL_ATMOSPHERE.scattering_size;
    vec4 uvwz = GetScatteringTextureUvwzFromRMuMuSNu(size, MU_AXIS_RAY_LENGTH, r, mu, mu_s, nu,
                                                     ray_r_mu_intersects_ground);
    uvwz.y = GetMuSTextureCoordLinearInDaylight(mu_s, size.z);
    rayleigh += GetScatteringBlendedExponentialInR(multiple_texture, size, false,
                                                   GetNominalNuBlend(size, uvwz), uvwz) /
                RayleighPhaseFunction(nu);
  }
  return rayleigh;
}

// Single scattering read from the tables is interpolated linearly between two mu_s texels and two
// nu slices. Where the Earth's shadow crosses the ray (sun zenith 85-108 degrees) it changes faster
// than the texels follow: at sun zenith 95 degrees the sky's order 1 was 13-27% too bright. The
// tables' read is corrected by the single scattering of the query, integrated along the ray, minus
// the same integral at the four (mu_s, nu) nodes the read blends, with the read's weights (a
// control variate: the march's own errors are common to both terms and cancel). The r and mu
// blends are left as they are: the shadow line moves with the sun, not with them.
//  - One march for the five suns: they share the ray, its transmittance and the air's density,
//    and differ in the sunlight reaching each point (Bruneton 2008 eq. 11 per sun).
//  - 32 steps (aerial_bench_sky): with 8 the twilight sky 10 km up was 20% off; with 16, 13.1%
//    (6.4% in green: between two mu_s texels 16 steps of 70 km missed the sunlit end of the ray,
//    and order 1 read 14% low instead of 2-3% on the texels), with 32 11.9% (2.9%), with 64 the
//    same. 32 also took the low-sun sky 50 km up from 1.5% to 1.0% in red.
//  - Not for the 3D tables: their low-sun error is the Earth's shadow they do not have (hundreds
//    of percent), which the correction, marched with their own fixed sun, cannot restore; it
//    made their low-sun medians worse by up to 3.3 points (aerial_bench_sky --lut 3d).
//  - Only while the lower mu_s node is below SINGLE_SCATTERING_CORRECTION_MU_S (sun zenith 75
//    degrees): above it the sun stays more than 6 degrees above every point of a ray (at most
//    1000 km long, 9 degrees of the Earth's arc), single scattering is smooth in mu_s, and the
//    correction moved no daylight or afternoon region by more than 0.05 points. Above it the march
//    still runs, for the multiple scattering's blend in nu (GetMultipleScatteringBlendCorrection),
//    which needs the nodes' single scattering (six in daylight, for its quadratic blend in mu_s)
//    only to take it out of the table's value and moves by the difference between that blend's
//    weights and the read's times any error in it: in MULTIPLE_SCATTERING_BLEND_STEPS steps, 16,
//    since the daylight blend takes weights of its own (below), and for the nodes only: the query's
//    sun does not need them, and every step is paid again at each node of the sky-view lattice
//    whenever the sun moves.
const int SINGLE_SCATTERING_CORRECTION_STEPS = 32;
const float SINGLE_SCATTERING_CORRECTION_MU_S = 0.26;
const int MULTIPLE_SCATTERING_BLEND_STEPS = 16;
const int LOW_SUN_SUNS = 5;  // the query and the blend's four nodes
const int SINGLE_SCATTERING_SUNS = 7;  // and in daylight a third mu_s node's two slices

// The suns marched: the query's (k = 0) and the texel nodes (k = 1 + 2 a + b: mu_s node a, nu
// slice b), with the read's blend weights of the upper node and slice. Nodes 0 and 1 are the two
// texels the read blends; node 2, for the daylight blend, the texel below them.
struct SingleScatteringSuns {
  float mu_s[SINGLE_SCATTERING_SUNS], nu[SINGLE_SCATTERING_SUNS];
  float mu_s_weight, nu_weight;
  float mu_s_texel;  // the lower node's texel index
  float nu_slice;    // the lower slice's index
};

// The mu_s that the scattering tables' mu_s texel `texel` holds.
float GetMuSOfScatteringTexel(ivec4 size, float texel) {
  return GetMuSFromScatteringUMuS(size, (texel + 0.5) / float(size.z));
}

// The two mu_s texels that the table's read at mu_s blends: (x, y) their mu_s, (z) the upper
// one's weight, (w) the lower one's texel index.
vec4 GetScatteringMuSBlend(ivec4 size, float mu_s) {
  vec2 blend = GetTexelBlend(GetScatteringUMuS(size, mu_s), float(size.z));
  return vec4(GetMuSOfScatteringTexel(size, blend.x), GetMuSOfScatteringTexel(size, blend.x + 1.0),
              blend.y, blend.x);
}

// Whether the sky's inscatter read from tables of this size is corrected (4D tables only).
bool SkyInscatterCorrectionApplies(ivec4 size) { return size.w > 1; }

// The query's sun and the texels' suns that the table's read blends; false where the correction
// is not needed.
bool GetSingleScatteringSuns(ivec4 size, float mu, float mu_s, float nu,
                             out SingleScatteringSuns suns) {
  if (!SkyInscatterCorrectionApplies(size)) return false;
  vec4 mu_s_blend = GetScatteringMuSBlend(size, mu_s);
  vec2 nu_blend = GetNominalNuBlend(size, vec4(GetUnitRangeFromNu(nu), 0.0, 0.0, 0.0));
  suns.mu_s_weight = mu_s_blend.z;
  suns.nu_weight = nu_blend.y;
  suns.mu_s_texel = mu_s_blend.w;
  suns.nu_slice = nu_blend.x;
  suns.mu_s[0] = mu_s;
  suns.nu[0] = nu;
  float node_mu_s[3] = float[3](mu_s_blend.x, mu_s_blend.y,
                                GetMuSOfScatteringTexel(size, max(suns.mu_s_texel - 1.0, 0.0)));
  for (int a = 0; a < 3; ++a) {
    float spread = sqrt(max((1.0 - mu * mu) * (1.0 - node_mu_s[a] * node_mu_s[a]), 0.0));
    for (int b = 0; b < 2; ++b) {
      int k = 1 + 2 * a + b;
      // A texel holds its value at its nominal nu clamped to what (mu, mu_s) allow.
      suns.mu_s[k] = node_mu_s[a];
      suns.nu[k] = clamp(GetNominalNuOfSlice(size, suns.nu_slice + float(b)),
                         mu * node_mu_s[a] - spread, mu * node_mu_s[a] + spread);
    }
  }
  return true;
}

// The single scattering of the ray (r, mu) for the suns of `suns` from `first_sun` to before
// `end_sun` (from 1: the nodes only), without phase, marched in `steps` steps spaced for the
// query's sun (GetStepSpacingExponent) with ExponentialStepIntegral.
void MarchSingleScatteringSuns(sampler2D transmittance_texture, float r, float mu,
                               SingleScatteringSuns suns, int first_sun, int end_sun, int steps,
                               out vec3 rayleigh[SINGLE_SCATTERING_SUNS],
                               out vec3 mie[SINGLE_SCATTERING_SUNS]) {
  bool ray_r_mu_intersects_ground = RayIntersectsGround(r, mu);
  float ray_length = DistanceToNearestAtmosphereBoundary(r, mu, ray_r_mu_intersects_ground);
  float spacing_exponent = GetStepSpacingExponent(r, suns.mu_s[0]);
  vec3 origin = GetRayOpticalDepthOrigin(transmittance_texture, r, mu, ray_r_mu_intersects_ground);
  vec3 rayleigh_previous[SINGLE_SCATTERING_SUNS], mie_previous[SINGLE_SCATTERING_SUNS];
  for (int k = 0; k < SINGLE_SCATTERING_SUNS; ++k) {
    rayleigh[k] = vec3(0.0);
    mie[k] = vec3(0.0);
  }
  float d_previous = 0.0;
  for (int i = 0; i <= steps; ++i) {
    float d = GetStepDistance(ray_length, i, steps, spacing_exponent);
    float dx = d - d_previous;
    d_previous = d;
    float r_d = RadiusAtDistance(r, mu, d);
    vec3 view = GetOpticalDepthFromOrigin(transmittance_texture, origin, r, mu, d,
                                          ray_r_mu_intersects_ground);
    for (int k = first_sun; k < end_sun; ++k) {
      vec3 rayleigh_i, mie_i;
      float mu_s_d = SunCosineAlongRay(r, suns.mu_s[k], suns.nu[k], d, r_d);
      ComputeSingleScatteringIntegrandAt(r_d, GetSunlightAt(transmittance_texture, r_d, mu_s_d, view),
                                         rayleigh_i, mie_i);
      if (i > 0) {
        rayleigh[k] += ExponentialStepIntegral(rayleigh_previous[k], rayleigh_i) * dx;
        mie[k] += ExponentialStepIntegral(mie_previous[k], mie_i) * dx;
      }
      rayleigh_previous[k] = rayleigh_i;
      mie_previous[k] = mie_i;
    }
  }
  vec3 sun = AERIAL_ATMOSPHERE.solar_irradiance.rgb;
  for (int k = 0; k < SINGLE_SCATTERING_SUNS; ++k) {
    rayleigh[k] *= sun * AERIAL_ATMOSPHERE.rayleigh_scattering.rgb;
    mie[k] *= sun * AERIAL_ATMOSPHERE.mie_scattering.rgb;
  }
}

// The marched suns' blend as the table's read blends its texels: the query's value minus the
// nodes' weighted values.
vec3 GetSingleScatteringDifference(SingleScatteringSuns suns,
                                   vec3 single[SINGLE_SCATTERING_SUNS]) {
  vec3 lower = mix(single[1], single[2], suns.nu_weight);
  vec3 upper = mix(single[3], single[4], suns.nu_weight);
  return single[0] - mix(lower, upper, suns.mu_s_weight);
}

// The 4D Rayleigh table holds single scattering plus multiple scattering divided by P_R of the
// texel's nominal nu (accumulate_multiple_scattering.comp), and the caller multiplies the read by
// P_R(nu). For the multiple part that restores a linear blend of M / P_R, not of M: multiple
// scattering is nearly isotropic, so the read followed the curvature of 1 / P_R, 2% low at nu = 0
// between the slices at nu = -+1/7 (the horizon under a high sun) and 0.8% high at nu = 0.87.
// The multiple part at each node is the table's value there minus the node's marched single
// scattering, so the correction can blend it as it should be blended: times P_R of its slice's
// nominal nu, linearly in nu, divided by P_R(nu); minus the blend the read made.
//  - Found with a Rayleigh-only atmosphere over a black ground, order 2 alone (`aerial probe
//    --orders 2 --series-tail off` against `--reference`, checked by an independent quadrature):
//    on the ground under a sun at the zenith it read 2.9 / 2.5 / 2.1% low looking at the horizon
//    (nu = 0) and 1.5 / 1.1 / 1.0% low at view zenith 30 degrees; with this term 1.0 / 0.5 / 0.1%
//    and 2.3 / 1.9 / 1.8%, as the two slices' P_R predict.
//  - So the correction runs for every sun: with a high sun this term alone.
//  - The daylight sky 10 km up: at most 1.79% -> 1.09% off, median 0.82% -> 0.65%; on the ground
//    at most 0.81% -> 0.73%, medians 0.28% -> 0.24% (aerial_bench_sky --grid quick).
//
// In mu_s, for a low sun, the blend is exponential. With the sun near or below the horizon the
// sky's orders >= 2 come more and more from the sunlit air far above and away, and fall roughly
// exponentially as the sun goes down (as J_ms does, GetDensityBlended): looking 2 degrees above
// the horizon away from a sun at zenith 92 degrees, the reference's orders <= 2 fall by 1.75x
// between the two mu_s texels around it, and the linear blend read them 4% too bright midway
// (5-6% in all, 2-4% on the texels).
//  - Only between two texels whose upper one has the sun below MULTIPLE_SCATTERING_EXPONENTIAL_MU_S
//    (sun zenith 84.3 degrees). 0 (the horizon, as for J_ms), 0.1 and 0.2 were measured
//    (aerial_bench_sky --grid quick): 0.1 took the low-sun sky on the ground from 4.3% to 3.0% in
//    blue (looking away from a sun at zenith 90 degrees, between the texels at 89.4 and 90.3);
//    0.2 raised two low-sun medians by 0.05 point and nothing else.
// Between the same texels the blend is exponential in nu too: in the shadow the multiple scattering
// also falls roughly exponentially as the view turns away from the sun's azimuth. 10 km up, 2
// degrees below the horizon, across the sun's plane (azimuth 90) from a sun at zenith 95 degrees
// (nu = 0, midway between two slices), the linear blend read the sky 4.3 / 6.9 / 3.0% high, the
// exponential one 2.2 / 4.9 / 2.4% (16 nu slices, twice the memory: 0.7 / 2.6 / 1.2%); the twilight
// sky 10 and 50 km up 8.2% -> 6.2% and 9.0% -> 6.5% (aerial_bench_sky --grid quick).
const float MULTIPLE_SCATTERING_EXPONENTIAL_MU_S = 0.1;

// In daylight (the lower mu_s texel above DAYLIGHT_LINEAR_MU_S) the blend below is linear in mu_s,
// quadratic over three texels where the one below the two the read blends is in daylight too
// (IsDaylightBlend), and at each mu_s node linear in the nu that its two slices hold.
//  - mu_s: the arctangent axis has daylight texels only at sun zenith 0, 54.2 and 66.8 degrees, far
//    from linear in mu_s, and the light the ground sends back into the sky goes as mu_s T(mu_s).
//    Order 2's ground-reflected part (a Rayleigh-only atmosphere over a ground of albedo 0.3 minus
//    the same over a black one, `aerial probe --orders 2 --series-tail off`, against a numpy
//    quadrature of sun -> ground -> air -> camera that the reference matches to 0.35%) read 1-10%
//    high on the ground between those texels (7% in red at sun zenith 40 degrees) and 7-12% 10
//    and 40 km up; linearly in mu_s, as the irradiance is read
//    (GetMuSTextureCoordLinearInDaylight), 0.4-1.5% on the ground and 0.7-0.9% 10 km up.
//    The air's own multiple scattering is concave in mu_s between those texels: looking down from
//    10 km with the sun at zenith 45 degrees its orders >= 2 read 1-2.9% low linearly in mu_s, 0.7%
//    on the texels. Lagrange's quadratic through the two texels the read blends and the one below
//    them (InterpolateQuadratic; for a sun above 54.2 degrees, the texel at 66.8) follows that
//    curvature. aerial_bench_sky --grid quick, against the linear blend: the daylight sky 10 km up
//    at most 1.23% -> 0.67%, median 0.48% -> 0.23% (twice the mu_s texels, linearly: 0.62%, 0.28%,
//    for twice the memory); 50 km up at most 1.25% -> 0.67%; on the ground at most 0.66% -> 0.46%,
//    median 0.15% -> 0.30%. The third texel's single scattering is marched with the other nodes'
//    (7 suns instead of 5 in daylight).
//  - nu: a slice holds its value at its nominal nu clamped to what (mu, mu_s) allow, and the read
//    blends it as if it were at the nominal nu. Looking 5 degrees above the horizon 31 degrees
//    from a sun on a texel (zenith 54.2), nu = 0.86 is midway between the nominal 5/7 and 1, and
//    the second slice holds nu = 0.86 itself: order 2 over a black ground read 2.7 / 1.8 / 1.6%
//    low, and +1.0 / +0.4 / -0.0% blended at the nus the slices hold. Not for a low sun, whose
//    exponential blend in nu was measured with the nominal weights: there this put the low-sun
//    sky 50 km up at 3.27% instead of 2.72% off in green.
//  - These weights differ from the read's, so an error in the nodes' marched single scattering
//    no longer cancels: with 4 steps order 1 alone read up to 2.6% low in blue, with 16 within
//    0.1% (MULTIPLE_SCATTERING_BLEND_STEPS).
//  - aerial_bench_sky --grid quick: the daylight sky on the ground 0.90% -> 0.68% at most, median
//    0.34% -> 0.15%; 50 km up median 0.41% -> 0.30% (at most 1.01% -> 1.19%, in blue). 10 km up the
//    median went 0.23% -> 0.55%: the ground's excess had hidden a deficit of the atmosphere's own
//    multiple scattering there (order 2 over a black ground 2.8-3.0% low looking 30 degrees down
//    with the sun at zenith 45 degrees, 0.7% on the texels; see docs/accuracy.md).

// Whether the multiple scattering is blended in mu_s by the daylight rule (quadratic over three
// nodes, above) rather than the read's two: where all three nodes have the sun above
// DAYLIGHT_LINEAR_MU_S, in the smooth part of the curve. The quarter-resolution tables' 16 texels
// put the third node at sun zenith 80 degrees for every sun above 69.5: a quadratic through it
// took their afternoon sky 2.5% RMSE from the 3D tables' (BenchQuick's bound: 1%).
bool IsDaylightBlend(SingleScatteringSuns suns) {
  return suns.mu_s[5] >= DAYLIGHT_LINEAR_MU_S;
}

// Lagrange's quadratic through (x[a], y[a]), a = 0, 1, 2, at x.
vec3 InterpolateQuadratic(float x0, float x1, float x2, vec3 y0, vec3 y1, vec3 y2, float x) {
  return y0 * ((x - x1) * (x - x2) / ((x0 - x1) * (x0 - x2))) +
         y1 * ((x - x0) * (x - x2) / ((x1 - x0) * (x1 - x2))) +
         y2 * ((x - x0) * (x - x1) / ((x2 - x0) * (x2 - x1)));
}

// The nu weight at mu_s node a: linear between the nus its slices were clamped to.
float GetNodeNuWeight(SingleScatteringSuns suns, int a, float nu) {
  float nu0 = suns.nu[1 + 2 * a], nu1 = suns.nu[2 + 2 * a];
  if (!(nu1 - nu0 > 1e-4)) return suns.nu_weight;  // one nu at this node: any weight
  return clamp((nu - nu0) / (nu1 - nu0), 0.0, 1.0);
}

vec3 GetMultipleScatteringBlendCorrection(sampler3D rayleigh_texture, float r, float mu,
                                          float mu_s, float nu, SingleScatteringSuns suns,
                                          vec3 rayleigh_single[SINGLE_SCATTERING_SUNS]) {
  ivec4 size = AERIAL_ATMOSPHERE.scattering_size;
  vec4 uvwz = GetScatteringTextureUvwzFromRMuMuSNu(size, MU_AXIS_RAY_LENGTH, r, mu, mu_s, nu,
                                                   RayIntersectsGround(r, mu));
  float phase0 = RayleighPhaseFunction(GetNominalNuOfSlice(size, suns.nu_slice));
  float phase1 = RayleighPhaseFunction(GetNominalNuOfSlice(size, suns.nu_slice + 1.0));
  // Decided by the upper mu_s texel for both axes, also for a sun on a texel (mu_s weight 0), which
  // then reads as the limit from above.
  bool low_sun =
      IsMuSTexelBelow(suns.mu_s_texel + 1.0, float(size.z), MULTIPLE_SCATTERING_EXPONENTIAL_MU_S);
  bool daylight = IsDaylightBlend(suns);
  vec3 multiple[3];  // per mu_s node, blended in nu
  vec3 read[2];      // the same as the table's read blends it (divided by P_R of each slice)
  for (int a = 0; a < (daylight ? 3 : 2); ++a) {
    float texel = a < 2 ? suns.mu_s_texel + float(a) : suns.mu_s_texel - 1.0;
    uvwz.y = (texel + 0.5) / float(size.z);
    vec3 stored[2];
    for (int b = 0; b < 2; ++b) {
      stored[b] = GetScatteringBlendedExponentialInR(rayleigh_texture, size, false,
                                                     vec2(suns.nu_slice + float(b), 0.0), uvwz) -
                  rayleigh_single[1 + 2 * a + b];
    }
    float nu_weight = low_sun ? suns.nu_weight : GetNodeNuWeight(suns, a, nu);
    multiple[a] = low_sun ? MixExponentially(stored[0] * phase0, stored[1] * phase1, nu_weight)
                          : mix(stored[0] * phase0, stored[1] * phase1, nu_weight);
    if (a < 2) read[a] = mix(stored[0], stored[1], suns.nu_weight);
  }
  // Linear in mu_s where the lower node has the sun above DAYLIGHT_LINEAR_MU_S but the third not.
  float mu_s_weight = suns.mu_s[1] >= DAYLIGHT_LINEAR_MU_S
                          ? clamp((mu_s - suns.mu_s[1]) / (suns.mu_s[3] - suns.mu_s[1]), 0.0, 1.0)
                          : suns.mu_s_weight;
  vec3 blended;
  if (daylight) {
    blended = InterpolateQuadratic(suns.mu_s[1], suns.mu_s[3], suns.mu_s[5], multiple[0],
                                   multiple[1], multiple[2], clamp(mu_s, suns.mu_s[1], suns.mu_s[3]));
  } else {
    blended = low_sun ? MixExponentially(multiple[0], multiple[1], mu_s_weight)
                      : mix(multiple[0], multiple[1], mu_s_weight);
  }
  return blended / RayleighPhaseFunction(nu) - mix(read[0], read[1], suns.mu_s_weight);
}

// The correction to add to the tables' inscatter of the ray (r, mu) with the sun at (mu_s, nu),
// without phase: single scattering's where the sun is low, and multiple scattering's blend. Zero
// for the 3D tables.
void GetSkyInscatterCorrection(sampler2D transmittance_texture, sampler3D rayleigh_texture,
                               float r, float mu, float mu_s, float nu, out vec3 rayleigh,
                               out vec3 mie) {
  rayleigh = vec3(0.0);
  mie = vec3(0.0);
  SingleScatteringSuns suns;
  if (!GetSingleScatteringSuns(AERIAL_ATMOSPHERE.scattering_size, mu, mu_s, nu, suns)) return;
  bool low_sun = suns.mu_s[1] <= SINGLE_SCATTERING_CORRECTION_MU_S;
  vec3 rayleigh_single[SINGLE_SCATTERING_SUNS], mie_single[SINGLE_SCATTERING_SUNS];
  MarchSingleScatteringSuns(
      transmittance_texture, r, mu, suns, low_sun ? 0 : 1,
      IsDaylightBlend(suns) ? SINGLE_SCATTERING_SUNS : LOW_SUN_SUNS,
      low_sun ? SINGLE_SCATTERING_CORRECTION_STEPS : MULTIPLE_SCATTERING_BLEND_STEPS,
      rayleigh_single, mie_single);
  if (low_sun) {
    rayleigh = GetSingleScatteringDifference(suns, rayleigh_single);
    mie = GetSingleScatteringDifference(suns, mie_single);
  }
  rayleigh += GetMultipleScatteringBlendCorrection(rayleigh_texture, r, mu, mu_s, nu, suns,
                                                   rayleigh_single);
}

// Clamped (ClampToLight): in the Earth's shadow the table's value and the correction nearly cancel.
void AddSkyInscatterCorrection(vec3 rayleigh, vec3 mie, inout Inscatter sky) {
  sky.rayleigh = ClampToLight(sky.rayleigh + rayleigh);
  sky.mie = ClampToLight(sky.mie + mie);
}

// The Rayleigh and Mie inscatter (without phase) that the scattering tables hold for the view ray
// (r, mu) to the ground or the top of the atmosphere; ray_r_mu_intersects_ground picks the half of
// the mu axis read.
void GetTableInscatter(sampler3D rayleigh_texture, sampler3D mie_texture, sampler3D multiple_texture,
                       float r, float mu, float mu_s, float nu, bool ray_r_mu_intersects_ground,
                       out vec3 rayleigh, out vec3 mie) {
  rayleigh = GetRayleighScattering(rayleigh_texture, multiple_texture, r, mu, mu_s, nu,
                                   ray_r_mu_intersects_ground);
  mie = GetScatteringExponentialInR(mie_texture, AERIAL_ATMOSPHERE.scattering_size, r, mu, mu_s, nu,
                                    ray_r_mu_intersects_ground);
}

// S(x, v) as the scattering tables hold it: the Rayleigh and Mie inscatter (without phase) along
// the whole view ray (r, mu), to the ground or the top of the atmosphere, and its transmittance.
Inscatter GetSkyInscatterFromTables(sampler2D transmittance_texture, sampler3D rayleigh_texture,
                                    sampler3D mie_texture, sampler3D multiple_texture, float r,
                                    float mu, float mu_s, float nu) {
  bool ray_r_mu_intersects_ground = RayIntersectsGround(r, mu);
  Inscatter result;
  GetTableInscatter(rayleigh_texture, mie_texture, multiple_texture, r, mu, mu_s, nu,
                    ray_r_mu_intersects_ground, result.rayleigh, result.mie);
  result.transmittance =
      ray_r_mu_intersects_ground
          ? GetTransmittance(transmittance_texture, r, mu,
                             DistanceToBottomAtmosphereBoundary(r, mu), true)
          : GetTransmittanceToTopAtmosphereBoundary(transmittance_texture, r, mu);
  return result;
}

// S(x, v), its single scattering corrected where the Earth's shadow crosses the ray.
Inscatter GetSkyInscatter(sampler2D transmittance_texture, sampler3D rayleigh_texture,
                          sampler3D mie_texture, sampler3D multiple_texture, float r, float mu,
                          float mu_s, float nu) {
  Inscatter sky = GetSkyInscatterFromTables(transmittance_texture, rayleigh_texture, mie_texture,
                                            multiple_texture, r, mu, mu_s, nu);
  vec3 rayleigh, mie;
  GetSkyInscatterCorrection(transmittance_texture, rayleigh_texture, r, mu, mu_s, nu, rayleigh,
                            mie);
  AddSkyInscatterCorrection(rayleigh, mie, sky);
  return sky;
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

// Inscatter over the first d meters of the view ray (r, mu) as the difference of two table reads,
// S(x, v) - T(x, p) S(p, v) (Bruneton 2008 eq. 16; Bruneton 2017 GetSkyRadianceToPoint, without
// its fix near the horizon): how Bruneton 2017's demo renders the aerial perspective, two 4D reads
// per pixel and no march. It cancels where the segment holds a small part of the whole ray's
// inscatter (GetSkyInscatterToPoint above), and the Earth's shadow is not corrected; aerial keeps
// it to compare with (AerialMode::kTableDifference). Both reads take the camera's
// ray_r_mu_intersects_ground, so that they read the same half of the mu axis.
Inscatter GetSkyInscatterToPointFromTables(sampler2D transmittance_texture,
                                           sampler3D rayleigh_texture, sampler3D mie_texture,
                                           sampler3D multiple_texture, float r, float mu,
                                           float mu_s, float nu, float d) {
  bool ray_r_mu_intersects_ground = RayIntersectsGround(r, mu);
  d = min(d, DistanceToNearestAtmosphereBoundary(r, mu, ray_r_mu_intersects_ground));
  float r_p = RadiusAtDistance(r, mu, d);
  float mu_p = MuAtDistance(r, mu, d, r_p);
  float mu_s_p = SunCosineAlongRay(r, mu_s, nu, d, r_p);
  vec3 rayleigh, mie, rayleigh_p, mie_p;
  GetTableInscatter(rayleigh_texture, mie_texture, multiple_texture, r, mu, mu_s, nu,
                    ray_r_mu_intersects_ground, rayleigh, mie);
  GetTableInscatter(rayleigh_texture, mie_texture, multiple_texture, r_p, mu_p, mu_s_p, nu,
                    ray_r_mu_intersects_ground, rayleigh_p, mie_p);
  Inscatter segment;
  segment.transmittance = GetTransmittance(transmittance_texture, r, mu, d, ray_r_mu_intersects_ground);
  segment.rayleigh = ClampToLight(rayleigh - segment.transmittance * rayleigh_p);
  segment.mie = ClampToLight(mie - segment.transmittance * mie_p);
  return segment;
}

vec3 ApplyPhaseFunctions(Inscatter inscatter, float nu) {
  return inscatter.rayleigh * RayleighPhaseFunction(nu) +
         inscatter.mie * MiePhaseFunction(AERIAL_ATMOSPHERE.mie_phase_g, nu);
}

// Radiance of the sun disc at the top of the atmosphere: irradiance over the disc's solid angle.
vec3 GetSolarRadiance() {
  return AERIAL_ATMOSPHERE.solar_irradiance.rgb /
         (PI * AERIAL_ATMOSPHERE.sun_angular_radius * AERIAL_ATMOSPHERE.sun_angular_radius);
}

#endif
