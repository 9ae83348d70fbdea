#pragma once
// The terrain chunks the sun's shadow map draws (shadow_map.h). The frame's own selection only
// holds chunks inside the view frustum and in sight, but a ridge behind the camera or hidden
// behind a nearer one still casts its shadow into the view. So the shadow pass selects again,
// with the frame's level-of-detail rule (the same camera, pixels per radian and error bound:
// lod_selection.h), over the box of light space the cascades cover, extruded toward the sun, and
// without occlusion culling. Where the two selections overlap they pick the same chunks, so the
// caster's triangles are the receiver's own: no acne from a level-of-detail mismatch.
#include <array>
#include <vector>

#include "aerial/render/shadow_cascades.h"
#include "aerial/terrain/lod_selection.h"

namespace aerial {

// The chunks each cascade draws: those of the selection whose bounds meet the cascade's box.
using ShadowTerrain = std::array<std::vector<terrain::SelectedChunk>, kShadowCascades>;

// A cascade's casters as its depth map resolves them: each chunk replaced by its coarsest
// ancestor whose geometric error is at most tolerance_m (sorted, each once, with the skirts of the
// coarsened list). Ulrich's chunks are a hierarchy of simplifications, so any ancestor is a valid
// coarser mesh of the same ground; the ridged mountains' errors are large, so at the default view
// this merges about a tenth of the last tile's chunks (1780 to 1609). The caster stays within
// twice the tolerance of the receiver's own chunk where they differ (a chunk's error is at most
// its parent's, as the terrain's are). Two selections that coarsen alike draw the same tile: the
// renderer redraws a cascade's tile when its coarsened casters change, not whenever the camera's
// level of detail moves by a level somewhere in it.
std::vector<terrain::SelectedChunk> CoarsenCasters(const std::vector<terrain::SelectedChunk>& chunks,
                                                   double tolerance_m, terrain::ChunkSource& source);

struct ShadowTerrainSelection {
  ShadowTerrain chunks;
  // Chunks drawn in place of finer ones not built yet (a later call with the same view may then
  // pick other chunks).
  int deferred = 0;
  // How far the camera may move before the same cascades select otherwise
  // (terrain::Selection::camera_slack_m).
  double camera_slack_m = 0.0;
};

ShadowTerrainSelection SelectShadowTerrain(const terrain::LodView& frame_view, const ShadowCascades& cascades,
                                           const LightBasis& basis, terrain::ChunkSource& source);

}  // namespace aerial
