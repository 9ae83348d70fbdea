#version 450
#extension GL_GOOGLE_include_directive : require
// Test shader: the GLSL values that aerial/render/sun_high_variant.h mirrors in C++, for
// tests/cpu_gpu_mapping_test.cpp to hold against them: the tables' mu_s axis both ways
// (mappings.glsl) and the elevation above which the sun's disc is read at its centre
// (transmittance.glsl).
#include "transmittance.glsl"
layout(local_size_x = 64) in;
// Per case: (mu_s, x) in, (GetUnitRangeFromMuS(mu_s), GetMuSFromUnitRange(x)) out; the constant
// once.
layout(std430, set = 0, binding = 1) readonly buffer MuSInputs { vec2 mu_s_inputs[]; };
layout(std430, set = 0, binding = 2) writeonly buffer MuSOutputs { vec2 mu_s_outputs[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Constants { float one_tap_elevation; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i == 0) one_tap_elevation = SUN_DISC_ONE_TAP_ELEVATION;
  if (i >= mu_s_inputs.length()) return;
  vec2 in_ = mu_s_inputs[i];
  mu_s_outputs[i] = vec2(GetUnitRangeFromMuS(in_.x), GetMuSFromUnitRange(in_.y));
}
