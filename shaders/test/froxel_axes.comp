#version 450
#extension GL_GOOGLE_include_directive : require
// Test shader: the froxel axes' mapping (froxel_axes.glsl) at the inputs the test gives, for
// tests/cpu_gpu_mapping_test.cpp to hold against FroxelAxis (aerial/shader_abi/froxel_axes.h).
#include "froxel_axes.glsl"
layout(local_size_x = 64) in;
// Per case: the packed axis (FroxelAxis::Packed) and a value y in; y's froxel coordinate and,
// taking y as a froxel coordinate, its screen position out.
layout(std430, set = 0, binding = 0) readonly buffer RowsInputs { vec4 rows_inputs[]; };
layout(std430, set = 0, binding = 1) readonly buffer RowsValues { float rows_values[]; };
layout(std430, set = 0, binding = 2) writeonly buffer RowsOutputs { vec2 rows_outputs[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= rows_inputs.length()) return;
  float y = rows_values[i];
  rows_outputs[i] = vec2(FroxelAxisCoordinate(y, rows_inputs[i]), FroxelScreenPosition(y, rows_inputs[i]));
}
