#include "aerial/render/shadow_terrain.h"

namespace aerial {

ShadowTerrain SelectShadowTerrain(const terrain::LodView& frame_view, const ShadowCascades& cascades,
                                  const LightBasis& basis, terrain::ChunkSource& source, int& deferred) {
  terrain::LodView view = frame_view;
  view.planes = CascadesUnionPlanes(cascades, basis);
  view.occlusion_culling = false;
  terrain::Selection selection = terrain::SelectChunks(view, source);
  deferred = selection.deferred;
  ShadowTerrain drawn;
  for (int i = 0; i < kShadowCascades; ++i) {
    view.planes = cascades[i].planes;
    for (const terrain::SelectedChunk& chunk : selection.chunks)
      if (terrain::IntersectsFrustum(view, source.Find(chunk.id)->bounds)) drawn[i].push_back(chunk);
  }
  return drawn;
}

}  // namespace aerial
