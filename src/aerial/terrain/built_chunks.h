#pragma once
// Built terrain chunks shared by the renderers of a process. A chunk is a pure function of its id
// and the planet's radius, and the tools that make many renderers of one terrain (a benchmark's
// accuracy phase, a test suite, a viewer that remakes its renderer when a setting changes) would
// otherwise build every chunk again in each. Thread-safe; keeps up to its capacity of chunks,
// dropping those asked for longest ago.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <unordered_map>

#include "aerial/terrain/terrain_chunk.h"

namespace aerial::terrain {

class BuiltChunks {
 public:
  explicit BuiltChunks(size_t capacity);

  // The process's own: kSharedCapacity chunks (about 5 KB each, 20 MB in all), a few views' worth
  // at 720p (a view draws and walks through 500-900).
  static constexpr size_t kSharedCapacity = 4096;
  static BuiltChunks& Shared();

  // The chunk, built by this call (outside the lock, so threads build different chunks at once)
  // if no earlier call kept it.
  std::shared_ptr<const TerrainChunk> Get(const ChunkId& id, double planet_radius_m);

  size_t size() const;
  size_t capacity() const { return capacity_; }

 private:
  struct Key {
    ChunkId id;
    double planet_radius_m;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    size_t operator()(const Key& k) const;
  };
  struct Entry {
    std::shared_ptr<const TerrainChunk> chunk;
    uint64_t last_asked;
  };
  // Drops the quarter of the chunks asked for longest ago (under the lock).
  void Trim();

  const size_t capacity_;
  mutable std::mutex mutex_;
  std::unordered_map<Key, Entry, KeyHash> chunks_;
  uint64_t clock_ = 0;
};

}  // namespace aerial::terrain
