#include "aerial/render/terrain_chunk_cache.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <thread>

#include "aerial/error.h"

namespace aerial {
namespace {

using terrain::ChunkId;
using terrain::kChunkVertices;

constexpr size_t kSlotBytes = kChunkVertices * sizeof(Vertex);

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
                                     uint32_t capacity, uint32_t frames_in_flight, terrain::BuiltChunks* shared)
    : planet_radius_m_(planet_radius_m),
      capacity_(capacity),
      frames_in_flight_(frames_in_flight),
      shared_(shared),
      vertices_(context, {.size = capacity * kSlotBytes,
                          .usage = ::vk::BufferUsageFlagBits::eVertexBuffer,
                          .host_visible = true}),
      indices_(IndexBuffer(context)) {
  for (uint32_t slot = capacity; slot > 0; --slot) free_slots_.push_back(slot - 1);
}

void TerrainChunkCache::BeginFrame(double budget_ms) {
  ++frame_;
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

// A free slot, or the slot of the chunk used longest ago if no frame in flight can still draw it.
std::optional<uint32_t> TerrainChunkCache::TakeSlot() {
  if (!free_slots_.empty()) {
    uint32_t slot = free_slots_.back();
    free_slots_.pop_back();
    return slot;
  }
  auto oldest = std::min_element(chunks_.begin(), chunks_.end(), [](const auto& a, const auto& b) {
    return a.second.last_used < b.second.last_used;
  });
  if (oldest == chunks_.end() || oldest->second.last_used + frames_in_flight_ >= frame_) return std::nullopt;
  uint32_t slot = oldest->second.slot;
  chunks_.erase(oldest);
  return slot;
}

// Chunks are built on all cores: each thread takes the next chunk until none is left or the
// frame's budget is spent, and writes it straight into its slot (slots are disjoint).
void TerrainChunkCache::Build(std::span<const ChunkId> ids) {
  std::vector<std::pair<ChunkId, uint32_t>> work;
  for (const ChunkId& id : ids) {
    if (chunks_.count(id)) continue;
    std::optional<uint32_t> slot = TakeSlot();
    if (!slot) break;  // the pool is full of chunks in use: the rest waits for a later frame
    work.push_back({id, *slot});
  }
  if (work.empty()) return;
  std::vector<std::optional<terrain::ChunkInfo>> infos(work.size());
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < work.size(); i = next++) {
      if (limited_ && std::chrono::steady_clock::now() > deadline_) return;
      std::shared_ptr<const terrain::TerrainChunk> chunk =
          shared_ ? shared_->Get(work[i].first, planet_radius_m_)
                  : std::make_shared<const terrain::TerrainChunk>(
                        terrain::BuildTerrainChunk(work[i].first, planet_radius_m_));
      std::memcpy(vertices_.mapped() + work[i].second * kSlotBytes, chunk->vertices.data(), kSlotBytes);
      infos[i] = terrain::InfoOf(*chunk);
    }
  };
  unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, unsigned(work.size()));
  std::vector<std::jthread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  pool.clear();  // joins
  for (size_t i = 0; i < work.size(); ++i) {
    if (infos[i]) {
      chunks_[work[i].first] = {*infos[i], work[i].second, frame_};
      ++built_this_frame_;
    } else {
      free_slots_.push_back(work[i].second);
    }
  }
}

int32_t TerrainChunkCache::VertexOffset(const ChunkId& id) const {
  auto it = chunks_.find(id);
  if (it == chunks_.end())
    throw Error("terrain chunk", std::to_string(id.level) + "/" + std::to_string(id.x) + "/" +
                                     std::to_string(id.y), "a built chunk");
  return int32_t(it->second.slot * kChunkVertices);
}

}  // namespace aerial
