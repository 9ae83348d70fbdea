// Shared definitions of every aerial shader: constants, the atmosphere uniform block and the small
// numerical guards that keep rounding from producing NaNs (Bruneton 2017, definitions.glsl and
// functions.glsl "ClampCosine", "SafeSqrt"). Lengths are in meters, coefficients in m^-1.
#ifndef AERIAL_DEFINITIONS_GLSL
#define AERIAL_DEFINITIONS_GLSL

const float PI = 3.14159265358979323846;

// Control flow that a CPU rasterizer pays for. lavapipe's shader compiler (gallivm, Mesa 22.3)
// runs a SIMD group of invocations in lockstep under a lane mask and does not jump over a branch
// that no lane takes: both sides of every if run, reads included (an early return too). A loop
// does end once every lane has left it. In the functions the frame calls per pixel, per vertex or
// per march step, therefore:
//  - a branch picks where to read, not whether to read: `read(a ? x : y)`, not
//    `if (a) return read(x); return read(y);`, which costs two reads;
//  - work that only some cases need sits in a loop over the case's count (GetSunDiscSunlight's taps),
//    not behind an if with the common case's early return before it: a group whose lanes all
//    take the common case then pays for its one pass (and the loop's last test), not for all;
//  - where a whole frame takes one case, a pipeline specialized for it folds the test away (the
//    froxel pass, the sky-view lattice and the marched per-pixel path under a high sun:
//    AERIAL_SUN_HIGH_EVERYWHERE, aerial/render/sun_high_variant.h).
// A GPU runs the same code at the same cost. Measured in docs/speed.md ("Reads on both sides of a branch").

// One layer of a density profile (Bruneton 2017, DensityProfileLayer):
// density(h) = exp_term * exp(exp_scale * h) + linear_term * h + constant_term, clamped to [0, 1].
struct DensityProfileLayer {
  float width;
  float exp_term;
  float exp_scale;
  float linear_term;
  float constant_term;
  float pad0;
  float pad1;
  float pad2;
};

// layers[0] below layers[0].width, layers[1] above.
struct DensityProfile {
  DensityProfileLayer layers[2];
};

// kMaxSpectralSunlightTerms in aerial/shader_abi/atmosphere_block.h.
#define AERIAL_SPECTRAL_SUNLIGHT_MAX_TERMS 48

// The atmosphere's and the frame's blocks (frame.glsl) are each read as the one element of an
// array, at AERIAL_BLOCK_INDEX: 0 unless the shader defines it first (blocks_not_inlined.glsl). An
// array of one struct in a std140 block lays its members out as the block itself would.
#ifndef AERIAL_BLOCK_INDEX
#define AERIAL_BLOCK_INDEX 0
#endif

// Mirrored by aerial::AtmosphereUniforms (aerial/shader_abi/atmosphere_block.h);
// tests/uniform_layout_test.cpp checks every member's offset against the compiler's layout.
struct AtmosphereParameters {
  vec4 solar_irradiance;        // W/m^2/nm, xyz = the three wavelengths.
  vec4 rayleigh_scattering;
  vec4 mie_scattering;
  vec4 mie_extinction;
  vec4 absorption_extinction;
  vec4 ground_albedo;
  DensityProfile rayleigh_density;
  DensityProfile mie_density;
  DensityProfile absorption_density;
  float bottom_radius;
  float top_radius;
  float sun_angular_radius;
  float mie_phase_g;
  float mu_s_min;
  float multiple_density_scale;  // J_ms is stored times this (GetMultipleScatteringDensity)
  float pad1;
  float pad2;
  ivec4 transmittance_size;     // x: mu, y: r.
  ivec4 irradiance_size;        // x: mu_s, y: r.
  ivec4 scattering_size;        // x: r, y: mu, z: mu_s, w: nu (w == 1: the 3D variant).
  ivec4 density_size;           // the same axes, for the per-order density and multiple scattering.
  ivec4 density_directions;     // x: zenith samples above the horizon, y: below, z: azimuths in [0, pi].
  ivec4 sample_counts;          // x: transmittance steps, y: single scattering steps,
                                // z: irradiance zenith samples, w: irradiance azimuth samples.
  ivec4 multiple_scattering_steps;  // x: steps per ray of the multiple scattering pass.
  ivec4 multiple_density_size;  // the scattering axes, for the density of orders >= 2 (J_ms).
  // Spectral tables: the sunlight through a path, per wavelength (GetPathSunlight); x: the
  // wavelengths, 0 for rgb tables; y: 1 where the channels are linear sRGB (spectral tables).
  ivec4 spectral_sunlight_terms;
  vec4 spectral_sunlight_exponent[AERIAL_SPECTRAL_SUNLIGHT_MAX_TERMS];
  vec4 spectral_sunlight_rayleigh[AERIAL_SPECTRAL_SUNLIGHT_MAX_TERMS];
  vec4 spectral_sunlight_mie[AERIAL_SPECTRAL_SUNLIGHT_MAX_TERMS];
  vec4 spectral_sunlight_direct[AERIAL_SPECTRAL_SUNLIGHT_MAX_TERMS];
};
layout(std140, set = 0, binding = 0) uniform AtmosphereBlock {
  AtmosphereParameters parameters[1];
} atmosphere_block;
#define AERIAL_ATMOSPHERE atmosphere_block.parameters[AERIAL_BLOCK_INDEX]

float ClampCosine(float mu) { return clamp(mu, -1.0, 1.0); }
float ClampDistance(float d) { return max(d, 0.0); }
float ClampRadius(float r) { return clamp(r, AERIAL_ATMOSPHERE.bottom_radius, AERIAL_ATMOSPHERE.top_radius); }
float SafeSqrt(float a) { return sqrt(max(a, 0.0)); }

// Integral over one step of length 1 of a function known at both ends, assuming it varies
// exponentially in between: the logarithmic mean (f1 - f0) / ln(f1 / f0). Along a ray through an
// exponential atmosphere the scattering integrands are close to exponential, where the plain
// trapezoid overestimates: with Mie's 1.2 km scale height and 50 steps over a 60 km zenith ray the
// trapezoid is 8% high, the logarithmic mean exact. Where a value is zero (shadow, ground) or the
// two ends are nearly equal, the trapezoid is used.
vec3 ExponentialStepIntegral(vec3 f0, vec3 f1) {
  vec3 trapezoid = 0.5 * (f0 + f1);
  bvec3 positive = greaterThan(min(f0, f1), vec3(1e-30));
  vec3 ratio = f1 / max(f0, vec3(1e-30));
  bvec3 use_log = bvec3(vec3(positive) * step(1e-3, abs(ratio - 1.0)));
  // Selections, not blends: a blend would multiply the unused branch's inf or NaN by zero.
  vec3 log_ratio = mix(vec3(1.0), log(max(ratio, vec3(1e-30))), use_log);
  return mix(trapezoid, (f1 - f0) / log_ratio, use_log);
}

// Interpolation at t in [0, 1] between two samples of a function that varies exponentially in
// between (a table's rows in r: the air's density falls exponentially with altitude): a geometric
// mix. Where either sample is zero (the night side) the mix is linear.
vec3 MixExponentially(vec3 a, vec3 b, float t) {
  bvec3 use_log = greaterThan(min(a, b), vec3(1e-30));
  vec3 exponential = exp(mix(log(max(a, vec3(1e-30))), log(max(b, vec3(1e-30))), t));
  return mix(mix(a, b, t), exponential, use_log);  // a selection: use_log is a bvec3
}

// No less light than none, where a sum that cancels could round below it (the Earth's shadow).
// The channels of rgb tables are radiances at three wavelengths: each is clamped. The channels of
// spectral tables are linear sRGB, where light outside the gamut has a negative channel (the Mie
// inscatter of a reddened low sun has a negative blue, a few percent of its red): a per-channel
// clamp added that blue back, 9% of the sky's blue 5 degrees from a sun on the horizon. There
// the colour's CIE XYZ, never negative for light, is clamped instead (IEC 61966-2-1 matrices).
vec3 ClampToLight(vec3 colour) {
  const mat3 xyz_from_linear_srgb = mat3(0.4124, 0.2126, 0.0193, 0.3576, 0.7152, 0.1192,
                                         0.1805, 0.0722, 0.9505);
  const mat3 linear_srgb_from_xyz = mat3(3.2406, -0.9689, 0.0557, -1.5372, 1.8758, -0.2040,
                                         -0.4986, 0.0415, 1.0570);
  vec3 xyz = xyz_from_linear_srgb * colour;
  bool srgb = AERIAL_ATMOSPHERE.spectral_sunlight_terms.y != 0;
  vec3 clamped_srgb = all(greaterThanEqual(xyz, vec3(0.0))) ? colour : linear_srgb_from_xyz * max(xyz, vec3(0.0));
  return srgb ? clamped_srgb : max(colour, vec3(0.0));
}

#endif
