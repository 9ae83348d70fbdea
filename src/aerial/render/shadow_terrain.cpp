#include "aerial/render/shadow_terrain.h"

#include <algorithm>

namespace aerial {
namespace {

// A tile draws the terrain resolved to this fraction of its texel: the casters then lie within half
// a texel of the receivers, inside the lookup's normal offset (1.5 texels, shadow.glsl) less what a
// 45-degree slope needs of it (1 texel).
constexpr double kCasterToleranceTexels = 0.25;

}  // namespace

terrain::LodView CascadeCasterView(const terrain::LodView& frame_view, const ShadowCascade& cascade) {
  terrain::LodView view = frame_view;
  view.occlusion_culling = false;
  view.front_to_back = false;
  view.planes = cascade.planes;
  view.resolved_error_m = kCasterToleranceTexels * cascade.texel_m;
  return view;
}

CascadeCasters SelectCascadeCasters(const terrain::LodView& frame_view, const ShadowCascade& cascade,
                                    terrain::ChunkSource& source) {
  terrain::Selection selection = terrain::SelectChunks(CascadeCasterView(frame_view, cascade), source);
  // Sorted, so that two selections of the same chunks compare equal (ShadowTileRedrawn).
  std::sort(selection.chunks.begin(), selection.chunks.end(),
            [](const terrain::SelectedChunk& a, const terrain::SelectedChunk& b) { return a.id < b.id; });
  return {std::move(selection.chunks), selection.deferred, selection.camera_slack_m};
}

}  // namespace aerial
