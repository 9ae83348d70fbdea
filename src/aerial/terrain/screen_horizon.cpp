#include "aerial/terrain/screen_horizon.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "aerial/scene/terrain.h"

namespace aerial::terrain {
namespace {

// How far an occluder is lowered below the mesh's lowest vertex: 1 m plus 1 mm per m of distance
// from the camera. It covers the tilt of the local vertical across a footprint (a chunk spans at
// most 1/250 rad of the planet where the horizon test uses it) and float rounding of the mesh.
constexpr double kMarginM = 1.0, kMarginPerM = 1e-3;

// The widest an occluder block may be on the screen, in columns, before it is split into cells.
constexpr double kBlockColumns = 32.0;

// How deep under a cell its occluder box reaches: deeper than any view ray of the terrain goes
// under the ground before it is lost anyway.
constexpr double kDepthM = 20e3;

// Points closer to the camera's plane than this (in clip w, i.e. meters along the view axis) are
// not projected: bounds or occluders reaching behind the camera are left alone.
constexpr double kMinW = 1e-3;

// The height of a polygon chain at device x, walking its vertices left to right from *at (kept
// for the next, larger x): on the segment that reaches x, its lower end on a vertical one when
// `lower`, else its upper end. vertex(i) is the chain's i-th vertex, count of them.
template <typename Vertex>
double ChainAt(const Vertex& vertex, size_t count, double x, size_t* at, bool lower) {
  while (*at + 2 < count && vertex(*at + 1)[0] < x) ++*at;
  const std::array<double, 2>&a = vertex(*at), &b = vertex(*at + 1);
  if (a[0] == b[0]) return lower ? std::min(a[1], b[1]) : std::max(a[1], b[1]);
  return a[1] + (x - a[0]) / (b[0] - a[0]) * (b[1] - a[1]);
}

// Andrew's monotone chain: the convex hull, counter-clockwise from its leftmost point, without
// repeated points. Returns the index of its rightmost point, where the lower chain ends and the
// upper one begins. (points is sorted in place; hull receives the result.)
size_t ConvexHull(std::vector<std::array<double, 2>>& points, std::vector<std::array<double, 2>>& hull) {
  hull.clear();
  if (points.size() < 3) return 0;
  std::sort(points.begin(), points.end());
  auto cross = [](const auto& o, const auto& a, const auto& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  hull.resize(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  const size_t lower_end = k - 1;
  for (size_t i = points.size() - 1, lower = k + 1; i > 0; --i) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0) --k;
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return lower_end;
}

}  // namespace

ScreenHorizon::ScreenHorizon(const glm::dmat4& view_projection, const glm::dvec3& camera,
                             double planet_radius_m, int columns)
    : view_projection_(view_projection),
      camera_(camera),
      planet_radius_m_(planet_radius_m),
      clip_center_(view_projection * glm::dvec4(0.0, 0.0, -planet_radius_m, 1.0)),
      horizon_(columns, -1.0) {}

bool ScreenHorizon::Project(const glm::dvec3& p, Screen& s) const {
  glm::dvec4 clip = view_projection_ * glm::dvec4(p, 1.0);
  if (clip.w < kMinW) return false;
  s = {clip.x / clip.w, -clip.y / clip.w};  // Vulkan's clip y points down
  return true;
}

bool ScreenHorizon::Hides(const Bounds& bounds) const {
  double x_min = INFINITY, x_max = -INFINITY, top = -INFINITY;
  for (int corner = 0; corner < 8; ++corner) {
    glm::dvec3 p(corner & 1 ? bounds.max.x : bounds.min.x, corner & 2 ? bounds.max.y : bounds.min.y,
                 corner & 4 ? bounds.max.z : bounds.min.z);
    Screen s;
    if (!Project(p, s)) return false;
    x_min = std::min(x_min, s.x);
    x_max = std::max(x_max, s.x);
    top = std::max(top, s.up);
  }
  int columns = int(horizon_.size());
  auto column = [&](double x) { return std::clamp(int(std::floor((x + 1.0) * 0.5 * columns)), 0, columns - 1); };
  if (x_max < -1.0 || x_min > 1.0) return false;  // off screen: the frustum test's business
  for (int c = column(x_min); c <= column(x_max); ++c)
    if (top >= horizon_[c]) return false;
  return true;
}

// Occluders are blocks of b x b cells at the height of the block's lowest corner, b as small as
// keeps a block within kBlockColumns columns of the screen: fine cells where the chunk is small on
// screen (distant mountains, whose crests raise the horizon), coarse blocks near the camera, whose
// every column would otherwise be updated 64 times.
void ScreenHorizon::AddOccluders(const Footprint& f,
                                 const std::array<float, kChunkCells * kChunkCells>& cell_lowest_m) {
  double x_min = INFINITY, x_max = -INFINITY;
  for (int corner = 0; corner < 4; ++corner) {
    Screen s;
    double x = f.x0 + (corner & 1) * f.size, y = f.y0 + (corner >> 1) * f.size;
    if (!Project(SurfacePoint(x, y, cell_lowest_m[0], planet_radius_m_), s)) {
      x_min = -INFINITY;  // reaching behind the camera: as wide as can be
      x_max = INFINITY;
      break;
    }
    x_min = std::min(x_min, s.x);
    x_max = std::max(x_max, s.x);
  }
  double columns = (x_max - x_min) * 0.5 * double(horizon_.size());
  int block = 1;
  while (block < kChunkCells && columns * block / kChunkCells > kBlockColumns) block *= 2;
  const int blocks = kChunkCells / block;
  const double side = block * f.cell();
  corners_.resize((blocks + 1) * (blocks + 1));
  for (int j = 0; j <= blocks; ++j)
    for (int i = 0; i <= blocks; ++i) {
      glm::dvec3 up = SurfacePoint(f.x0 + i * side, f.y0 + j * side, 0.0, planet_radius_m_) -
                      glm::dvec3(0.0, 0.0, -planet_radius_m_);
      corners_[j * (blocks + 1) + i] = {up, view_projection_ * glm::dvec4(up, 0.0)};
    }
  for (int j = 0; j < blocks; ++j) {
    for (int i = 0; i < blocks; ++i) {
      float lowest = INFINITY;
      for (int jj = j * block; jj < (j + 1) * block; ++jj)
        for (int ii = i * block; ii < (i + 1) * block; ++ii)
          lowest = std::min(lowest, cell_lowest_m[jj * kChunkCells + ii]);
      const Corner* south_west = &corners_[j * (blocks + 1) + i];
      AddOccluder({south_west, south_west + 1, south_west + blocks + 2, south_west + blocks + 1}, lowest);
    }
  }
}

// The occluder is the box under the block from the height of its lowest corner (lowered by the
// margin) down kDepthM: every ray through it is under the ground. Its projection is the convex
// hull of its corners, cut where the box reaches behind the camera.
void ScreenHorizon::AddOccluder(const std::array<const Corner*, 4>& corners, double lowest_m) {
  const glm::dvec3 center(0.0, 0.0, -planet_radius_m_);
  // One margin for the cell (at its first corner's distance; cells are small beside distances).
  glm::dvec3 first = center + corners[0]->up * ((planet_radius_m_ + lowest_m) / planet_radius_m_);
  double top = lowest_m - kMarginM - kMarginPerM * glm::length(first - camera_);
  std::array<glm::dvec4, 8> clip;  // top corners, then the bottom ones
  bool all_in_front = true;
  double x_min = INFINITY, x_max = -INFINITY, top_up = -INFINITY;
  for (int i = 0; i < 4; ++i) {
    // Along the local vertical: the bottom corner is the top one pulled toward the planet's center.
    clip[i] = clip_center_ + corners[i]->clip_up * ((planet_radius_m_ + top) / planet_radius_m_);
    all_in_front = all_in_front && clip[i].w >= kMinW;
    if (all_in_front) {
      x_min = std::min(x_min, clip[i].x / clip[i].w);
      x_max = std::max(x_max, clip[i].x / clip[i].w);
      top_up = std::max(top_up, -clip[i].y / clip[i].w);
    }
  }
  // A block whose top stays under the horizon across its columns adds nothing.
  if (all_in_front && !RisesAbove(x_min, x_max, top_up)) return;
  for (int i = 0; i < 4; ++i) {
    clip[i + 4] = clip[i] - corners[i]->clip_up * (kDepthM / planet_radius_m_);
    all_in_front = all_in_front && clip[i + 4].w >= kMinW;
  }
  std::vector<std::array<double, 2>>& points = points_;
  points.clear();
  auto project = [&](const glm::dvec4& c) { points.push_back({c.x / c.w, -c.y / c.w}); };
  for (const glm::dvec4& corner : clip)
    if (corner.w >= kMinW) project(corner);
  if (!all_in_front) {
    constexpr std::array<std::array<int, 2>, 12> kEdges = {
        {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
    for (const auto& [i, j] : kEdges) {
      const glm::dvec4 &a = clip[i], &b = clip[j];
      if ((a.w >= kMinW) != (b.w >= kMinW)) project(glm::mix(a, b, (kMinW - a.w) / (b.w - a.w)));
    }
  }
  // The columns under the top face: beside it only the box's slanted sides, far lower, would count.
  size_t lower_end = ConvexHull(points, hull_);
  RaiseHorizon(hull_, lower_end, all_in_front ? x_min : -INFINITY, all_in_front ? x_max : INFINITY);
}

bool ScreenHorizon::RisesAbove(double x_min, double x_max, double up) const {
  int columns = int(horizon_.size());
  // Clamped as doubles: an occluder far off screen projects to x beyond any int (fmax and fmin
  // also send a NaN to a bound).
  auto column_edge = [&](double edge) { return int(std::fmin(std::fmax(edge, 0.0), columns)); };
  int first = column_edge(std::ceil((x_min + 1.0) * 0.5 * columns));
  int last = column_edge(std::floor((x_max + 1.0) * 0.5 * columns));
  for (int column = first; column < last; ++column)
    if (up > horizon_[column]) return true;
  return false;
}

// Over a column [x0, x1] a convex polygon's lower edge is highest and its upper edge lowest at one
// of the column's sides, so the band it covers across the whole column is [max of the two lows,
// min of the two highs]. A band that reaches down to the horizon raises it.
void ScreenHorizon::RaiseHorizon(const std::vector<std::array<double, 2>>& polygon, size_t lower_end,
                                 double x_min, double x_max) {
  if (polygon.size() < 3) return;
  int columns = int(horizon_.size());
  double span_min = INFINITY, span_max = -INFINITY;
  for (const auto& p : polygon) {
    span_min = std::min(span_min, p[0]);
    span_max = std::max(span_max, p[0]);
  }
  x_min = std::max(x_min, span_min);
  x_max = std::min(x_max, span_max);
  // Only whole columns inside that span can be covered.
  // Clamped as doubles: an occluder far off screen projects to x beyond any int (fmax and fmin
  // also send a NaN to a bound).
  auto column_edge = [&](double edge) { return int(std::fmin(std::fmax(edge, 0.0), columns)); };
  int first = column_edge(std::ceil((x_min + 1.0) * 0.5 * columns));
  int last = column_edge(std::floor((x_max + 1.0) * 0.5 * columns));
  if (first >= last) return;
  // The polygon's lower and upper edges at a device x, both chains walked left to right as the
  // columns go (the upper chain is the polygon's tail read backwards, then its first point).
  const size_t n = polygon.size();
  auto lower = [&](size_t i) -> const std::array<double, 2>& { return polygon[i]; };
  auto upper = [&](size_t i) -> const std::array<double, 2>& { return polygon[i == 0 ? 0 : n - i]; };
  size_t lower_at = 0, upper_at = 0;
  auto extent = [&](double x) {
    return std::array<double, 2>{ChainAt(lower, lower_end + 1, x, &lower_at, true),
                                 ChainAt(upper, n - lower_end + 1, x, &upper_at, false)};
  };
  // A column's right side is the next one's left side: each side is measured once.
  std::array<double, 2> left = extent(2.0 * first / columns - 1.0);
  for (int column = first; column < last; ++column) {
    std::array<double, 2> right = extent(2.0 * (column + 1) / columns - 1.0);
    double low = std::max(left[0], right[0]), high = std::min(left[1], right[1]);
    if (low <= horizon_[column] && high > horizon_[column]) horizon_[column] = high;
    left = right;
  }
}

}  // namespace aerial::terrain
