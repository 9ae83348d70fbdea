// Where the froxels' rows and columns sit on the screen: the rows gathered around the horizon, the
// columns at the sun's glow. The GLSL side of FroxelAxis (src/aerial/shader_abi/froxel_axes.h,
// which says why and gives the mapping; tests/cpu_gpu_mapping_test.cpp holds the two together).
// axis: the FrameBlock's froxel_rows or froxel_columns (focus, spread, span, asinh(focus /
// spread)), which aerial::MakeFrameUniforms fills.
#ifndef AERIAL_FROXEL_AXES_GLSL
#define AERIAL_FROXEL_AXES_GLSL

// asinh as sign(x) log(|x| + sqrt(x^2 + 1)): for x < 0 the sum x + sqrt(x^2 + 1) would cancel.
float FroxelAxisAsinh(float x) { return sign(x) * log(abs(x) + sqrt(x * x + 1.0)); }

// The froxels' texture coordinate along an axis of a screen coordinate (uv, 0 at the left or top).
float FroxelAxisCoordinate(float screen, vec4 axis) {
  return (FroxelAxisAsinh((screen - axis.x) / axis.y) + axis.w) / axis.z;
}

// The screen coordinate of a froxel texture coordinate: the inverse.
float FroxelScreenPosition(float coordinate, vec4 axis) {
  return axis.x + axis.y * sinh(coordinate * axis.z - axis.w);
}

// Both axes at once: the froxels' texture xy of a screen position, and the inverse.
vec2 FroxelAxesCoordinates(vec2 uv, vec4 columns, vec4 rows) {
  return vec2(FroxelAxisCoordinate(uv.x, columns), FroxelAxisCoordinate(uv.y, rows));
}
vec2 FroxelScreenPositions(vec2 coordinates, vec4 columns, vec4 rows) {
  return vec2(FroxelScreenPosition(coordinates.x, columns), FroxelScreenPosition(coordinates.y, rows));
}

#endif
