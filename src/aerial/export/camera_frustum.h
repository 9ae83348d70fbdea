#pragma once
// The frustum-space grid (export-vdb's default layout): W x H x S voxels over the camera's view
// frustum, from its near plane (view depth camera.near_m) to the froxels' far distance, placed in
// the world by OpenVDB's NonlinearFrustumMap, so that Houdini shows each voxel where the camera
// saw it.
//
// Voxel (i, j, k)'s center is the point at view depth (distance along the view axis)
//   z_k = near + (far - near) (k + 0.5) / S
// on the view ray through the image point (u, v) = ((i + 0.5) / W, (j + 0.5) / H), (0, 0) the
// image's top-left (i right, j down, k away from the camera): W x H the froxels' resolution, even
// on the image, where the froxels' rows gather at the horizon and their columns at the sun's glow
// (shader_abi/froxel_axes.h). Nor can
// the depth slices be the froxels': theirs are spheres around the camera, quadratic
// in k (distance far ((k + 0.5) / D)^2), and an OpenVDB frustum's are planes, linear in k. So the
// linear slices are as thin as the froxels' first: S = FrustumSlices(), which puts the first
// voxel's center at the first froxel slice's distance (31.25 m for 32 slices to 128 km, S = 2082
// slices of 61.5 m), and each voxel is read from the froxels at its own distance along its ray,
// the way the shaders read them (trilinear, FroxelTexels::Read). Far away the linear slices are
// then finer than the froxels' (the last is 7.9 km deep), which costs voxels, not accuracy.
//
// The map: the index box [-0.5, W - 0.5] x [-0.5, H - 0.5] x [-0.5, S - 0.5] (voxel faces, so
// that voxel centers sit at the cell centers above) goes to OpenVDB's unit frustum, whose near
// face is 1 wide and H / W high; the second map scales it to the near plane, w = 2 near t aspect
// wide and h = 2 near t high (t = tan(vertical fov / 2)), turns its x to the camera's right, its
// y to the camera's down (j grows down the image) and its z to forward, and moves it to the
// near plane's center. taper = w / w_far = near / far; depth = (far - near) / w.
#include <cstdint>

#include <glm/glm.hpp>

#include "aerial/export/vdb_file.h"
#include "aerial/froxel_grid.h"
#include "aerial/scene.h"

namespace aerial {

// The frustum grid's voxels are capped as the world grid's are (2^24, about 0.7 GB at peak).
inline constexpr int64_t kMaxFrustumVoxels = int64_t(1) << 24;

// The linear slices from near to far whose first center is at the froxels' first slice distance
// (rounded up to a whole number of slices, so the center is at most that distance), never fewer
// than the froxels' own slices and never more than kMaxFrustumVoxels allow for W x H columns (the
// first center is then farther out). A first froxel slice at or in front of the near plane
// (a short far distance) asks for the cap.
int FrustumSlices(const FroxelGrid& grid, double near_m);

class CameraFrustum {
 public:
  // Throws Error naming the camera's near_m unless it is in (0, grid.far_m).
  CameraFrustum(const Camera& camera, double aspect, const FroxelGrid& grid);

  VdbFrustum Map() const;
  int slices() const { return slices_; }
  // The image point of voxel column (i, j).
  glm::dvec2 ScreenPoint(int i, int j) const;
  // Voxel (i, j, k)'s center in the world (scene frame, m), where Map() puts it.
  glm::dvec3 VoxelCenter(int i, int j, int k) const;

 private:
  glm::dvec3 position_, forward_, right_, up_;
  double tan_half_fov_, aspect_, near_m_, far_m_;
  int width_, height_, slices_;
};

}  // namespace aerial
