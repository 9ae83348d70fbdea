#pragma once
// The frustum-space grid (export-vdb's default layout): W x H x D voxels over the camera's view
// frustum, from its near plane (view depth camera.near_m) to the froxels' far distance, placed in
// the world by OpenVDB's NonlinearFrustumMap, so that Houdini shows each voxel where the camera
// saw it.
//
// Voxel (i, j, k)'s center is the point at view depth (distance along the view axis)
//   z_k = near + (far - near) (k + 0.5) / D
// on the view ray through the image point (u, v) = ((i + 0.5) / W, (j + 0.5) / H), (0, 0) the
// image's top-left (i right, j down, k away from the camera). The columns (i, j) are the
// froxels' own. The depth slices are not: the froxels' are spheres around the camera, quadratic
// in k (distance far ((k + 0.5) / D)^2), and an OpenVDB frustum's are planes, linear in k. So each
// voxel is resampled in depth only: read from the froxels at its own distance along its ray, the
// way the shaders read them (trilinear, FroxelTexels::Read). Linear slices are coarser than the
// froxels' near the camera (4 km deep for 32 slices to 128 km, where the froxels' first slice is
// 125 m deep) and finer far away (the froxels' last is 7.9 km deep).
//
// The map: the index box [-0.5, W - 0.5] x [-0.5, H - 0.5] x [-0.5, D - 0.5] (voxel faces, so
// that voxel centers sit at the cell centers above) goes to OpenVDB's unit frustum, whose near
// face is 1 wide and H / W high; the second map scales it to the near plane, w = 2 near t aspect
// wide and h = 2 near t high (t = tan(vertical fov / 2)), turns its x to the camera's right, its
// y to the camera's down (j grows down the image) and its z to forward, and moves it to the
// near plane's center. taper = w / w_far = near / far; depth = (far - near) / w.
#include <glm/glm.hpp>

#include "aerial/export/vdb_file.h"
#include "aerial/froxel_grid.h"
#include "aerial/scene.h"

namespace aerial {

class CameraFrustum {
 public:
  // Throws Error naming the camera's near_m unless it is in (0, grid.far_m).
  CameraFrustum(const Camera& camera, double aspect, const FroxelGrid& grid);

  VdbFrustum Map() const;
  // The image point of voxel column (i, j).
  glm::dvec2 ScreenPoint(int i, int j) const;
  // Voxel (i, j, k)'s center in the world (scene frame, m), where Map() puts it.
  glm::dvec3 VoxelCenter(int i, int j, int k) const;

 private:
  glm::dvec3 position_, forward_, right_, up_;
  double tan_half_fov_, aspect_, near_m_, far_m_;
  int width_, height_, depth_;
};

}  // namespace aerial
