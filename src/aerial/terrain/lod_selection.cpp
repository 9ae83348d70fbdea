#include "aerial/terrain/lod_selection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_set>

#include "aerial/scene/camera.h"
#include "aerial/scene/terrain.h"
#include "aerial/terrain/screen_horizon.h"

namespace aerial::terrain {
namespace {

// The sea-level footprint is not exactly the surface's: a point h above sea level sits at
// (R + h) / R times its sea-level x and y (SurfacePoint), 0.08% further out at h = 5 km.
constexpr double kHorizontalSpread = 2e-3;

// Conservative bounds of a child that is not built yet: its footprint, widened for the spread,
// over its parent's heights, raised by the parent's error (the surface may rise that far above
// the parent's triangles between its vertices).
Bounds EstimateChildBounds(const ChunkId& child, const ChunkInfo& parent) {
  Footprint f = FootprintOf(child);
  auto widen = [](double lo, double hi) {
    double margin = kHorizontalSpread * std::max(std::fabs(lo), std::fabs(hi)) + 1.0;
    return std::array<double, 2>{lo - margin, hi + margin};
  };
  auto x = widen(f.x0, f.x0 + f.size), y = widen(f.y0, f.y0 + f.size);
  return {{x[0], y[0], parent.bounds.min.z - parent.geometric_error_m},
          {x[1], y[1], parent.bounds.max.z + parent.geometric_error_m}};
}

// Where a chunk's descendants may lie: its surface is within its geometric error of its triangles
// (each finer mesh samples that surface), so within its bounds grown by that error.
Bounds DescendantsBounds(const ChunkInfo& info) {
  glm::dvec3 margin(info.geometric_error_m);
  return {info.bounds.min - margin, info.bounds.max + margin};
}

// Quadtree order from the camera (its sea-level point): at every node, the child on the camera's
// side of both splitting lines first, the one across both last. Two chunks are ordered at the
// first node where their paths from the root part. A path's ranks (2 bits a level) are packed from
// the top bit down, so that comparing the keys compares the paths; no drawn chunk lies inside
// another, so no path is a prefix of another.
void SortFrontToBack(const LodView& view, std::vector<SelectedChunk>& chunks) {
  static_assert(2 * kMaxChunkLevel <= 64, "a path's ranks fit in a 64-bit key");
  const glm::dvec3 center(0.0, 0.0, -view.planet_radius_m);
  glm::dvec3 eye = center + view.planet_radius_m * glm::normalize(view.camera - center);
  auto path_key = [&](const ChunkId& id) {
    uint64_t key = 0;
    for (int level = 0; level < id.level; ++level) {
      int shift = id.level - level - 1;  // the bit of x and y that picks the child at this level
      ChunkId node{level, id.x >> (shift + 1), id.y >> (shift + 1)};
      Footprint f = FootprintOf(node);
      int camera_x = eye.x >= f.x0 + f.size / 2 ? 1 : 0, camera_y = eye.y >= f.y0 + f.size / 2 ? 1 : 0;
      int child_x = (id.x >> shift) & 1, child_y = (id.y >> shift) & 1;
      uint64_t rank = (child_x != camera_x ? 1 : 0) + (child_y != camera_y ? 2 : 0);
      key |= rank << (62 - 2 * level);
    }
    return key;
  };
  std::vector<std::pair<uint64_t, SelectedChunk>> keyed;
  keyed.reserve(chunks.size());
  for (const SelectedChunk& chunk : chunks) keyed.push_back({path_key(chunk.id), chunk});
  std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (size_t i = 0; i < chunks.size(); ++i) chunks[i] = keyed[i].second;
}

// Front to back, each chunk either hidden by those drawn before it or drawn and then an occluder.
void LeaveOutHidden(const LodView& view, ChunkSource& source, Selection& selection) {
  ScreenHorizon horizon(view.view_projection, view.camera, view.planet_radius_m);
  std::vector<SelectedChunk> drawn;
  for (const SelectedChunk& chunk : selection.chunks) {
    const ChunkInfo& info = *source.Find(chunk.id);
    if (horizon.Hides(info.bounds)) {
      ++selection.hidden;
      continue;
    }
    drawn.push_back(chunk);
    horizon.AddOccluders(FootprintOf(chunk.id), info.cell_lowest_m);
  }
  selection.chunks = std::move(drawn);
}

}  // namespace

bool WithinTerrain(const ChunkId& id) {
  Footprint f = FootprintOf(id);
  double dx = std::max({f.x0, 0.0, -(f.x0 + f.size)});
  double dy = std::max({f.y0, 0.0, -(f.y0 + f.size)});
  return std::hypot(dx, dy) < kTerrainRadiusM;
}

void MarkSkirts(std::vector<SelectedChunk>& chunks) {
  std::unordered_set<ChunkId, ChunkIdHash> drawn;
  drawn.reserve(chunks.size());
  for (const SelectedChunk& chunk : chunks) drawn.insert(chunk.id);
  for (SelectedChunk& chunk : chunks) {
    const ChunkId& c = chunk.id;
    std::array<std::pair<ChunkId, uint32_t>, 4> neighbours = {
        std::pair{ChunkId{c.level, c.x, c.y - 1}, uint32_t(kSouth)},
        std::pair{ChunkId{c.level, c.x + 1, c.y}, uint32_t(kEast)},
        std::pair{ChunkId{c.level, c.x, c.y + 1}, uint32_t(kNorth)},
        std::pair{ChunkId{c.level, c.x - 1, c.y}, uint32_t(kWest)}};
    chunk.skirts = 0;
    for (const auto& [neighbour, side] : neighbours)
      if (!drawn.contains(neighbour)) chunk.skirts |= side;
  }
}

LodView MakeLodView(const Camera& camera, double aspect, int height_px, double max_error_px,
                    double planet_radius_m, int min_height_px) {
  LodView view;
  view.camera = camera.position;
  view.planet_radius_m = planet_radius_m;
  view.max_error_px = max_error_px;
  double tan_half = std::tan(camera.vertical_fov_deg * std::numbers::pi / 360.0);
  view.pixels_per_radian = double(std::max(height_px, min_height_px)) / (2.0 * tan_half);
  // Gribb and Hartmann, "Fast Extraction of Viewing Frustum Planes from the World-View-Projection
  // Matrix" (2001), for Vulkan's clip space with reversed Z: -w <= x, y <= w and z <= w (near).
  glm::dmat4 m = ProjectionMatrix(camera, aspect) * ViewMatrix(camera);
  view.view_projection = m;
  auto row = [&](int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
  view.planes = {row(3) + row(0), row(3) - row(0), row(3) + row(1), row(3) - row(1), row(3) - row(2)};
  for (glm::dvec4& plane : view.planes) plane /= glm::length(glm::dvec3(plane));
  return view;
}

double DistanceToBounds(const glm::dvec3& p, const Bounds& bounds) {
  return glm::length(p - glm::clamp(p, bounds.min, bounds.max));
}

double ScreenSpaceErrorPx(const LodView& view, double geometric_error_m, const Bounds& bounds) {
  double distance = DistanceToBounds(view.camera, bounds);
  if (distance <= 0.0) return geometric_error_m > 0.0 ? INFINITY : 0.0;
  return geometric_error_m * view.pixels_per_radian / distance;
}

double RefinementSlackM(const LodView& view, double geometric_error_m, const Bounds& bounds) {
  if (geometric_error_m <= 0.0) return std::numeric_limits<double>::infinity();  // never refined
  double threshold_m = geometric_error_m * view.pixels_per_radian / view.max_error_px;
  return std::fabs(DistanceToBounds(view.camera, bounds) - threshold_m);
}

bool IntersectsFrustum(const LodView& view, const Bounds& bounds) {
  for (const glm::dvec4& plane : view.planes) {
    // The box's corner furthest along the plane's normal.
    glm::dvec3 corner(plane.x >= 0 ? bounds.max.x : bounds.min.x, plane.y >= 0 ? bounds.max.y : bounds.min.y,
                      plane.z >= 0 ? bounds.max.z : bounds.min.z);
    if (glm::dot(glm::dvec3(plane), corner) + plane.w < 0.0) return false;
  }
  return true;
}

Selection SelectChunks(const LodView& view, ChunkSource& source) {
  Selection selection;
  const ChunkId root{};
  if (!source.Find(root)) source.Build(std::span(&root, 1));
  std::vector<ChunkId> level = {root};
  while (!level.empty()) {
    // This level's visible chunks that are too coarse, and the children they need built.
    std::vector<ChunkId> refine, missing;
    for (const ChunkId& id : level) {
      const ChunkInfo* info = source.Find(id);
      if (!info) continue;
      // A chunk outside the frustum is not drawn, but a finer one below it may rise into it.
      const bool inside = IntersectsFrustum(view, info->bounds);
      if (!inside && !IntersectsFrustum(view, DescendantsBounds(*info))) continue;
      if (info->geometric_error_m <= view.resolved_error_m) {
        if (inside) selection.chunks.push_back({id});
        continue;
      }
      if (id.level < kMaxChunkLevel)
        selection.camera_slack_m = std::min(selection.camera_slack_m,
                                            RefinementSlackM(view, info->geometric_error_m, info->bounds));
      if (id.level == kMaxChunkLevel ||
          ScreenSpaceErrorPx(view, info->geometric_error_m, info->bounds) <= view.max_error_px) {
        if (inside) selection.chunks.push_back({id});
        continue;
      }
      refine.push_back(id);
      for (const ChunkId& child : Children(id)) {
        if (WithinTerrain(child) && !source.Find(child) &&
            IntersectsFrustum(view, EstimateChildBounds(child, *info)))
          missing.push_back(child);
      }
    }
    if (!missing.empty()) source.Build(missing);
    std::vector<ChunkId> next;
    for (const ChunkId& id : refine) {
      const ChunkInfo& info = *source.Find(id);
      std::vector<ChunkId> children;
      bool ready = true;
      for (const ChunkId& child : Children(id)) {
        if (!WithinTerrain(child)) continue;
        if (source.Find(child)) {
          children.push_back(child);
        } else if (IntersectsFrustum(view, EstimateChildBounds(child, info))) {
          ready = false;
        }
      }
      if (ready) {
        next.insert(next.end(), children.begin(), children.end());
      } else {
        // Drawn in their place where it is in the frustum itself.
        if (IntersectsFrustum(view, info.bounds)) selection.chunks.push_back({id});
        ++selection.deferred;
      }
    }
    level = std::move(next);
  }
  if (view.front_to_back || view.occlusion_culling) SortFrontToBack(view, selection.chunks);
  if (view.occlusion_culling) LeaveOutHidden(view, source, selection);
  MarkSkirts(selection.chunks);
  return selection;
}

}  // namespace aerial::terrain
