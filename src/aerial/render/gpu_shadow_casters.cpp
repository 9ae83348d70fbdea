#include "aerial/render/gpu_shadow_casters.h"

#include <algorithm>
#include <limits>

#include "aerial/render/shadow_terrain.h"

namespace aerial {
namespace {

// The GPU's slack is computed in single precision, from distances of up to about 100 km (a
// rounding of 8 mm each): so much less of it is trusted, lest a camera just within it pick other
// chunks there.
double TrustedSlackM(double gpu_slack_m) { return std::max(0.0, gpu_slack_m * (1.0 - 1e-5) - 0.05); }

}  // namespace

GpuShadowCasters::GpuShadowCasters(const vk::Context& context, uint32_t slots, uint32_t vertices_per_slot,
                                   uint32_t feedbacks) {
  for (int cascade = kFirstGpuCasterCascade; cascade < kShadowCascades; ++cascade)
    tiles_[cascade].selection = std::make_unique<GpuChunkSelection>(context, slots, vertices_per_slot, 0, feedbacks,
                                                                    /*occlusion_culling=*/false);
}

void GpuShadowCasters::Apply(const std::vector<TerrainChunkCache::SlotChange>& changes) {
  for (Tile& tile : tiles_) {
    if (!tile.selection) continue;
    for (const TerrainChunkCache::SlotChange& change : changes) {
      // Casters read no froxels: every chunk goes to the list that Draw records.
      if (change.info)
        tile.selection->Insert(change.slot, change.id, *change.info, std::numeric_limits<double>::infinity());
      else
        tile.selection->Remove(change.slot);
    }
  }
}

std::vector<terrain::ChunkId> GpuShadowCasters::ReadFeedback(uint32_t feedback, TerrainChunkCache& cache) {
  std::vector<terrain::ChunkId> requested;
  for (Tile& tile : tiles_) {
    if (!tile.selection) continue;
    GpuChunkSelection::Feedback read = tile.selection->ReadFeedback(feedback);
    if (read.generation <= tile.read_generation) continue;
    tile.read_generation = read.generation;
    for (uint32_t slot : read.drawn_slots) cache.Used(slot);
    requested.insert(requested.end(), read.requested.begin(), read.requested.end());
    if (read.generation != tile.drawn_generation || !tile.made) continue;
    tile.made->camera_slack_m = TrustedSlackM(read.camera_slack_m);
    tile.made->whole = read.deferred == 0;
    tile.read = true;
  }
  return requested;
}

bool GpuShadowCasters::Kept(int cascade, const terrain::LodView& frame_view, const ShadowCascade& now,
                            bool moved) const {
  const Tile& tile = tiles_.at(cascade);
  if (moved || !tile.made) return false;
  if (!tile.read) return true;
  return CastersKept(tile.made, frame_view, now, moved);
}

void GpuShadowCasters::Record(const vk::CommandBuffer& cmd, int cascade, const terrain::LodView& frame_view,
                              const ShadowCascade& now, uint32_t feedback, bool redrawn) {
  Tile& tile = tiles_.at(cascade);
  tile.selection->Record(cmd, CascadeCasterView(frame_view, now), feedback,
                         redrawn ? GpuChunkSelection::Compare::kRedrawn : GpuChunkSelection::Compare::kWithTheLast);
  tile.if_changed = !redrawn;
  tile.drawn_generation = tile.selection->generation();
  tile.made = CasterSelection{.camera = frame_view.camera,
                              .pixels_per_radian = frame_view.pixels_per_radian,
                              .max_error_px = frame_view.max_error_px,
                              .planes = now.planes};
  tile.read = false;
}

bool GpuShadowCasters::whole() const {
  return std::all_of(tiles_.begin(), tiles_.end(),
                     [](const Tile& t) { return !t.selection || (t.read && t.made->whole); });
}

void GpuShadowCasters::BeginIfChanged(const vk::CommandBuffer& cmd, int cascade) const {
  tiles_.at(cascade).selection->BeginIfChanged(cmd);
}

int GpuShadowCasters::Draw(const vk::CommandBuffer& cmd, int cascade) const {
  return tiles_.at(cascade).selection->Draw(cmd, true);
}

}  // namespace aerial
