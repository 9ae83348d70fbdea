#include "aerial/render/terrain_chunk_cache.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <exception>
#include <thread>
#include <unordered_set>

#include <sys/resource.h>
#include <unistd.h>

#include "aerial/error.h"

namespace aerial {
namespace {

using terrain::ChunkId;
using terrain::kChunkVertices;

constexpr size_t kSlotBytes = kChunkVertices * sizeof(Vertex);
constexpr int kBackgroundNice = 19;

vk::Buffer IndexBuffer(const vk::Context& context) {
  const std::vector<uint32_t>& indices = terrain::ChunkIndices();
  vk::Buffer buffer(context, {.size = indices.size() * sizeof(uint32_t),
                              .usage = ::vk::BufferUsageFlagBits::eIndexBuffer,
                              .host_visible = true});
  buffer.Write(std::as_bytes(std::span(indices)));
  return buffer;
}

}  // namespace

TerrainChunkCache::TerrainChunkCache(const vk::Context& context, double planet_radius_m,
                                     uint32_t capacity, uint32_t frames_in_flight, terrain::BuiltChunks* shared,
                                     bool log_slot_changes)
    : planet_radius_m_(planet_radius_m),
      capacity_(capacity),
      frames_in_flight_(frames_in_flight),
      shared_(shared),
      log_slot_changes_(log_slot_changes),
      vertices_(context, {.size = capacity * kSlotBytes,
                          .usage = ::vk::BufferUsageFlagBits::eVertexBuffer,
                          .host_visible = true}),
      indices_(IndexBuffer(context)),
      id_in_slot_(capacity),
      drawn_frame_(capacity, 0) {
  for (uint32_t slot = capacity; slot > 0; --slot) free_slots_.push_back(slot - 1);
}

void TerrainChunkCache::BeginFrame(double budget_ms) {
  ++frame_;
  ReclaimEmptied();
  built_this_frame_ = 0;
  limited_ = budget_ms > 0.0;
  deadline_ = std::chrono::steady_clock::now() +
              std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                  std::chrono::duration<double, std::milli>(budget_ms));
}

const terrain::ChunkInfo* TerrainChunkCache::Find(const ChunkId& id) {
  auto it = chunks_.find(id);
  if (it == chunks_.end()) return nullptr;
  it->second.last_used = frame_;
  return &it->second.info;
}

// Thousands of slots a frame (a far shadow tile's casters): only noted here, by slot, and folded
// into the chunks and their ancestors when slots are to be emptied (FoldDrawnSlots), which is rare.
void TerrainChunkCache::Used(uint32_t slot) { drawn_frame_.at(slot) = frame_; }

void TerrainChunkCache::FoldDrawnSlots() {
  for (auto& [id, entry] : chunks_) {
    const uint64_t drawn = drawn_frame_[entry.slot];
    if (drawn <= entry.last_used) continue;
    entry.last_used = drawn;
    // Up to the first ancestor used as late: those above it are too.
    for (ChunkId above = id; above.level > 0;) {
      above = terrain::Parent(above);
      auto it = chunks_.find(above);
      if (it == chunks_.end() || it->second.last_used >= drawn) break;
      it->second.last_used = drawn;
    }
  }
}

// The slots emptied may be filled again once no frame recorded before can draw their chunks: at
// once where only the CPU's selections draw (they draw only chunks they found, and no chunk found
// by a frame in flight is emptied); with a log for a GPU's tree, after frames_in_flight frames.
void TerrainChunkCache::ReclaimEmptied() {
  const uint64_t delay = log_slot_changes_ ? frames_in_flight_ : 0;
  size_t reclaimed = 0;
  while (reclaimed < emptied_slots_.size() && emptied_slots_[reclaimed].first + delay <= frame_)
    free_slots_.push_back(emptied_slots_[reclaimed++].second);
  emptied_slots_.erase(emptied_slots_.begin(), emptied_slots_.begin() + ptrdiff_t(reclaimed));
}

// Empties the slots of the chunks used longest ago, a sixteenth of the pool at a time (one pass
// over the pool for many slots), none that a frame in flight found.
void TerrainChunkCache::EmptyLeastUsed() {
  FoldDrawnSlots();
  std::vector<std::pair<uint64_t, ChunkId>> unused;
  for (const auto& [id, entry] : chunks_)
    if (entry.last_used + frames_in_flight_ < frame_) unused.push_back({entry.last_used, id});
  const size_t count = std::min(unused.size(), size_t(std::max(1u, capacity_ / 16)));
  std::nth_element(unused.begin(), unused.begin() + ptrdiff_t(count), unused.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (size_t i = 0; i < count; ++i) {
    auto it = chunks_.find(unused[i].second);
    emptied_slots_.push_back({frame_, it->second.slot});
    if (log_slot_changes_) slot_changes_.push_back({it->second.slot, it->first, std::nullopt});
    chunks_.erase(it);
  }
  ReclaimEmptied();
}

// A free slot, if there is one or the pool has chunks to spare.
std::optional<uint32_t> TerrainChunkCache::TakeSlot() {
  if (free_slots_.empty()) EmptyLeastUsed();
  if (free_slots_.empty()) return std::nullopt;
  uint32_t slot = free_slots_.back();
  free_slots_.pop_back();
  return slot;
}

std::vector<TerrainChunkCache::Job> TerrainChunkCache::TakeSlotsFor(std::span<const ChunkId> ids) {
  std::vector<Job> jobs;
  std::unordered_set<ChunkId, terrain::ChunkIdHash> taken;
  for (const ChunkId& id : ids) {
    if (chunks_.count(id) || !taken.insert(id).second) continue;
    std::optional<uint32_t> slot = TakeSlot();
    if (!slot) break;  // the pool is full of chunks in use: the rest waits for a later frame
    jobs.push_back({id, *slot});
  }
  return jobs;
}

std::optional<TerrainChunkCache::TimePoint> TerrainChunkCache::Deadline() const {
  if (!limited_) return std::nullopt;
  return deadline_;
}

// On all cores: each thread takes the next job until none is left or the deadline has passed,
// and writes its chunk straight into the job's slot (slots are disjoint). It touches nothing else
// of the cache, so it may run beside the rendering thread.
void TerrainChunkCache::RunJobs(std::span<Job> jobs, std::optional<TimePoint> deadline) const {
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < jobs.size(); i = next++) {
      if (deadline && std::chrono::steady_clock::now() > *deadline) return;
      std::shared_ptr<const terrain::TerrainChunk> chunk =
          shared_ ? shared_->Get(jobs[i].id, planet_radius_m_)
                  : std::make_shared<const terrain::TerrainChunk>(
                        terrain::BuildTerrainChunk(jobs[i].id, planet_radius_m_));
      std::memcpy(vertices_.mapped() + jobs[i].slot * kSlotBytes, chunk->vertices.data(), kSlotBytes);
      jobs[i].info = terrain::InfoOf(*chunk);
    }
  };
  unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, unsigned(jobs.size()));
  std::vector<std::jthread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
}

void TerrainChunkCache::TakeIn(std::span<const Job> jobs) {
  for (const Job& job : jobs) {
    if (job.info) {
      chunks_[job.id] = {*job.info, job.slot, frame_};
      id_in_slot_[job.slot] = job.id;
      if (log_slot_changes_) slot_changes_.push_back({job.slot, job.id, job.info});
      ++built_this_frame_;
    } else {
      free_slots_.push_back(job.slot);
    }
  }
}

bool TerrainChunkCache::BuildingInBackground(const ChunkId& id) const {
  return background_ &&
         std::any_of(background_->jobs.begin(), background_->jobs.end(), [&](const Job& job) { return job.id == id; });
}

void TerrainChunkCache::Build(std::span<const ChunkId> ids) {
  if (std::any_of(ids.begin(), ids.end(), [&](const ChunkId& id) { return BuildingInBackground(id); }))
    FinishBackgroundBuilds();
  std::vector<Job> jobs = TakeSlotsFor(ids);
  if (jobs.empty()) return;
  RunJobs(jobs, Deadline());
  TakeIn(jobs);
}

void TerrainChunkCache::BuildInBackground(std::span<const ChunkId> ids) {
  FinishBackgroundBuilds();
  std::vector<Job> jobs = TakeSlotsFor(ids);
  if (jobs.empty()) return;
  background_ = std::make_unique<BackgroundBuild>(BackgroundBuild{.jobs = std::move(jobs)});
  background_->thread = std::jthread([this, build = background_.get(), deadline = Deadline()] {
    // The least priority, for this thread and the ones it starts: the rendering thread comes first.
    setpriority(PRIO_PROCESS, gettid(), kBackgroundNice);
    try {
      RunJobs(build->jobs, deadline);
    } catch (...) {
      build->error = std::current_exception();
    }
  });
}

void TerrainChunkCache::FinishBackgroundBuilds() {
  if (!background_) return;
  background_->thread.join();
  const std::unique_ptr<BackgroundBuild> done = std::move(background_);
  TakeIn(done->jobs);  // the chunks built before an error, and the other slots back to the pool
  if (done->error) std::rethrow_exception(done->error);
}

int32_t TerrainChunkCache::VertexOffset(const ChunkId& id) const {
  auto it = chunks_.find(id);
  if (it == chunks_.end())
    throw Error("terrain chunk", std::to_string(id.level) + "/" + std::to_string(id.x) + "/" +
                                     std::to_string(id.y), "a built chunk");
  return int32_t(it->second.slot * kChunkVertices);
}

}  // namespace aerial
