#include "aerial/shader_abi/froxel_axes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "aerial/shader_abi/frame_geometry.h"

namespace aerial {

double FroxelAxis::Span() const { return std::asinh((1.0 - focus) / spread) + std::asinh(focus / spread); }

double FroxelAxis::Coordinate(double screen) const {
  return (std::asinh((screen - focus) / spread) + std::asinh(focus / spread)) / Span();
}

double FroxelAxis::ScreenPosition(double coordinate) const {
  return focus + spread * std::sinh(coordinate * Span() - std::asinh(focus / spread));
}

std::array<float, 4> FroxelAxis::Packed() const {
  return {float(focus), float(spread), float(Span()), float(std::asinh(focus / spread))};
}

FroxelAxis FroxelAxis::Unpack(const std::array<float, 4>& packed) {
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

FroxelAxis RowsAroundHorizon(const FrameUniforms& frame, double planet_radius_m) {
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
  FroxelAxis rows;
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

// Where the sun is on the screen, clamped to it, and the weight of its glow there: 1 with the sun
// on the screen, halved for every kFroxelGlowHalvingDeg between the sun and the screen's nearest
// point to it, 0 with the sun behind the camera's plane.
struct SunGlow {
  glm::dvec2 uv{0.5};
  double weight = 0.0;
};

SunGlow SunGlowOnScreen(const FrameUniforms& frame) {
  const glm::dvec3 sun = glm::normalize(
      glm::dvec3(frame.sun_direction[0], frame.sun_direction[1], frame.sun_direction[2]));
  // A direction is a point at infinity: w = 0.
  const glm::dvec4 clip = FromColumnMajorFloats(frame.view_projection) * glm::dvec4(sun, 0.0);
  SunGlow glow;
  if (!(clip.w > 0.0)) return glow;
  glow.uv = glm::clamp(0.5 + 0.5 * glm::dvec2(clip) / clip.w, 0.0, 1.0);
  const double cos_angle = glm::dot(ViewRayFromScreen(frame, glow.uv), sun);
  const double angle_deg = std::acos(std::clamp(cos_angle, -1.0, 1.0)) * 180.0 / std::numbers::pi;
  glow.weight = std::exp2(-angle_deg / kFroxelGlowHalvingDeg);
  return glow;
}

}  // namespace

glm::dvec2 FroxelAxes::Coordinates(glm::dvec2 screen) const {
  return {columns.Coordinate(screen.x), rows.Coordinate(screen.y)};
}

glm::dvec2 FroxelAxes::ScreenPosition(glm::dvec2 coordinates) const {
  return {columns.ScreenPosition(coordinates.x), rows.ScreenPosition(coordinates.y)};
}

FroxelAxes AxesOf(const FrameUniforms& frame) {
  return {.columns = FroxelAxis::Unpack(frame.froxel_columns), .rows = FroxelAxis::Unpack(frame.froxel_rows)};
}

FroxelAxes PlaceFroxelAxes(const FrameUniforms& frame, double planet_radius_m) {
  FroxelAxes axes;
  axes.rows = RowsAroundHorizon(frame, planet_radius_m);
  const SunGlow glow = SunGlowOnScreen(frame);
  // At most 100 times the spread (the weight 53 degrees off the screen): the columns are then within
  // 0.003 screen widths of even, and the shaders' float asinh stays within 5e-6 of the mapping.
  axes.columns = {.focus = glow.uv.x, .spread = kFroxelColumnSpread / std::max(glow.weight, 1e-2)};
  // Rows grow downward: the sun's height on the screen above the band of rows at the horizon.
  const double sun_above_band = axes.rows.focus - axes.rows.spread - glow.uv.y;
  if (sun_above_band > 0.0) axes.rows.focus -= glow.weight * std::min(0.5 * sun_above_band, kFroxelRowsRiseToSun);
  return axes;
}

}  // namespace aerial
