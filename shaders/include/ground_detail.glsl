// The ground's fine detail: variation of the terrain's albedo below the scale its geometry and
// its per-vertex materials resolve (the height field's finest octave is 560 m; a chunk's vertices
// are metres to kilometres apart), so that the ground near the camera has texture and its
// contrast visibly fades with distance through the haze.
//
// Two octaves of value noise (Perlin 1985's lattice noise with values, not gradients) over the
// ground's east and north coordinates, as a factor of the albedo whose mean is 1: the ground keeps
// the brightness of its materials at every distance. Each octave fades out as a pixel's footprint
// on the ground approaches half its wavelength (frequency clamping: Ebert et al., "Texturing &
// Modeling", ch. 2), so the distant ground is its materials' albedo, not aliased noise. ALU only:
// no texture to bind or, on a CPU rasterizer, to filter in software.
#ifndef AERIAL_GROUND_DETAIL_GLSL
#define AERIAL_GROUND_DETAIL_GLSL

// Off (RendererOptions::ground_detail), the detail is compiled out: a CPU rasterizer runs both
// sides of a branch, so only a constant takes its cost away.
layout(constant_id = 7) const bool kGroundDetail = true;

const float kGroundDetailWavelengthsM[2] = float[2](9.0, 70.0);
const float kGroundDetailAmplitudes[2] = float[2](0.12, 0.16);

// A hash of a lattice point to [0, 1) (integer mixing as in Jarzynski & Olano, "Hash Functions
// for GPU Rendering", JCGT 2020).
float GroundDetailHash(ivec2 p) {
  uint h = uint(p.x) * 0x8da6b343u ^ uint(p.y) * 0xd8163841u;
  h = (h ^ (h >> 15u)) * 0x2c1b3c6du;
  h ^= h >> 12u;
  return float(h) * (1.0 / 4294967296.0);
}

// Value noise in [-1, 1] at x (lattice units), smoothly interpolated between lattice points.
float GroundDetailNoise(vec2 x) {
  vec2 cell = floor(x);
  vec2 f = x - cell;
  vec2 u = f * f * (3.0 - 2.0 * f);
  ivec2 c = ivec2(cell);
  float a = GroundDetailHash(c), b = GroundDetailHash(c + ivec2(1, 0));
  float d = GroundDetailHash(c + ivec2(0, 1)), e = GroundDetailHash(c + ivec2(1, 1));
  return 2.0 * mix(mix(a, b, u.x), mix(d, e, u.x), u.y) - 1.0;
}

// The albedo's factor at a ground point (east, north in metres; the scene frame's x and y), for a
// fragment whose footprint on the ground is footprint_m wide. Derivatives are taken by the caller
// in uniform control flow.
float GroundAlbedoDetail(vec2 ground_m, float footprint_m) {
  float factor = 1.0;
  for (int octave = 0; octave < 2; ++octave) {
    float wavelength = kGroundDetailWavelengthsM[octave];
    // Full amplitude up to a quarter wavelength a pixel, none from half (the Nyquist limit).
    float resolved = clamp(2.0 - 4.0 * footprint_m / wavelength, 0.0, 1.0);
    if (resolved > 0.0)
      factor += kGroundDetailAmplitudes[octave] * resolved * GroundDetailNoise(ground_m / wavelength);
  }
  return factor;
}

// The factor for the fragment at relative_position (from the camera, scene frame), weighted by
// `amount` (0 leaves the albedo alone: a mesh that is not the ground).
float GroundAlbedoDetailAt(vec3 relative_position, float amount) {
  if (!kGroundDetail) return 1.0;
  vec2 ground = relative_position.xy + AERIAL_FRAME.camera_scene_position.xy;
  // The footprint from the camera-relative position: its derivatives are those of the ground
  // point, without the cancellation of a large camera offset.
  float footprint = max(length(dFdx(relative_position.xy)), length(dFdy(relative_position.xy)));
  if (amount == 0.0) return 1.0;
  return mix(1.0, GroundAlbedoDetail(ground, footprint), amount);
}

#endif
