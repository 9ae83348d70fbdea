// Texture coordinate mappings of the precomputed tables (Bruneton 2017, functions.glsl sections
// "Precomputation" of each table). Every mapping comes as a pair, table coordinate from physical
// parameters and back, and every coordinate lands on texel centers so that no lookup reads past the
// domain.
//
// The horizon. The scattering table's mu axis is split in two halves: u_mu < 0.5 holds rays that
// hit the ground and u_mu > 0.5 rays that reach the top of the atmosphere. Both halves place the
// horizon at their outer texel centers (u -> 0 and u -> 1) and the zenith/nadir in the middle, so a
// bilinear fetch never blends a ground ray with a sky ray: that blending is what draws the bright or
// dark line at the horizon in ports that map mu linearly. The caller passes the ground flag
// explicitly (RayIntersectsGround of the camera ray) and uses the same flag for every lookup along
// one ray, so the two ends of an aerial-perspective segment can never fall in different halves.
// In the radiance tables the mapping is in terms of the distance to the boundary, which varies
// smoothly near the horizon, instead of mu, whose derivative diverges; the scattering density
// tables map the view zenith angle (MU_AXIS_VIEW_ZENITH below).
#ifndef AERIAL_MAPPINGS_GLSL
#define AERIAL_MAPPINGS_GLSL
#include "geometry.glsl"

// x in [0,1] -> texel-center coordinate of a table of `size` texels, and back.
float GetTextureCoordFromUnitRange(float x, int size) {
  return 0.5 / float(size) + x * (1.0 - 1.0 / float(size));
}
float GetUnitRangeFromTextureCoord(float u, int size) {
  return (u - 0.5 / float(size)) / (1.0 - 1.0 / float(size));
}

// The two texels that a linear read at texture coordinate u blends on an axis of `size` texels:
// (x) the lower one's index, (y) the upper one's weight. For reads that blend them otherwise
// (exponentially) and fetch each at its centre, (index + 0.5) / size.
vec2 GetTexelBlend(float u, float size) {
  float texel = clamp(u * size - 0.5, 0.0, size - 1.0);
  float lower = min(floor(texel), size - 2.0);
  return vec2(lower, texel - lower);
}

// H: distance to the top boundary of a horizontal ray from the ground.
float HorizonDistanceFromGround() {
  return sqrt(SquaredHorizonDistance(AERIAL_ATMOSPHERE.top_radius));
}

// ---- Transmittance table: x = d/d_max mapping of mu, y = rho/H mapping of r. ----
// Its r axis, rho/H in [0, 1] (rho the distance to the horizon, H its value at the top); the
// scattering and irradiance tables warp it (GetUnitRangeFromR below).
float GetTransmittanceUnitRangeFromR(float r) {
  return sqrt(SquaredHorizonDistance(r)) / HorizonDistanceFromGround();
}
float GetRFromTransmittanceUnitRange(float x_r) {
  float rho = HorizonDistanceFromGround() * x_r;
  return sqrt(rho * rho + AERIAL_ATMOSPHERE.bottom_radius * AERIAL_ATMOSPHERE.bottom_radius);
}

vec2 GetTransmittanceTextureUvFromRMu(float r, float mu) {
  float H = HorizonDistanceFromGround();
  float rho = sqrt(SquaredHorizonDistance(r));
  float d = DistanceToTopAtmosphereBoundary(r, mu);
  float d_min = AERIAL_ATMOSPHERE.top_radius - r;
  float d_max = rho + H;
  float x_mu = (d - d_min) / (d_max - d_min);
  return vec2(GetTextureCoordFromUnitRange(x_mu, AERIAL_ATMOSPHERE.transmittance_size.x),
              GetTextureCoordFromUnitRange(GetTransmittanceUnitRangeFromR(r),
                                           AERIAL_ATMOSPHERE.transmittance_size.y));
}

void GetRMuFromTransmittanceTextureUv(vec2 uv, out float r, out float mu) {
  float x_mu = GetUnitRangeFromTextureCoord(uv.x, AERIAL_ATMOSPHERE.transmittance_size.x);
  float x_r = GetUnitRangeFromTextureCoord(uv.y, AERIAL_ATMOSPHERE.transmittance_size.y);
  float H = HorizonDistanceFromGround();
  float rho = H * x_r;
  r = GetRFromTransmittanceUnitRange(x_r);
  float d_min = AERIAL_ATMOSPHERE.top_radius - r;
  float d_max = rho + H;
  float d = d_min + x_mu * (d_max - d_min);
  // H^2 - rho^2 = R_top^2 - r^2, taken without cancellation.
  mu = d == 0.0 ? 1.0 : (SquaredTopBoundaryFromRadius(r) - d * d) / (2.0 * r * d);
  mu = ClampCosine(mu);
}

// ---- The sun's zenith cosine on the scattering and irradiance tables' mu_s axes. ----
// The Earth's shadow moves through the atmosphere as the sun goes down: from sun zenith 85 to
// 108 degrees the sky changes by orders of magnitude per few degrees, while from 0 to 60 it
// hardly changes. The axis follows Yusov 2013's arctangent mapping of mu_s (his centres it on
// the horizon for mu_s >= -0.2), here centred on MU_S_DENSEST (sun zenith 95.7 degrees) with a
// width 1 / MU_S_SPREAD, over [mu_s_min, 1]. Of the default 38 texels it gives 1.4 to sun zeniths
// 0-60, 5.8 to 60-85, 11.5 to 85-95, 14.7 to 95-108 and 3.6 to 108-120, where Bruneton 2017's
// distance mapping (which the tables used before) gave 2.8, 11.8, 13.3, 7.7 and 2.4. Centres -0.05
// to -0.15 and widths 1/6 to 1/8 were measured (aerial_bench_sky): -0.1 and 1/8 had the smallest
// low-sun errors at first. Once the low sun's reads were corrected (GetSkyInscatterCorrection,
// step spacing, order 2's density blend), 1/7 moved texels from the Earth's shadow to the
// afternoon and took the daylight radiance to a point on the ground from 1.10% to 0.89%, the
// low-sun sky irradiance on the ground from 2.4% to 2.2% and the twilight sky there from 8.2% to
// 7.9%; 1/6 took the low-sun irradiance on the ground to 4.5%.
const float MU_S_DENSEST = -0.1;
const float MU_S_SPREAD = 7.0;

float GetUnitRangeFromMuS(float mu_s) {
  float low = atan(MU_S_SPREAD * (AERIAL_ATMOSPHERE.mu_s_min - MU_S_DENSEST));
  float high = atan(MU_S_SPREAD * (1.0 - MU_S_DENSEST));
  return clamp((atan(MU_S_SPREAD * (mu_s - MU_S_DENSEST)) - low) / (high - low), 0.0, 1.0);
}

float GetMuSFromUnitRange(float x) {
  float low = atan(MU_S_SPREAD * (AERIAL_ATMOSPHERE.mu_s_min - MU_S_DENSEST));
  float high = atan(MU_S_SPREAD * (1.0 - MU_S_DENSEST));
  return ClampCosine(MU_S_DENSEST + tan(low + x * (high - low)) / MU_S_SPREAD);
}

// ---- The r axis of the scattering and irradiance tables. ----
// Bruneton 2017's x = rho / H, warped by W(x) = x - R_WARP x^2 (1 - x). rho / H
// alone is dense near the ground (texels at 0, 0.06, 0.25, 0.56 km) but 3.4-3.8 km apart above
// 45 km, where single scattering toward the zenith falls to zero at the top of the atmosphere and
// is concave in x: looking up from 50 / 55 km with the sun overhead it read 1.5 / 5.4% low, and
// 0.4% with 64 r texels. W keeps the slope 1 at the ground (texels at 0, 0.06, 0.27, 0.62 km)
// and has slope 1 + R_WARP at the top: 2.6 km apart there, and 1.9 km instead of 1.5 km apart
// around 10 km, where the slope is least (1 - R_WARP / 3). R_WARP 0.35, 0.5, 0.75 and 1 were
// measured (aerial_bench_sky --grid quick). 0.75 took the daylight sky 50 km up from 1.54% to
// 1.42% at most and its median from 0.41% to 0.34%; since the sky's multiple scattering is blended
// linearly in mu_s in daylight (GetMultipleScatteringBlendCorrection), 50 km up needs less and
// 10 km up more: 0.5 instead of 0.75 takes the daylight sky 10 km up from a median of 0.55% to
// 0.45% (its single scattering looking 30 degrees down read 0.26-0.37% low between r texels 2.1
// km apart; 0.04-0.17% with 64 texels), the low-sun sky 10 km up 0.41% -> 0.20%, and the daylight
// sky 50 km up stays at 0.31% (0.35 put it at 0.50%); the low-sun radiance to a point 10 km up
// goes 2.06% -> 2.78% at most.
const float R_WARP = 0.5;

float WarpR(float x) {
  return x - R_WARP * x * x * (1.0 - x);
}

float GetUnitRangeFromR(float r) { return WarpR(GetTransmittanceUnitRangeFromR(r)); }

float GetRFromUnitRange(float u) {
  // W' lies in [1 - R_WARP / 3, 1 + R_WARP]: Newton's method from x = u converges in a few steps.
  float x = u;
  for (int i = 0; i < 6; ++i) {
    x -= (WarpR(x) - u) / (1.0 - R_WARP * (2.0 * x - 3.0 * x * x));
  }
  return GetRFromTransmittanceUnitRange(x);
}

// ---- Irradiance table: the mu_s axis above, the warped rho/H (above) in r. ----
// In daylight the sky irradiance is nearly linear in mu_s (the sunlight reaching the ground, and so
// the light it reflects into the sky, goes as mu_s T(mu_s) with T close to 1), while the
// arctangent axis puts its daylight texels far apart (of the irradiance table's 64, at sun zeniths
// 0, 43.6 and 56.1 degrees): blending linearly in the axis coordinate, a sun at 30 degrees got 58%
// of the zenith texel instead of 51%. Measured (aerial_bench_sky), the daylight irradiance on the
// ground read 0.65 / 0.50 / 0.26% high at median (red / green / blue) and 0.49 / 0.39 / 0.07% with
// this read. Between texels whose lower sun is above DAYLIGHT_LINEAR_MU_S the blend is therefore
// linear in mu_s; below it, where the Earth's shadow makes the irradiance anything but linear, it
// stays linear in the axis coordinate. The sky's multiple scattering is read the same way: the 3D
// table directly, the 4D one through its blend correction (GetMultipleScatteringBlendCorrection),
// which goes on to a quadratic in mu_s where three daylight texels allow it.
const float DAYLIGHT_LINEAR_MU_S = 0.26;  // sun zenith 75 degrees

// The texture coordinate of mu_s on an arctangent axis of `texels` texels, linear in mu_s between
// two daylight texels.
float GetMuSTextureCoordLinearInDaylight(float mu_s, int texels) {
  float u = GetTextureCoordFromUnitRange(GetUnitRangeFromMuS(mu_s), texels);
  vec2 blend = GetTexelBlend(u, float(texels));
  float last = float(texels - 1);
  float mu_s_lower = GetMuSFromUnitRange(blend.x / last);
  if (mu_s_lower < DAYLIGHT_LINEAR_MU_S) return u;
  float mu_s_upper = GetMuSFromUnitRange((blend.x + 1.0) / last);
  float weight = clamp((mu_s - mu_s_lower) / (mu_s_upper - mu_s_lower), 0.0, 1.0);
  return (blend.x + weight + 0.5) / float(texels);
}

// Bruneton 2017 maps r linearly; the sky irradiance changes fastest near the ground (Mie's 1.2 km
// scale height), where a linear axis of 16 texels puts 4 km between the first two: interpolated at
// 1 km the red irradiance was 7% high. rho = sqrt(r^2 - R^2), as on the scattering tables, puts
// texels at 0, 0.27, 1.1, 2.4 km... for the same cost. Warped as the scattering tables' r axis:
// unwarped, the order-1 irradiance 50 km up read 1.1% low in every channel between its rows 3.5 km
// apart (and exact with 64 rows).
vec2 GetIrradianceTextureUvFromRMuS(float r, float mu_s) {
  float x_r = GetUnitRangeFromR(r);
  return vec2(GetMuSTextureCoordLinearInDaylight(mu_s, AERIAL_ATMOSPHERE.irradiance_size.x),
              GetTextureCoordFromUnitRange(x_r, AERIAL_ATMOSPHERE.irradiance_size.y));
}

void GetRMuSFromIrradianceTextureUv(vec2 uv, out float r, out float mu_s) {
  float x_mu_s = GetUnitRangeFromTextureCoord(uv.x, AERIAL_ATMOSPHERE.irradiance_size.x);
  r = GetRFromUnitRange(GetUnitRangeFromTextureCoord(uv.y, AERIAL_ATMOSPHERE.irradiance_size.y));
  mu_s = GetMuSFromUnitRange(x_mu_s);
}

// ---- Scattering tables: (u_nu, u_mu_s, u_mu, u_r) in [0,1]^4. ----
// `size` is (r, mu, mu_s, nu): atmosphere.scattering_size for the final tables,
// atmosphere.density_size for the scattering density and multiple scattering of one order.
float GetScatteringUMuS(ivec4 size, float mu_s) {
  return GetTextureCoordFromUnitRange(GetUnitRangeFromMuS(mu_s), size.z);
}

float GetMuSFromScatteringUMuS(ivec4 size, float u_mu_s) {
  return GetMuSFromUnitRange(GetUnitRangeFromTextureCoord(u_mu_s, size.z));
}

// Whether mu_s texel `texel` of a table with mu_s_size texels holds a sun lower than mu_s:
// texel / (mu_s_size - 1) < x(mu_s), so no tan per call with a constant mu_s.
bool IsMuSTexelBelow(float texel, float mu_s_size, float mu_s) {
  return texel < GetUnitRangeFromMuS(mu_s) * (mu_s_size - 1.0);
}

float GetScatteringUR(ivec4 size, float r) {
  return GetTextureCoordFromUnitRange(GetUnitRangeFromR(r), size.x);
}

float GetRFromScatteringUR(ivec4 size, float u_r) {
  return GetRFromUnitRange(GetUnitRangeFromTextureCoord(u_r, size.x));
}

// The mu axis, two ways. Both split it at the horizon into two halves, x = 0 at the zenith (sky
// half) or the nadir (ground half) and x = 1 at the horizon.
//  - MU_AXIS_RAY_LENGTH (the radiance tables: single and multiple scattering): the distance to the
//    boundary the ray meets, Bruneton 2017's mapping. These tables hold integrals along the ray,
//    which change fastest with its length near the horizon.
//  - MU_AXIS_VIEW_ZENITH (the scattering density tables: J_n of each order, and J_ms): the view
//    zenith angle, uniform within each half. A density is the light scattered at one point toward
//    the view direction, a convolution of the incident radiance with the phase functions, so it
//    is smooth in that direction however long the ray beyond it. On the distance mapping, 32
//    texels per half put one cell between the nadir and a view zenith of 118 degrees 10 km up
//    (109 degrees 3 km up), and every downward texel of the ground slice at the nadir. Looking
//    down from 3 km (view zenith 120, sun at the zenith, Rayleigh only, ground albedo 0), the
//    order-2 density was 8.5 / 7.1 / 5.3% low that way, 2.8 / 2.2 / 1.8% on this axis (`aerial
//    probe --orders 2 --series-tail off --distance-m 10` against `--reference`). These tables'
//    fourth axis is the view-sun azimuth (GetUnitRangeFromViewSunAzimuth), not nu.
const int MU_AXIS_RAY_LENGTH = 0;
const int MU_AXIS_VIEW_ZENITH = 1;

float GetUnitRangeFromMuInHalf(int mu_axis, float r, float mu, bool ray_r_mu_intersects_ground) {
  if (mu_axis == MU_AXIS_VIEW_ZENITH) {
    float theta_h = HorizonZenithAngle(r);
    float theta = acos(ClampCosine(mu));
    return clamp(ray_r_mu_intersects_ground ? (PI - theta) / (PI - theta_h) : theta / theta_h,
                 0.0, 1.0);
  }
  float rho = sqrt(SquaredHorizonDistance(r));
  if (ray_r_mu_intersects_ground) {
    // Distance to the ground, from r - R (nadir) to rho (horizon).
    float d = -r * mu - SafeSqrt(GroundDiscriminant(r, mu));
    float d_min = r - AERIAL_ATMOSPHERE.bottom_radius;
    float d_max = rho;
    return d_max == d_min ? 0.0 : (d - d_min) / (d_max - d_min);
  }
  // Distance to the top boundary, from R_top - r (zenith) to rho + H (horizon).
  float d = DistanceToTopAtmosphereBoundary(r, mu);
  float d_min = AERIAL_ATMOSPHERE.top_radius - r;
  float d_max = rho + HorizonDistanceFromGround();
  return (d - d_min) / (d_max - d_min);
}

float GetMuFromUnitRangeInHalf(int mu_axis, float r, float x, bool ray_r_mu_intersects_ground) {
  if (mu_axis == MU_AXIS_VIEW_ZENITH) {
    float theta_h = HorizonZenithAngle(r);
    return cos(ray_r_mu_intersects_ground ? PI - x * (PI - theta_h) : x * theta_h);
  }
  float rho = sqrt(SquaredHorizonDistance(r));
  if (ray_r_mu_intersects_ground) {
    float d_min = r - AERIAL_ATMOSPHERE.bottom_radius;
    float d = d_min + (rho - d_min) * x;
    return d == 0.0 ? -1.0 : ClampCosine(-(rho * rho + d * d) / (2.0 * r * d));
  }
  float d_min = AERIAL_ATMOSPHERE.top_radius - r;
  float d = d_min + (rho + HorizonDistanceFromGround() - d_min) * x;
  return d == 0.0 ? 1.0 : ClampCosine((SquaredTopBoundaryFromRadius(r) - d * d) / (2.0 * r * d));
}

// The nu axis: unit range u in [0, 1] <-> nu in [-1, 1], uniform as in Bruneton 2017. With an
// odd number of slices one lies on nu = 0, 90 degrees in azimuth from a sun on the horizon, where
// the Earth's shadow on the air changes fastest and the worst low-sun sky samples sit (10 km up, 2
// degrees down, sun at 95 degrees): between two slices the read blends a shadow edge linearly. So
// the default has 9 slices (table_options.h). A warp nu = sign(x) |x|^p (x = 2u - 1, p > 1) also
// brings the slices nearer nu = 0 for an even count, but spreads them where the daylight radiance
// to a point looks toward the sun: with 12 slices, p = 1.4 took the low-sun sky 10 km up from
// 3.03% to 2.95% and that radiance on the ground from 0.80% to 0.91%; 11 uniform slices reach
// 2.11% and keep 0.80% (aerial_bench_sky --grid quick).
float GetUnitRangeFromNu(float nu) { return 0.5 * nu + 0.5; }

float GetNuFromUnitRange(float u) { return 2.0 * u - 1.0; }

// The density tables' fourth axis (J_n of each order, J_ms): the cosine of the azimuth phi between
// the view and the sun, uniform over [-1, 1] and reversed (u = 0 at phi = 0), i.e. nu rescaled to
// the range [mu mu_s - s, mu mu_s + s] (s = sin theta sin theta_s) that (mu, mu_s) allow. On the nu
// axis a texel outside that range holds the value at the clamped nu, and the range closes on
// nu = mu as the sun nears the zenith: a sun at 45 degrees and a view 2 degrees up toward it
// (nu = 0.73) were blended with the zenith texel, which held the density at nu = 0.035 in every
// slice, and order 2's density from the air read 8.5 / 6.4 / 4.9% low there (`aerial probe
// --orders 2 --series-tail off` against `--reference`). Every (mu, mu_s, phi) is a geometry, and
// at fixed phi the density goes continuously to its zenith value as the sun rises. Measured
// (aerial_bench_sky --grid quick): the daylight radiance to a point on the ground 1.02% -> 0.68%
// at most; the low-sun sky 10 km up 2.52% -> 2.35%. Uniform in phi itself did as well in daylight
// but read the low-sun sky 10 km up at 2.61%, and costs an acos per read.
// Half the width of the nu range that (mu, mu_s) allow: sin theta sin theta_s.
float GetNuSpread(float mu, float mu_s) {
  return sqrt(max((1.0 - mu * mu) * (1.0 - mu_s * mu_s), 0.0));
}

float GetUnitRangeFromViewSunAzimuth(float mu, float mu_s, float nu) {
  float spread = GetNuSpread(mu, mu_s);
  return spread > 0.0 ? 0.5 - 0.5 * clamp((nu - mu * mu_s) / spread, -1.0, 1.0) : 0.5;
}

float GetNuFromViewSunAzimuthUnitRange(float mu, float mu_s, float u) {
  float spread = GetNuSpread(mu, mu_s);
  return ClampCosine(mu * mu_s + spread * (1.0 - 2.0 * u));
}

vec4 GetScatteringTextureUvwzFromRMuMuSNu(ivec4 size, int mu_axis, float r, float mu, float mu_s,
                                          float nu, bool ray_r_mu_intersects_ground) {
  int half_mu = size.y / 2;
  float u_half = GetTextureCoordFromUnitRange(
      GetUnitRangeFromMuInHalf(mu_axis, r, mu, ray_r_mu_intersects_ground), half_mu);
  float u_mu = ray_r_mu_intersects_ground ? 0.5 - 0.5 * u_half : 0.5 + 0.5 * u_half;
  float u_nu = mu_axis == MU_AXIS_VIEW_ZENITH ? GetUnitRangeFromViewSunAzimuth(mu, mu_s, nu)
                                             : GetUnitRangeFromNu(nu);
  return vec4(u_nu, GetScatteringUMuS(size, mu_s), u_mu, GetScatteringUR(size, r));
}

void GetRMuMuSNuFromScatteringTextureUvwz(ivec4 size, int mu_axis, vec4 uvwz, out float r,
                                          out float mu, out float mu_s, out float nu,
                                          out bool ray_r_mu_intersects_ground) {
  r = GetRFromScatteringUR(size, uvwz.w);
  int half_mu = size.y / 2;
  ray_r_mu_intersects_ground = uvwz.z < 0.5;
  float u_half = ray_r_mu_intersects_ground ? 1.0 - 2.0 * uvwz.z : 2.0 * uvwz.z - 1.0;
  mu = GetMuFromUnitRangeInHalf(mu_axis, r, GetUnitRangeFromTextureCoord(u_half, half_mu),
                                ray_r_mu_intersects_ground);
  mu_s = GetMuSFromScatteringUMuS(size, uvwz.y);
  nu = mu_axis == MU_AXIS_VIEW_ZENITH ? GetNuFromViewSunAzimuthUnitRange(mu, mu_s, uvwz.x)
                                      : ClampCosine(GetNuFromUnitRange(uvwz.x));
}

bool IsScatteringTexel(ivec4 size, ivec3 texel) {
  return texel.x < size.z * size.w && texel.y < size.y && texel.z < size.x;
}

// The nu that nu slice `slice` stands for on the table's nu axis (which spans [-1, 1] with its end
// points), before clamping to what (mu, mu_s) allow.
float GetNominalNuOfSlice(ivec4 size, float slice) {
  return GetNuFromUnitRange(slice / float(size.w - 1));
}

// The same for a texel of the packed 3D image.
float GetScatteringTexelNominalNu(ivec4 size, ivec3 texel) {
  return size.w > 1 ? GetNominalNuOfSlice(size, float(texel.x / size.z)) : 0.0;
}

// The texel (x, y, z) of the 3D image that packs the 4D table: x = nu_index * MU_S + mu_s_index.
// The fourth axis's samples span it exactly (nu_size texels, end points included); the other axes
// use texel centers. On the radiance tables' nu axis, nu is then clamped to the values that
// (mu, mu_s) allow.
void GetRMuMuSNuFromScatteringTexel(ivec4 size, int mu_axis, ivec3 texel, out float r,
                                    out float mu, out float mu_s, out float nu,
                                    out bool ray_r_mu_intersects_ground) {
  int mu_s_size = size.z;
  int nu_size = size.w;
  float nu_index = float(texel.x / mu_s_size);
  float mu_s_index = float(texel.x % mu_s_size);
  vec4 uvwz = vec4(nu_size > 1 ? nu_index / float(nu_size - 1) : 0.5,
                   (mu_s_index + 0.5) / float(mu_s_size),
                   (float(texel.y) + 0.5) / float(size.y), (float(texel.z) + 0.5) / float(size.x));
  GetRMuMuSNuFromScatteringTextureUvwz(size, mu_axis, uvwz, r, mu, mu_s, nu,
                                       ray_r_mu_intersects_ground);
  // A 3D table has no nu: its texels stand for every azimuth; mu mu_s is the azimuthal mean. The
  // density tables' azimuth axis only holds allowed nus.
  if (nu_size == 1) {
    nu = mu * mu_s;
  } else if (mu_axis == MU_AXIS_RAY_LENGTH) {
    float spread = GetNuSpread(mu, mu_s);
    nu = clamp(nu, mu * mu_s - spread, mu * mu_s + spread);
  }
}

#endif
