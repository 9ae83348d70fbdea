#include "aerial/terrain/built_chunks.h"

#include <algorithm>
#include <bit>
#include <vector>

namespace aerial::terrain {

BuiltChunks::BuiltChunks(size_t capacity) : capacity_(std::max<size_t>(capacity, 1)) {}

BuiltChunks& BuiltChunks::Shared() {
  static BuiltChunks shared(kSharedCapacity);
  return shared;
}

size_t BuiltChunks::KeyHash::operator()(const Key& k) const {
  return ChunkIdHash{}(k.id) ^ (std::hash<uint64_t>{}(std::bit_cast<uint64_t>(k.planet_radius_m)) << 1);
}

std::shared_ptr<const TerrainChunk> BuiltChunks::Get(const ChunkId& id, double planet_radius_m) {
  const Key key{id, planet_radius_m};
  {
    std::lock_guard lock(mutex_);
    auto it = chunks_.find(key);
    if (it != chunks_.end()) {
      it->second.last_asked = ++clock_;
      return it->second.chunk;
    }
  }
  auto chunk = std::make_shared<const TerrainChunk>(BuildTerrainChunk(id, planet_radius_m));
  std::lock_guard lock(mutex_);
  // Another thread may have built it meanwhile: the chunks are equal, and the first one stays.
  auto [it, inserted] = chunks_.try_emplace(key, Entry{chunk, 0});
  it->second.last_asked = ++clock_;
  if (inserted && chunks_.size() > capacity_) Trim();
  return it->second.chunk;
}

void BuiltChunks::Trim() {
  std::vector<uint64_t> asked;
  asked.reserve(chunks_.size());
  for (const auto& [key, entry] : chunks_) asked.push_back(entry.last_asked);
  // Keep three quarters of the capacity, so that trimming is rare: the newest ones.
  const size_t keep = std::max<size_t>(capacity_ - capacity_ / 4, 1);
  auto cut = asked.end() - std::ptrdiff_t(keep);
  std::nth_element(asked.begin(), cut, asked.end());
  const uint64_t oldest_kept = *cut;
  std::erase_if(chunks_, [&](const auto& item) { return item.second.last_asked < oldest_kept; });
}

size_t BuiltChunks::size() const {
  std::lock_guard lock(mutex_);
  return chunks_.size();
}

}  // namespace aerial::terrain
