#pragma once
// Which terrain chunks to draw for a camera: chunked level of detail (Ulrich 2002). Walking the
// quadtree from the root, a chunk outside the view frustum is not drawn (nor walked into, unless
// a finer chunk below it may rise into the frustum), a chunk whose geometric error projects to
// more than max_error_px pixels is replaced by its four children, and any other is drawn. The
// projected error of a chunk is its geometric error (terrain_chunk.h) seen from its nearest point,
// rho = error * K / distance with K = height_px / (2 tan(fov_y / 2)) (Ulrich's equation 1 with the
// viewport's pixels per radian), so every drawn chunk is within max_error_px of the surface on
// screen, wherever the camera is.
#include <array>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "aerial/scene.h"
#include "aerial/terrain/terrain_chunk.h"

namespace aerial::terrain {

struct LodView {
  glm::dvec3 camera{0.0};
  glm::dmat4 view_projection{1.0};  // scene frame to clip space
  double planet_radius_m = 0.0;
  // Leave out chunks hidden behind nearer ones (screen_horizon.h).
  bool occlusion_culling = true;
  // Return the chunks front to back (for early depth tests); a selection of shadow casters,
  // drawn into a depth map in any order, leaves it out.
  bool front_to_back = true;
  // The frustum's four sides and its near plane in the scene frame: a point p is inside when
  // dot(plane.xyz, p) + plane.w >= 0 for all five (there is no far plane).
  std::array<glm::dvec4, 5> planes{};
  double pixels_per_radian = 0.0;
  double max_error_px = 1.0;
  // A chunk whose geometric error is at most this is drawn without its refinement test: the target
  // resolves nothing finer (a shadow map's texel: render/shadow_terrain.h). Chunk errors never grow
  // from parent to child, so each chunk the rule alone would draw is replaced by its coarsest
  // ancestor within this error. 0: every chunk is tested.
  double resolved_error_m = 0.0;
  bool operator==(const LodView&) const = default;
};

// The error bound is kept at least as fine as max_error_px at min_height_px rows, so that small
// renders (thumbnails, tests) show the same terrain as a 720p frame.
inline constexpr int kLodMinHeightPx = 720;
LodView MakeLodView(const Camera& camera, double aspect, int height_px, double max_error_px,
                    double planet_radius_m, int min_height_px = kLodMinHeightPx);

double DistanceToBounds(const glm::dvec3& p, const Bounds& bounds);
double ScreenSpaceErrorPx(const LodView& view, double geometric_error_m, const Bounds& bounds);
bool IntersectsFrustum(const LodView& view, const Bounds& bounds);
// How far the camera may move before the chunk's refinement test (ScreenSpaceErrorPx against
// max_error_px) can flip: it flips where the distance to the chunk's bounds crosses
// error * K / max_error_px, and that distance changes no faster than the camera moves.
double RefinementSlackM(const LodView& view, double geometric_error_m, const Bounds& bounds);

// What the selection knows of a chunk once it is built.
struct ChunkInfo {
  double geometric_error_m = 0.0;
  Bounds bounds;
  double longest_edge_m = 0.0;  // TerrainChunk::longest_edge_m
  double largest_rise_m = 0.0;  // TerrainChunk::largest_rise_m
  std::array<float, kChunkCells * kChunkCells> cell_lowest_m{};  // TerrainChunk::cell_lowest_m
  std::array<float, kChunkCells * kChunkCells> cell_highest_m{};  // TerrainChunk::cell_highest_m
};

inline ChunkInfo InfoOf(const TerrainChunk& chunk) {
  return {chunk.geometric_error_m, chunk.bounds, chunk.longest_edge_m, chunk.largest_rise_m, chunk.cell_lowest_m,
          chunk.cell_highest_m};
}

// Where chunks come from: built on demand (on the CPU, then uploaded) and kept.
class ChunkSource {
 public:
  virtual ~ChunkSource() = default;
  // The chunk's info if it is built, else null.
  virtual const ChunkInfo* Find(const ChunkId& id) = 0;
  // Builds the chunks (those it can within its time budget; the rest stay unbuilt).
  virtual void Build(std::span<const ChunkId> ids) = 0;
};

struct SelectedChunk {
  ChunkId id;
  // The sides whose neighbour is not drawn at the same level (ChunkSide bits): the only sides
  // where a crack can open, so the only ones that need the skirt.
  uint32_t skirts = kAllSides;
  bool operator==(const SelectedChunk&) const = default;
};

struct Selection {
  std::vector<SelectedChunk> chunks;  // to draw, front to back
  int hidden = 0;  // chunks left out because nearer ones hide them
  // Chunks that should have replaced a drawn one but were not built yet: a chunk is drawn in its
  // children's place until all of them are built, so the view is never left with holes.
  int deferred = 0;
  // How far the camera may move, in any direction, before a refinement test of this selection
  // could come out otherwise (RefinementSlackM, the least over the chunks tested): a selection
  // made again for a camera closer than this to this one, with the same planes, pixels per radian
  // and error bound, every chunk built and no occlusion culling (which follows the view), picks
  // the same chunks.
  double camera_slack_m = std::numeric_limits<double>::infinity();
};

// The chunks of the terrain within kTerrainRadiusM of the origin (chunks entirely beyond it are
// not drawn) for the view, in front-to-back order unless view.front_to_back is off: quadtree
// order from the camera, so that along any view ray a chunk comes after every chunk in front of
// it. Builds what it needs through source; the root chunk first.
Selection SelectChunks(const LodView& view, ChunkSource& source);

// Whether any of the chunk's footprint lies within kTerrainRadiusM of the origin (chunks entirely
// beyond it are never drawn).
bool WithinTerrain(const ChunkId& id);

// Sets each chunk's skirts: a side needs none where the chunk across it is in the list at the same
// level (both share the side's vertices exactly), and one everywhere else.
void MarkSkirts(std::vector<SelectedChunk>& chunks);

}  // namespace aerial::terrain
