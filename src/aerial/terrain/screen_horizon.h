#pragma once
// Occlusion culling by the terrain in front: a horizon on the screen (after "occlusion horizons",
// Downs, Möller and Séquin, I3D 2001; for height fields, Lloyd and Egbert, "Horizon Occlusion
// Culling for Real-time Rendering of Hierarchical Terrains", IEEE Visualization 2002).
//
// The camera is above the ground, so a view ray that passes below the ground anywhere has hit it
// there and sees nothing beyond. A drawn chunk's mesh never dips below its lowest vertex, so its
// footprint at that height (lowered by a margin, as two flat triangles, which lie below the
// curved ground between their corners) is an occluder: a ray through it is below the ground, and
// so is each of its cells at the height of the cell's lowest corner, which follows the ground
// far more closely over mountains. The
// horizon keeps, per screen column, the top of the band that occluders cover without a gap from
// the bottom of the screen. Chunks are visited front to back (quadtree order from the camera:
// along any view ray a later chunk is never in front of an earlier one), so a chunk whose bounds
// project wholly below the horizon is hidden by chunks already drawn, and is not drawn.
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "aerial/terrain/chunk_id.h"
#include "aerial/terrain/terrain_chunk.h"

namespace aerial::terrain {

class ScreenHorizon {
 public:
  // view_projection: scene frame to Vulkan clip space (camera.h). columns: across the screen.
  ScreenHorizon(const glm::dmat4& view_projection, const glm::dvec3& camera, double planet_radius_m,
                int columns = 1024);

  // True when every corner of bounds projects below the horizon, within the columns it spans.
  bool Hides(const Bounds& bounds) const;
  const std::vector<double>& horizon() const { return horizon_; }
  // Adds a drawn chunk's cells as occluders, each at the height of its lowest corner.
  void AddOccluders(const Footprint& footprint,
                    const std::array<float, kChunkCells * kChunkCells>& cell_lowest_m);

 private:
  struct Screen {
    double x, up;  // normalized device x (-1 left, 1 right) and height (-1 bottom, 1 top)
  };
  // A corner of the occluder blocks: its local vertical, scaled to the planet's radius (the point
  // h above sea level there is the planet's centre + up (R + h) / R), and that vector in clip
  // space, so that a block's corners at any height project with one multiply-add each.
  struct Corner {
    glm::dvec3 up;
    glm::dvec4 clip_up;
  };
  bool Project(const glm::dvec3& p, Screen& s) const;
  // The block over corners (counter-clockwise from its south-west one) at the height lowest_m.
  void AddOccluder(const std::array<const Corner*, 4>& corners, double lowest_m);
  // Whether a height `up` would be above the horizon in any whole column within [x_min, x_max].
  bool RisesAbove(double x_min, double x_max, double up) const;
  // Raises the horizon with a convex polygon over the columns within [x_min, x_max]; the polygon
  // is counter-clockwise from its leftmost point, its lower chain first, through polygon[lower_end]
  // (ConvexHull).
  void RaiseHorizon(const std::vector<std::array<double, 2>>& polygon, size_t lower_end, double x_min,
                    double x_max);

  glm::dmat4 view_projection_;
  glm::dvec3 camera_;
  double planet_radius_m_;
  glm::dvec4 clip_center_;  // the planet's centre in clip space
  std::vector<double> horizon_;  // per column, in device height
  std::vector<Corner> corners_;  // scratch, as points_ and hull_
  std::vector<std::array<double, 2>> points_, hull_;  // scratch, kept so that occluders do not allocate
};

}  // namespace aerial::terrain
