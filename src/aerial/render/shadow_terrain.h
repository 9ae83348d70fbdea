#pragma once
// The terrain chunks the sun's shadow map draws (shadow_map.h). The frame's own selection only
// holds chunks inside the view frustum and in sight, but a ridge behind the camera or hidden
// behind a nearer one still casts its shadow into the view. So each cascade selects again, with
// the frame's level-of-detail rule (the same camera, pixels per radian and error bound:
// lod_selection.h), over its own box of light space extruded toward the sun, without occlusion
// culling, and no finer than its depth map resolves. Where a cascade's selection and the frame's
// overlap at a level its texels resolve, they pick the same chunks, so the caster's triangles are
// the receiver's own: no acne from a level-of-detail mismatch.
#include <array>
#include <vector>

#include "aerial/render/shadow_cascades.h"
#include "aerial/terrain/lod_selection.h"

namespace aerial {

// The chunks each cascade draws, sorted, each once, with the skirts of its own list.
using ShadowTerrain = std::array<std::vector<terrain::SelectedChunk>, kShadowCascades>;

// One cascade's casters.
struct CascadeCasters {
  std::vector<terrain::SelectedChunk> chunks;
  // Chunks drawn in place of finer ones not built yet (a later call with the same view may then
  // pick other chunks).
  int deferred = 0;
  // How far the camera may move before the cascade selects otherwise
  // (terrain::Selection::camera_slack_m). Its chunks' errors are within a fixed fraction of its
  // texel or tested against the camera, so the coarse far cascades' slack is tens of metres where
  // the first one's is a metre or two.
  double camera_slack_m = 0.0;
};

// A cascade's casters are the frame's rule stopped at chunks whose geometric error is within a
// quarter of the cascade's texel (LodView::resolved_error_m): Ulrich's chunks are a hierarchy of
// simplifications, so any ancestor is a valid coarser mesh of the same ground, and a finer one
// would change no texel. The ridged mountains' errors are large, so at the default view this
// merges about a tenth of the last tile's chunks (1328 to 1186), and its selection never walks
// the finer levels that the far cascades' hundred kilometres would otherwise take. The caster
// stays within twice that of the receiver's own chunk where they differ (a chunk's error is at
// most its parent's, as the terrain's are). Two selections that resolve alike draw the same tile:
// the renderer redraws a cascade's tile when its casters change, not whenever the camera's level
// of detail moves by a level somewhere in it.
CascadeCasters SelectCascadeCasters(const terrain::LodView& frame_view, const ShadowCascade& cascade,
                                    terrain::ChunkSource& source);
// The view that selection is made for, for a selection made elsewhere (the GPU's:
// gpu_chunk_selection.h).
terrain::LodView CascadeCasterView(const terrain::LodView& frame_view, const ShadowCascade& cascade);

}  // namespace aerial
