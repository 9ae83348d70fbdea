#pragma once
// The shadow map's terrain casters selected by the GPU (TerrainSelector::kGpu): per cascade from
// kFirstGpuCasterCascade, a GpuChunkSelection over the chunk cache's slots for the cascade's view
// (CascadeCasterView), whose draws the tile records (ShadowMap::Record). A tile redrawn then costs
// the CPU a few commands, whatever the terrain it draws.
//
// The nearest cascade's casters stay with the CPU (SelectCascadeCasters). Its window is the
// smallest and nearest the camera, so a moving camera leaves the slack of its selection (a metre
// or a few) nearly every frame, and the GPU would select them again each frame: on lavapipe that
// selection with its redraw test cost the frame more than all the others (docs/speed.md). The
// tile also holds the fewest chunks (a handful), which the CPU selects and compares in
// microseconds.
//
// The CPU learns what a selection picked from its feedback only, once its frame has completed:
// how far the camera may move before it would pick other chunks (its camera slack) and whether
// it lacked any. Until then the tile keeps what it drew (unless its window moves); after, a
// camera within that slack keeps it, as with the CPU's selection (CastersKept). A tile whose
// casters are selected again is redrawn whole, and only if the GPU found them changed (drawn
// under conditional rendering: GpuChunkSelection::BeginIfChanged), unless it is redrawn anyway
// (its window moved). Their list stays on the GPU, so there is no region of changed casters to
// redraw alone (shadow_tile_region.h).
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "aerial/render/frame_cache_policy.h"
#include "aerial/render/gpu_chunk_selection.h"
#include "aerial/render/shadow_cascades.h"
#include "aerial/render/terrain_chunk_cache.h"

namespace aerial {

// The first cascade whose casters the GPU selects (see above).
inline constexpr int kFirstGpuCasterCascade = 1;

class GpuShadowCasters {
 public:
  // As GpuChunkSelection's; each tile's draws start at instance 0.
  GpuShadowCasters(const vk::Context& context, uint32_t slots, uint32_t vertices_per_slot, uint32_t feedbacks);
  static uint64_t MemoryBytes(uint32_t slots, uint32_t feedbacks) {
    return (kShadowCascades - kFirstGpuCasterCascade) * GpuChunkSelection::MemoryBytes(slots, feedbacks, false);
  }

  // Whether the GPU selects the casters of `cascade`.
  static bool Selects(int cascade) { return cascade >= kFirstGpuCasterCascade; }

  // The chunk cache's slot changes (TerrainChunkCache::TakeSlotChanges), for every tile's tree.
  void Apply(const std::vector<TerrainChunkCache::SlotChange>& changes);

  // Reads the feedbacks written with `feedback` (its frame has completed): the chunks drawn count
  // as used; returns those asked for, for the caller to build (and then Apply the cache's slot
  // changes).
  std::vector<terrain::ChunkId> ReadFeedback(uint32_t feedback, TerrainChunkCache& cache);

  // Whether the tile of `cascade` keeps its casters (see above); moved: its window moved.
  bool Kept(int cascade, const terrain::LodView& frame_view, const ShadowCascade& now, bool moved) const;

  // Records the selection of the casters of `cascade` for the frame's view, and its feedback's
  // copy. redrawn: the tile is redrawn whatever they are; else only if they changed (IfChanged).
  void Record(const vk::CommandBuffer& cmd, int cascade, const terrain::LodView& frame_view,
              const ShadowCascade& now, uint32_t feedback, bool redrawn);

  // Whether every tile whose casters it selects has them read back, lacking no chunk.
  bool whole() const;

  // Records the draws of the casters last selected for `cascade` (ShadowMap::Record).
  int Draw(const vk::CommandBuffer& cmd, int cascade) const;
  // Whether the last selection of the tile of `cascade` decides on the GPU if it is redrawn; if so,
  // its redraw goes between BeginIfChanged and cmd.endConditionalRenderingEXT().
  bool IfChanged(int cascade) const { return Selects(cascade) && tiles_.at(cascade).if_changed; }
  void BeginIfChanged(const vk::CommandBuffer& cmd, int cascade) const;

 private:
  struct Tile {
    std::unique_ptr<GpuChunkSelection> selection;  // none for the cascades the CPU selects
    uint32_t drawn_generation = 0;  // of the selection whose casters the tile holds
    uint32_t read_generation = 0;   // of the last feedback read
    // What the drawn casters were selected for; their slack and wholeness once read back.
    std::optional<CasterSelection> made;
    bool read = false;
    bool if_changed = false;
  };
  std::array<Tile, kShadowCascades> tiles_;
};

}  // namespace aerial
