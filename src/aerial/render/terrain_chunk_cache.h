#pragma once
// The terrain chunks on the GPU: a fixed pool of chunk-sized slots in one host-visible vertex
// buffer, and the index buffer every chunk shares. Chunks are built on the CPU when the LOD
// selection first asks for them (terrain/lod_selection.h), at once or, for a selection made on the
// GPU, in the background while the rendering thread records a frame, written into a free slot,
// and kept until the pool is full; then the chunks used longest ago go. A slot emptied is filled
// again only once every frame recorded before may have completed: a selection made on the GPU may
// draw any chunk the tree held when it was recorded. Chunks come from a BuiltChunks shared with
// other renderers if given one.
#include <chrono>
#include <exception>
#include <memory>
#include <optional>
#include <span>
#include <thread>
#include <unordered_map>
#include <utility>
#include <vector>

#include "aerial/terrain/built_chunks.h"
#include "aerial/terrain/lod_selection.h"
#include "aerial/vk/resources.h"

namespace aerial {

class TerrainChunkCache : public terrain::ChunkSource {
 public:
  // capacity: chunk slots (each kChunkVertices vertices); frames_in_flight: how many frames after
  // its last use a slot may still be read by the GPU; shared: where built chunks are found and kept
  // (null: each is built here).
  // log_slot_changes: keep the slots filled and emptied for TakeSlotChanges.
  TerrainChunkCache(const vk::Context& context, double planet_radius_m, uint32_t capacity,
                    uint32_t frames_in_flight, terrain::BuiltChunks* shared, bool log_slot_changes = false);

  // Starts a frame: building stops once budget_ms of building has been spent in it (0: no limit).
  void BeginFrame(double budget_ms);

  const terrain::ChunkInfo* Find(const terrain::ChunkId& id) override;
  // Builds the chunks not built yet on all cores, each into a free slot, until the frame's budget is
  // spent; first waits for those being built in the background if any of them is asked for.
  void Build(std::span<const terrain::ChunkId> ids) override;
  // Starts building the chunks on other threads, each into a slot taken now, and returns: the
  // rendering thread records its frame meanwhile, as engines stream their terrain. They are found
  // once FinishBackgroundBuilds took them in; a call first finishes the last call's.
  void BuildInBackground(std::span<const terrain::ChunkId> ids);
  // Waits for the chunks BuildInBackground started, and takes them in as Build would have.
  void FinishBackgroundBuilds();
  // The chunk in `slot`, and every chunk above it, was drawn by a selection made elsewhere (the
  // GPU's): it counts as used this frame, as Find would have made it.
  void Used(uint32_t slot);

  // A slot filled with a chunk (info set) or emptied, in the order they happened.
  struct SlotChange {
    uint32_t slot;
    terrain::ChunkId id;
    std::optional<terrain::ChunkInfo> info;
  };
  // The slot changes since the last call (with log_slot_changes).
  std::vector<SlotChange> TakeSlotChanges() { return std::exchange(slot_changes_, {}); }

  // The first vertex of a built chunk in vertices().
  int32_t VertexOffset(const terrain::ChunkId& id) const;
  const vk::Buffer& vertices() const { return vertices_; }
  const vk::Buffer& indices() const { return indices_; }  // terrain::ChunkIndices()

  int built_this_frame() const { return built_this_frame_; }
  size_t size() const { return chunks_.size(); }

 private:
  struct Entry {
    terrain::ChunkInfo info;
    uint32_t slot;
    uint64_t last_used;
  };
  // A chunk to build, the slot it goes in, and what it is once built (none: the budget ran out).
  struct Job {
    terrain::ChunkId id;
    uint32_t slot;
    std::optional<terrain::ChunkInfo> info;
  };
  struct BackgroundBuild {
    std::vector<Job> jobs;
    std::exception_ptr error;
    std::jthread thread;
  };
  using TimePoint = std::chrono::steady_clock::time_point;
  std::vector<Job> TakeSlotsFor(std::span<const terrain::ChunkId> ids);
  std::optional<TimePoint> Deadline() const;  // the frame's budget's end, if it has one
  void RunJobs(std::span<Job> jobs, std::optional<TimePoint> deadline) const;
  bool BuildingInBackground(const terrain::ChunkId& id) const;
  void TakeIn(std::span<const Job> jobs);
  std::optional<uint32_t> TakeSlot();
  void EmptyLeastUsed();
  void FoldDrawnSlots();  // Used's marks into the chunks' last_used, and their ancestors'
  void ReclaimEmptied();

  double planet_radius_m_;
  uint32_t capacity_, frames_in_flight_;
  terrain::BuiltChunks* shared_;
  bool log_slot_changes_;
  vk::Buffer vertices_, indices_;
  std::unordered_map<terrain::ChunkId, Entry, terrain::ChunkIdHash> chunks_;
  std::vector<terrain::ChunkId> id_in_slot_;
  std::vector<uint64_t> drawn_frame_;  // per slot, the last frame Used marked it in (0: none)
  std::vector<uint32_t> free_slots_;
  std::vector<std::pair<uint64_t, uint32_t>> emptied_slots_;  // (frame emptied, slot), oldest first
  std::vector<SlotChange> slot_changes_;
  uint64_t frame_ = 0;
  std::chrono::steady_clock::time_point deadline_;
  bool limited_ = false;
  int built_this_frame_ = 0;
  // Last, so that its thread, which writes into vertices_, is joined before anything else goes.
  std::unique_ptr<BackgroundBuild> background_;
};

}  // namespace aerial
