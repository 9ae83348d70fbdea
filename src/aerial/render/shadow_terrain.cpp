#include "aerial/render/shadow_terrain.h"

#include <algorithm>

namespace aerial {

ShadowTerrainSelection SelectShadowTerrain(const terrain::LodView& frame_view, const ShadowCascades& cascades,
                                           const LightBasis& basis, terrain::ChunkSource& source) {
  terrain::LodView view = frame_view;
  view.planes = CascadesUnionPlanes(cascades, basis);
  view.occlusion_culling = false;
  view.front_to_back = false;
  terrain::Selection selection = terrain::SelectChunks(view, source);
  ShadowTerrainSelection drawn{.deferred = selection.deferred, .camera_slack_m = selection.camera_slack_m};
  for (int i = 0; i < kShadowCascades; ++i) {
    view.planes = cascades[i].planes;
    for (const terrain::SelectedChunk& chunk : selection.chunks)
      if (terrain::IntersectsFrustum(view, source.Find(chunk.id)->bounds)) drawn.chunks[i].push_back(chunk);
  }
  return drawn;
}

std::vector<terrain::SelectedChunk> CoarsenCasters(const std::vector<terrain::SelectedChunk>& chunks,
                                                   double tolerance_m, terrain::ChunkSource& source) {
  std::vector<terrain::ChunkId> coarse;
  coarse.reserve(chunks.size());
  for (const terrain::SelectedChunk& chunk : chunks) {
    terrain::ChunkId id = chunk.id;
    // The selection built every ancestor of a drawn chunk before the chunk itself.
    for (const terrain::ChunkInfo* parent; id.level > 0 && (parent = source.Find(terrain::Parent(id))) &&
                                           parent->geometric_error_m <= tolerance_m;)
      id = terrain::Parent(id);
    coarse.push_back(id);
  }
  std::sort(coarse.begin(), coarse.end());
  coarse.erase(std::unique(coarse.begin(), coarse.end()), coarse.end());
  std::vector<terrain::SelectedChunk> casters;
  casters.reserve(coarse.size());
  for (const terrain::ChunkId& id : coarse) casters.push_back({id});
  terrain::MarkSkirts(casters);
  return casters;
}

}  // namespace aerial
