#include "aerial/render/shadow_terrain.h"

#include <algorithm>

namespace aerial {
namespace {

// A tile draws the terrain resolved to this fraction of its texel: the casters then lie within half
// a texel of the receivers, inside the lookup's normal offset (1.5 texels, shadow.glsl) less what a
// 45-degree slope needs of it (1 texel).
constexpr double kCasterToleranceTexels = 0.25;

}  // namespace

ShadowTerrainSelection SelectShadowTerrain(const terrain::LodView& frame_view, const ShadowCascades& cascades,
                                           terrain::ChunkSource& source) {
  terrain::LodView view = frame_view;
  view.occlusion_culling = false;
  view.front_to_back = false;
  ShadowTerrainSelection drawn{.camera_slack_m = std::numeric_limits<double>::infinity()};
  for (int i = 0; i < kShadowCascades; ++i) {
    view.planes = cascades[i].planes;
    view.resolved_error_m = kCasterToleranceTexels * cascades[i].texel_m;
    terrain::Selection selection = terrain::SelectChunks(view, source);
    // Sorted, so that two selections of the same chunks compare equal (ShadowTileRedrawn).
    std::sort(selection.chunks.begin(), selection.chunks.end(),
              [](const terrain::SelectedChunk& a, const terrain::SelectedChunk& b) { return a.id < b.id; });
    drawn.chunks[i] = std::move(selection.chunks);
    drawn.deferred += selection.deferred;
    drawn.camera_slack_m = std::min(drawn.camera_slack_m, selection.camera_slack_m);
  }
  return drawn;
}

}  // namespace aerial
