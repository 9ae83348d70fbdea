#version 450
#extension GL_GOOGLE_include_directive : require
// Test shader: the froxel depth mapping (froxel_depth.glsl) and the sky-view lattice's size
// (sky_view_lattice.glsl) at the inputs the test gives, for tests/cpu_gpu_mapping_test.cpp to hold
// against their C++ side.
#include "froxel_depth.glsl"
#include "sky_view_lattice.glsl"
layout(local_size_x = 64) in;
// Per case: (slice center, slice count, far distance, distance) in, (slice distance, depth
// coordinate) out; a sky-view table size in, its lattice size out.
layout(std430, set = 0, binding = 0) readonly buffer FroxelInputs { vec4 froxel_inputs[]; };
layout(std430, set = 0, binding = 1) writeonly buffer FroxelOutputs { vec2 froxel_outputs[]; };
layout(std430, set = 0, binding = 2) readonly buffer TableSizes { ivec2 table_sizes[]; };
layout(std430, set = 0, binding = 3) writeonly buffer LatticeSizes { ivec2 lattice_sizes[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < froxel_inputs.length()) {
    vec4 in_ = froxel_inputs[i];
    froxel_outputs[i] = vec2(FroxelSliceDistance(in_.x, in_.y, in_.z), FroxelDepthCoordinate(in_.w, in_.z));
  }
  if (i < table_sizes.length()) lattice_sizes[i] = GetSkyViewLatticeSize(table_sizes[i]);
}
