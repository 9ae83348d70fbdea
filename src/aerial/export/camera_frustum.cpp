#include "aerial/export/camera_frustum.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "aerial/error.h"
#include "aerial/scene/camera.h"

namespace aerial {

int FrustumSlices(const FroxelGrid& grid, double near_m) {
  const int64_t columns = int64_t(grid.width) * grid.height;
  const int64_t most = std::max<int64_t>(grid.depth, kMaxFrustumVoxels / columns);
  const double first = grid.SliceDistance(0.5);
  if (!(first > near_m)) return int(most);
  const double wanted = std::ceil((grid.far_m - near_m) / (2.0 * (first - near_m)));
  return int(std::clamp<double>(wanted, grid.depth, double(most)));
}

CameraFrustum::CameraFrustum(const Camera& camera, double aspect, const FroxelGrid& grid)
    : position_(camera.position),
      forward_(Forward(camera)),
      right_(Right(camera)),
      up_(Up(camera)),
      tan_half_fov_(std::tan(glm::radians(camera.vertical_fov_deg) / 2.0)),
      aspect_(aspect),
      near_m_(camera.near_m),
      far_m_(grid.far_m),
      width_(grid.width),
      height_(grid.height),
      slices_(0) {
  if (!(near_m_ > 0.0 && near_m_ < far_m_)) {
    char value[32], allowed[128];
    std::snprintf(value, sizeof value, "%.9g", near_m_);
    std::snprintf(allowed, sizeof allowed, "in (0, %.9g) m, the froxel far distance (export-vdb's frustum grid)",
                  far_m_);
    throw Error("camera.near_m", value, allowed);
  }
  slices_ = FrustumSlices(grid, near_m_);
}

VdbFrustum CameraFrustum::Map() const {
  const double near_width = 2.0 * near_m_ * tan_half_fov_ * aspect_, near_height = 2.0 * near_m_ * tan_half_fov_;
  VdbFrustum frustum;
  frustum.index_min = {-0.5, -0.5, -0.5};
  frustum.index_max = {width_ - 0.5, height_ - 0.5, slices_ - 0.5};
  frustum.taper = near_m_ / far_m_;
  frustum.depth = (far_m_ - near_m_) / near_width;
  // The unit frustum's y spans H / W at the near face: scaled to near_height, down the image.
  const glm::dvec3 x = right_ * near_width, y = -up_ * (near_height * width_ / height_), z = forward_ * near_width;
  const glm::dvec3 origin = position_ + forward_ * near_m_;
  for (int row = 0; row < 3; ++row) {
    frustum.second_map[row * 4 + 0] = x[row];
    frustum.second_map[row * 4 + 1] = y[row];
    frustum.second_map[row * 4 + 2] = z[row];
    frustum.second_map[row * 4 + 3] = origin[row];
  }
  return frustum;
}

glm::dvec2 CameraFrustum::ScreenPoint(int i, int j) const {
  return {(i + 0.5) / width_, (j + 0.5) / height_};
}

glm::dvec3 CameraFrustum::VoxelCenter(int i, int j, int k) const {
  // The ray through the image point, scaled to view depth 1, then to z_k.
  const glm::dvec2 uv = ScreenPoint(i, j);
  const glm::dvec3 ray = forward_ + right_ * ((2.0 * uv.x - 1.0) * tan_half_fov_ * aspect_) +
                         up_ * ((1.0 - 2.0 * uv.y) * tan_half_fov_);
  return position_ + ray * (near_m_ + (far_m_ - near_m_) * (k + 0.5) / slices_);
}

}  // namespace aerial
