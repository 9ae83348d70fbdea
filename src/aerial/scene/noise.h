#pragma once
// Deterministic pseudo-random numbers and 2D gradient noise for the procedural scene (and the
// hash for the display's dither, aerial/image/tone_map.h). Everything is a pure function of its
// integer inputs (no clock, no mutable state; the gradients' tables are constants), so the
// built-in scene is bit-identical on every run and machine, which its tests and reference images
// rely on.
#include <array>
#include <cstdint>

namespace aerial {

// A 32-bit integer hash (the "lowbias32" finalizer of Chris Wellons' hash-prospector, bias
// ~0.17): every input bit affects every output bit, so consecutive indices give unrelated values.
uint32_t Hash(uint32_t x);
uint32_t Hash(uint32_t a, uint32_t b, uint32_t c = 0);

// Uniform in [0, 1) from a hash: its top 24 bits as a float-exact fraction.
double UnitFromHash(uint32_t h);

// The unit vector at the angle 2 pi UnitFromHash(h): the cosine and sine of that angle to within
// 1.6e-15 (noise_test), from two small tables instead of calls to cos and sin, which would be half
// of a terrain chunk's build (28 gradients per height).
std::array<double, 2> UnitGradient(uint32_t h);

// Perlin's gradient noise (Perlin 2002, "Improving Noise": quintic fade 6t^5 - 15t^4 + 10t^3)
// with unit gradients at integer lattice points, UnitGradient(Hash(ix, iy, seed)). Smooth (C2),
// zero at lattice points, and within [-1, 1] (the 2D extreme is sqrt(2)/2 ~ 0.71).
double GradientNoise(double x, double y, uint32_t seed);

}  // namespace aerial
