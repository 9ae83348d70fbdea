#pragma once
// Where a shadow tile whose window held must be redrawn when its terrain casters changed: only
// the texels that the chunks it drew and the chunks it now selects can cover. As the camera
// moves, a cascade's casters change where the frame's level of detail switches a chunk's level
// (shadow_terrain.h), a few dozen chunks of the last tile's thousand, together 0.1-3% of its
// texels (17% at most in the third tile) in the corridor flight (examples/paths/corridor.toml).
// The depth a texel holds is the nearest of the casters over it, whatever order they are drawn
// in, so clearing those texels and drawing every caster that reaches them leaves the tile as a
// whole redraw would (to the float rounding of the camera-relative positions the draws take).
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "aerial/render/shadow_cascades.h"
#include "aerial/terrain/lod_selection.h"

namespace aerial {

// A rectangle of a tile's texels: [min, max) along each axis, from the tile's corner.
struct TileTexels {
  glm::ivec2 min{0}, max{0};
  bool Empty() const { return max.x <= min.x || max.y <= min.y; }
  bool Overlaps(const TileTexels& other) const;
  bool operator==(const TileTexels&) const = default;
};
TileTexels WholeTile(int tile_texels);

// The texels a box of the scene frame can cover in a cascade's tile: its corners' bounding
// rectangle, widened by a texel (a triangle covers a texel whose centre it holds), within the tile.
TileTexels BoxTexels(const ShadowCascade& cascade, int tile_texels, const terrain::Bounds& box);

// Above this fraction of the tile, the tile is redrawn whole: the region would then cost about as
// much and save the culling.
inline constexpr double kWholeTileRedrawFraction = 0.5;

// The texels to redraw for casters that changed from `drawn` to `selected` (both sorted by id, as
// SelectCascadeCasters returns them): those of every chunk in one list and not the other, or in
// both with other skirts. nullopt: the whole tile (a chunk's bounds are unknown to `source`, or
// the region is over kWholeTileRedrawFraction of the tile). An empty rectangle: nothing changed.
std::optional<TileTexels> ChangedCastersTexels(const ShadowCascade& cascade, int tile_texels,
                                               const std::vector<terrain::SelectedChunk>& drawn,
                                               const std::vector<terrain::SelectedChunk>& selected,
                                               terrain::ChunkSource& source);

// The casters whose bounds reach into `region` (all those whose bounds are unknown).
std::vector<terrain::SelectedChunk> CastersReaching(const ShadowCascade& cascade, int tile_texels,
                                                    const std::vector<terrain::SelectedChunk>& casters,
                                                    const TileTexels& region, terrain::ChunkSource& source);

}  // namespace aerial
