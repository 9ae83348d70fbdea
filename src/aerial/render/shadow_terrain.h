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

// deferred: set to the number of chunks drawn in place of finer ones not built yet (a later call
// with the same view may then pick other chunks).
ShadowTerrain SelectShadowTerrain(const terrain::LodView& frame_view, const ShadowCascades& cascades,
                                  const LightBasis& basis, terrain::ChunkSource& source, int& deferred);

}  // namespace aerial
