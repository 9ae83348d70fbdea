#version 450
#extension GL_GOOGLE_include_directive : require
// Test shader: ReadTable (table_read.glsl) of a 2D and a 3D table at each queried coordinate.
#include "table_read.glsl"
layout(local_size_x = 64) in;
layout(set = 0, binding = 0) uniform sampler2D table_2d;
layout(set = 0, binding = 1) uniform sampler3D table_3d;
layout(std430, set = 0, binding = 2) readonly buffer Queries { vec4 uvw[]; };
// Per query: the 2D table's value at uvw.xy, then the 3D table's at uvw.xyz.
layout(std430, set = 0, binding = 3) writeonly buffer Results { vec4 value[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uvw.length()) return;
  value[2 * i] = ReadTable(table_2d, uvw[i].xy);
  value[2 * i + 1] = ReadTable(table_3d, uvw[i].xyz);
}
