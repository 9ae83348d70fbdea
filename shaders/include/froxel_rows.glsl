// Where the froxel rows sit on the screen: gathered around the horizon, where a row's far end spans
// the most height of air. The GLSL side of FroxelRows (src/aerial/shader_abi/froxel_rows.h, which
// says why and gives the mapping; tests/cpu_gpu_mapping_test.cpp holds the two together). rows:
// the FrameBlock's froxel_rows (focus, spread, span, asinh(focus / spread)), which
// aerial::MakeFrameUniforms fills.
#ifndef AERIAL_FROXEL_ROWS_GLSL
#define AERIAL_FROXEL_ROWS_GLSL

// asinh as sign(x) log(|x| + sqrt(x^2 + 1)): for x < 0 the sum x + sqrt(x^2 + 1) would cancel.
float FroxelRowsAsinh(float x) { return sign(x) * log(abs(x) + sqrt(x * x + 1.0)); }

// The froxels' texture y of a screen row (uv y, 0 at the top).
float FroxelRowCoordinate(float screen_y, vec4 rows) {
  return (FroxelRowsAsinh((screen_y - rows.x) / rows.y) + rows.w) / rows.z;
}

// The screen row of a froxel texture y: the inverse.
float FroxelScreenRow(float row_coordinate, vec4 rows) {
  return rows.x + rows.y * sinh(row_coordinate * rows.z - rows.w);
}

#endif
