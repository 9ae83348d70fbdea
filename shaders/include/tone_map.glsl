// Linear radiance to display values, for the viewer. Mirrors src/aerial/image/tone_map.cpp
// (ToneMapChannel) line by line, so the window shows what a PNG of the same frame holds; the test
// tests/viewer_present_test.cpp holds the two within 1e-3 on a ramp.
#ifndef AERIAL_TONE_MAP_GLSL
#define AERIAL_TONE_MAP_GLSL

// Krzysztof Narkowicz, "ACES Filmic Tone Mapping Curve" (2015): x (a x + b) / (x (c x + d) + e),
// strictly increasing on x >= 0, tending to a / c > 1, hence the clamp.
vec3 AcesFilmic(vec3 x) {
  const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
  return clamp(x * (a * x + b) / (x * (c * x + d) + e), 0.0, 1.0);
}

// sRGB opto-electronic transfer function (IEC 61966-2-1): linear toe below 0.0031308, then a
// 1/2.4 power law.
vec3 SrgbOetf(vec3 linear) {
  vec3 toe = 12.92 * linear;
  vec3 power = 1.055 * pow(max(linear, vec3(0.0031308)), vec3(1.0 / 2.4)) - 0.055;
  return mix(power, toe, lessThanEqual(linear, vec3(0.0031308)));
}

// Negative and NaN radiance show as black; the curve is already 1 from x ~ 7.24, so the cap at
// 1e4 changes nothing but keeps +inf from turning into inf / inf = NaN.
vec3 SanitizeRadiance(vec3 x) {
  bvec3 positive = greaterThan(x, vec3(0.0));  // false for NaN
  return mix(vec3(0.0), min(x, vec3(1e4)), positive);
}

// Radiance times exposure to linear display values in [0, 1], before the sRGB encoding.
vec3 ToneMapLinear(vec3 exposed_radiance) { return AcesFilmic(SanitizeRadiance(exposed_radiance)); }

// Radiance times exposure to sRGB-encoded values in [0, 1] (ToneMapChannel in tone_map.cpp).
vec3 ToneMap(vec3 exposed_radiance) { return SrgbOetf(ToneMapLinear(exposed_radiance)); }

#endif
