#include "aerial/shader_abi/froxel_rows.h"

#include <algorithm>
#include <cmath>

#include "aerial/shader_abi/frame_geometry.h"

namespace aerial {

double FroxelRows::Span() const { return std::asinh((1.0 - focus) / spread) + std::asinh(focus / spread); }

double FroxelRows::RowCoordinate(double screen_y) const {
  return (std::asinh((screen_y - focus) / spread) + std::asinh(focus / spread)) / Span();
}

double FroxelRows::ScreenRow(double row_coordinate) const {
  return focus + spread * std::sinh(row_coordinate * Span() - std::asinh(focus / spread));
}

std::array<float, 4> FroxelRows::Packed() const {
  return {float(focus), float(spread), float(Span()), float(std::asinh(focus / spread))};
}

FroxelRows FroxelRows::Unpack(const std::array<float, 4>& packed) {
  return {.focus = packed[0], .spread = packed[1]};
}

namespace {

// Where f, continuous on [a, b], crosses zero, by bisection; f(a) and f(b) of opposite signs.
template <typename F>
double Crossing(F f, double a, double b) {
  const bool a_positive = f(a) > 0.0;
  for (int i = 0; i < 40; ++i) {
    double middle = 0.5 * (a + b);
    ((f(middle) > 0.0) == a_positive ? a : b) = middle;
  }
  return 0.5 * (a + b);
}

}  // namespace

FroxelRows FroxelRowsAroundHorizon(const FrameUniforms& frame, double planet_radius_m) {
  const glm::dvec3 camera(frame.camera_planet_position[0], frame.camera_planet_position[1],
                          frame.camera_planet_position[2]);
  const double r = glm::length(camera), R = planet_radius_m;
  const glm::dvec3 up = camera / r;
  auto mu = [&](double y) { return glm::dot(ViewRayFromScreen(frame, {0.5, y}), up); };
  // The horizon's ray dips below the horizontal by acos(R / r): mu = -sqrt(1 - (R / r)^2).
  const double ratio = std::min(R / r, 1.0);
  const double horizon_mu = -std::sqrt(1.0 - ratio * ratio);
  auto above_horizon = [&](double y) { return mu(y) - horizon_mu; };
  const double top = above_horizon(0.0), bottom = above_horizon(1.0);
  FroxelRows rows;
  if ((top > 0.0) == (bottom > 0.0)) {
    rows.focus = std::abs(top) < std::abs(bottom) ? 0.0 : 1.0;
  } else {
    rows.focus = Crossing(above_horizon, 0.0, 1.0);
  }
  // Below the horizon the band reaches down to where the sea-level ground is kFroxelRowsFarGroundM
  // away: from a mountain or an aircraft all of the ground below is far, and the rows stay near
  // even. From lower down, the ground at the horizon (sqrt(r^2 - R^2) away) is nearer than that.
  const double below_edge = bottom < top ? 1.0 : 0.0;
  auto beyond_far_ground = [&](double y) {
    double m = std::min(mu(y), horizon_mu), discriminant = r * r * (m * m - 1.0) + R * R;
    return -r * m - std::sqrt(std::max(discriminant, 0.0)) - kFroxelRowsFarGroundM;
  };
  if (beyond_far_ground(rows.focus) > 0.0) {
    const double far_ground = beyond_far_ground(below_edge) > 0.0
                                  ? below_edge
                                  : Crossing(beyond_far_ground, rows.focus, below_edge);
    rows.spread = std::max(kFroxelRowSpread, std::abs(far_ground - rows.focus));
  }
  return rows;
}

}  // namespace aerial
