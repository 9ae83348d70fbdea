#version 450
// Last pass of the half-precision tables: each float32 texel, rounded in place to the nearest value
// a 16-bit float holds (ties to even), before the blit converts the table to half floats.
//
// Vulkan leaves the rounding of a blit's float conversion to the implementation. Lavapipe rounds
// toward zero: 99.7% of the sky's order-1 reads came out lower than from the float32 table, by
// 0.036% at the median (aerial_bench_sky --orders 1 --series-tail off, float16 against float32),
// a bias as large as a tenth of the daylight median target. Once rounded here the values are
// exact in half floats, and every rounding mode converts them to the same bits.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba32f) uniform image3D table;

// IEEE 754 binary16: 10 fraction bits, exponents down to -14, and below 2^-14 subnormals whose step
// stays 2^-24. Values beyond the largest half (65504) round to a value the blit turns into
// infinity, as it would have.
float RoundToHalf(float x) {
  if (x == 0.0 || isinf(x) || isnan(x)) return x;
  int exponent;
  frexp(x, exponent);  // |x| = m 2^exponent, m in [0.5, 1)
  float step = ldexp(1.0, max(exponent - 1, -14) - 10);
  return roundEven(x / step) * step;  // exact: step is a power of two
}

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(texel, imageSize(table)))) return;
  vec4 value = imageLoad(table, texel);
  imageStore(table, texel,
             vec4(RoundToHalf(value.x), RoundToHalf(value.y), RoundToHalf(value.z),
                  RoundToHalf(value.w)));
}
