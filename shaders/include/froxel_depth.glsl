// The froxel volume's depth mapping, the GLSL side of FroxelGrid::SliceDistance and
// DepthCoordinate (aerial/froxel_grid.h; tests/cpu_gpu_mapping_test.cpp holds the two
// together). Slice k's texel center stands for the distance
//   d_k = far * ((k + 0.5) / D)^2,
// a quadratic distribution (Hillaire 2020): near slices are thin (31 m at the default 32 slices
// over 128 km) where aerial perspective changes fastest relative to the distance and where
// nearby objects need it resolved, far slices are long (8 km) where it changes slowly. The
// inverse, w = sqrt(d / far), puts any distance on the texture's z axis with texel centers at the
// d_k.
#ifndef AERIAL_FROXEL_DEPTH_GLSL
#define AERIAL_FROXEL_DEPTH_GLSL

float FroxelSliceDistance(float slice_center, float slices, float far_distance) {
  float s = slice_center / slices;
  return far_distance * s * s;
}

float FroxelDepthCoordinate(float distance, float far_distance) {
  return sqrt(max(distance, 0.0) / far_distance);
}

#endif
