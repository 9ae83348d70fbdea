// Linear radiance to display values, for the viewer. Mirrors src/aerial/image/tone_map.cpp
// (DisplayCurve, ToneMapColour, DitherSteps) line by line, so the window shows what a PNG of the
// same frame holds; the test tests/viewer_present_test.cpp holds the two within 1e-3 on a ramp.
#ifndef AERIAL_TONE_MAP_GLSL
#define AERIAL_TONE_MAP_GLSL

// Khronos PBR Neutral (2024): a toe, the identity up to 0.76, then the brightest channel
// compressed toward 1 with the colour scaled with it and mixed toward white as far as it is
// compressed, so that hues are kept.
const float kStartCompression = 0.8 - 0.04;
const float kDesaturation = 0.15;

// The curve's shoulder alone.
vec3 NeutralShoulder(vec3 color) {
  float peak = max(color.r, max(color.g, color.b));
  if (peak < kStartCompression) return color;
  const float d = 1.0 - kStartCompression;
  float new_peak = 1.0 - d * d / (peak + d - kStartCompression);
  float g = 1.0 - 1.0 / (kDesaturation * (peak - new_peak) + 1.0);
  return mix(color * (new_peak / peak), vec3(new_peak), g);
}

vec3 PbrNeutral(vec3 color) {
  float x = min(color.r, min(color.g, color.b));
  float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  return NeutralShoulder(color - offset);
}

// sRGB opto-electronic transfer function (IEC 61966-2-1): linear toe below 0.0031308, then a
// 1/2.4 power law.
vec3 SrgbOetf(vec3 linear) {
  vec3 toe = 12.92 * linear;
  vec3 power = 1.055 * pow(max(linear, vec3(0.0031308)), vec3(1.0 / 2.4)) - 0.055;
  return mix(power, toe, lessThanEqual(linear, vec3(0.0031308)));
}

// Negative and NaN radiance show as black; the cap at 1e4 changes nothing but keeps +inf from
// turning into inf / inf = NaN.
vec3 SanitizeRadiance(vec3 x) {
  bvec3 positive = greaterThan(x, vec3(0.0));  // false for NaN
  return mix(vec3(0.0), min(x, vec3(1e4)), positive);
}

// Radiance times white balance and exposure to linear display values in [0, 1], before the sRGB
// encoding (DisplayCurve in tone_map.cpp).
vec3 ToneMapLinear(vec3 exposed_radiance) {
  return clamp(PbrNeutral(SanitizeRadiance(exposed_radiance)), 0.0, 1.0);
}

// The debug views of one term (inscatter.frag, froxel_slice.frag): the shoulder without the toe,
// which takes a dim colour's darkest channel to about 0 and so would hide the term's own colour.
vec3 ToneMapLinearWithoutToe(vec3 exposed_radiance) {
  return clamp(NeutralShoulder(SanitizeRadiance(exposed_radiance)), 0.0, 1.0);
}

// Radiance times exposure to sRGB-encoded values in [0, 1] (ToneMapColour in tone_map.cpp).
vec3 ToneMap(vec3 exposed_radiance) { return SrgbOetf(ToneMapLinear(exposed_radiance)); }

// Chris Wellons' "lowbias32" integer hash (Hash in src/aerial/scene/noise.cpp).
uint DitherHash(uint v) {
  v ^= v >> 16;
  v *= 0x7feb352du;
  v ^= v >> 15;
  v *= 0x846ca68bu;
  v ^= v >> 16;
  return v;
}

// Triangular noise over (-1, 1) 8-bit steps for the pixel (DitherSteps in tone_map.cpp).
float DitherSteps(uvec2 pixel) {
  uint a = DitherHash(pixel.x + DitherHash(pixel.y));
  uint b = DitherHash(a);
  return float(a >> 8) / 16777216.0 - float(b >> 8) / 16777216.0;
}

#endif
