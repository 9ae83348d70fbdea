#include "aerial/render/shadow_terrain.h"

namespace aerial {

ShadowTerrain SelectShadowTerrain(const terrain::LodView& frame_view, const ShadowCascades& cascades,
                                  const LightBasis& basis, terrain::ChunkSource& source) {
  terrain::LodView view = frame_view;
  view.planes = CascadesUnionPlanes(cascades, basis);
  view.occlusion_culling = false;
  terrain::Selection selection = terrain::SelectChunks(view, source);
  ShadowTerrain drawn;
  for (int i = 0; i < kShadowCascades; ++i) {
    view.planes = cascades[i].planes;
    for (const terrain::SelectedChunk& chunk : selection.chunks)
      if (terrain::IntersectsFrustum(view, source.Find(chunk.id)->bounds)) drawn[i].push_back(chunk);
  }
  return drawn;
}

bool SameChunks(const ShadowTerrain& a, const ShadowTerrain& b) {
  for (int i = 0; i < kShadowCascades; ++i) {
    if (a[i].size() != b[i].size()) return false;
    for (size_t k = 0; k < a[i].size(); ++k)
      if (a[i][k].id != b[i][k].id || a[i][k].skirts != b[i][k].skirts) return false;
  }
  return true;
}

}  // namespace aerial
