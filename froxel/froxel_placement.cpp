#include "froxel/froxel_placement.h"

#include <algorithm>
#include <cmath>

namespace aerial {

FroxelPlacement::FroxelPlacement(const FrameUniforms& frame, const FroxelGrid& grid)
    : frame_(frame),
      view_projection_(FromColumnMajorFloats(frame.view_projection)),
      camera_(frame.camera_scene_position[0], frame.camera_scene_position[1],
              frame.camera_scene_position[2]),
      grid_(grid),
      axes_(AxesOf(frame)) {}

glm::dvec3 FroxelPlacement::RayThroughScreen(glm::dvec2 uv) const {
  return ViewRayFromScreen(frame_, uv);
}

glm::dvec3 FroxelPlacement::FroxelCenter(int i, int j, int k) const {
  glm::dvec2 uv = axes_.ScreenPosition({(i + 0.5) / grid_.width, (j + 0.5) / grid_.height});
  return camera_ + RayThroughScreen(uv) * grid_.SliceDistance(k + 0.5);
}

std::optional<FroxelPlacement::ScreenPoint> FroxelPlacement::ToScreen(const glm::dvec3& world) const {
  glm::dvec3 relative = world - camera_;
  // Clip w is the distance in front of the camera (ProjectionMatrix in camera.h).
  glm::dvec4 clip = view_projection_ * glm::dvec4(relative, 1.0);
  if (!(clip.w > 0.0)) return std::nullopt;
  return ScreenPoint{glm::dvec2(clip) / clip.w * 0.5 + 0.5, glm::length(relative)};
}

bool FroxelPlacement::Covers(const ScreenPoint& point) const {
  return point.uv.x >= 0.0 && point.uv.x <= 1.0 && point.uv.y >= 0.0 && point.uv.y <= 1.0 &&
         point.distance <= grid_.far_m;
}

std::array<glm::dvec3, 2> FroxelPlacement::Bounds() const {
  // The covered volume is the union of the segments from the camera to the far cap, so its box
  // is that of the apex and the cap. The cap is sampled on a grid; between samples it can bulge
  // out by at most far * (1 - cos(half the angle between neighbors)), added as a margin.
  constexpr int kSteps = 64;
  glm::dvec3 low = camera_, high = camera_;
  double largest_step = 0.0;
  for (int y = 0; y <= kSteps; ++y) {
    for (int x = 0; x <= kSteps; ++x) {
      glm::dvec3 ray = RayThroughScreen(glm::dvec2(x, y) / double(kSteps));
      if (x > 0) {
        glm::dvec3 previous = RayThroughScreen(glm::dvec2(x - 1, y) / double(kSteps));
        largest_step = std::max(largest_step, glm::length(ray - previous));
      }
      if (y > 0) {
        glm::dvec3 previous = RayThroughScreen(glm::dvec2(x, y - 1) / double(kSteps));
        largest_step = std::max(largest_step, glm::length(ray - previous));
      }
      glm::dvec3 point = camera_ + ray * grid_.far_m;
      low = glm::min(low, point);
      high = glm::max(high, point);
    }
  }
  // Between samples c apart (a chord of the unit sphere; sqrt(2) c across a cell's diagonal) the
  // cap leaves the samples' box by at most the arc's sagitta, about (sqrt(2) c)^2 / 8 = c^2 / 4;
  // c^2 / 2 keeps a safe distance above that.
  double margin = grid_.far_m * largest_step * largest_step / 2.0;
  return {low - margin, high + margin};
}

FroxelTexels::Sample FroxelTexels::Read(glm::dvec2 uv, double distance) const {
  const glm::dvec2 xy = axes.Coordinates(uv);
  double coords[3] = {xy.x * grid.width - 0.5, xy.y * grid.height - 0.5,
                      grid.DepthCoordinate(distance) * grid.depth - 0.5};
  int sizes[3] = {grid.width, grid.height, grid.depth};
  Sample sample{glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
  for (int corner = 0; corner < 8; ++corner) {
    int index[3];
    double weight = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
      // Clamp-to-edge with linear filtering: coordinates beyond the outer texel centers read them.
      double c = std::clamp(coords[axis], 0.0, double(sizes[axis] - 1));
      int i0 = std::min(int(std::floor(c)), sizes[axis] - 2);
      double t = c - i0;
      int bit = (corner >> axis) & 1;
      index[axis] = i0 + bit;
      weight *= bit ? t : 1.0 - t;
    }
    if (weight == 0.0) continue;
    size_t texel = ((size_t(index[2]) * grid.height + index[1]) * grid.width + index[0]) * 4;
    for (int c = 0; c < 3; ++c) {
      sample.rayleigh[c] += weight * rayleigh[texel + c];
      sample.mie[c] += weight * mie[texel + c];
      sample.transmittance[c] += weight * transmittance[texel + c];
    }
  }
  double first = grid.SliceDistance(0.5);
  if (distance < first) {
    double t = distance / first;
    sample.rayleigh *= t;
    sample.mie *= t;
    sample.transmittance = glm::mix(glm::dvec3(1.0), sample.transmittance, t);
  }
  return sample;
}

}  // namespace aerial
