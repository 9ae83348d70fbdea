// CTest label "sanitizer": chunks built on other threads into the shared vertex buffer: run under the sanitizers too.
// The terrain chunk cache (src/aerial/render/terrain_chunk_cache.h): its eviction where a GPU's
// selection draws (the chunks it drew, TerrainChunkCache::Used, and their ancestors, which its
// walk from the root passes through, count as used; a slot emptied is filled again only after
// the frames in flight), and chunks built in the background.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <vector>

#include "aerial/render/terrain_chunk_cache.h"
#include "aerial/terrain/built_chunks.h"
#include "aerial/terrain/terrain_chunk.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

using terrain::ChunkId;

constexpr double kR = 6360e3;
constexpr uint32_t kFramesInFlight = 2;

class TerrainChunkCacheTest : public GpuTest {
 protected:
  void BeginFrame() {
    cache_.BeginFrame(0.0);
    ++frame_;
  }
  // The slots filled and emptied since the last call.
  void TakeChanges() {
    for (const TerrainChunkCache::SlotChange& change : cache_.TakeSlotChanges()) {
      if (change.info) {
        slot_of_[change.id] = change.slot;
        if (auto it = emptied_in_frame_.find(change.slot); it != emptied_in_frame_.end()) {
          EXPECT_GE(frame_, it->second + kFramesInFlight) << "slot " << change.slot << " filled again too soon";
        }
      } else {
        emptied_.push_back(change.id);
        emptied_in_frame_[change.slot] = frame_;
      }
    }
  }
  bool Emptied(const ChunkId& id) const { return std::find(emptied_.begin(), emptied_.end(), id) != emptied_.end(); }

  // 21 chunks (the root and two levels) fill all but 3 of its 24 slots; it empties one at a time.
  TerrainChunkCache cache_{SharedContext(), kR, 24, kFramesInFlight, &terrain::BuiltChunks::Shared(), true};
  uint64_t frame_ = 0;
  std::map<ChunkId, uint32_t> slot_of_;
  std::map<uint32_t, uint64_t> emptied_in_frame_;
  std::vector<ChunkId> emptied_;
};

std::vector<ChunkId> Level(int level) {
  std::vector<ChunkId> ids;
  for (int x = 0; x < (1 << level); ++x)
    for (int y = 0; y < (1 << level); ++y) ids.push_back({level, x, y});
  return ids;
}

// The GPU draws one chunk every frame and nothing is found on the CPU, while eight finer chunks
// need five slots of the full pool: those emptied are chunks not used since they were built,
// never the drawn one or its ancestors, and each is filled again only after the frames in flight.
TEST_F(TerrainChunkCacheTest, KeepsTheChunksTheGpuDrewAndTheirAncestors) {
  BeginFrame();
  for (int level = 0; level <= 2; ++level) cache_.Build(Level(level));
  TakeChanges();
  ASSERT_EQ(slot_of_.size(), 21u);
  // The drawn chunk and its ancestors are the least recently found: without the GPU's marks they
  // would be the first emptied.
  const ChunkId drawn{2, 1, 2};
  const std::vector<ChunkId> kept = {drawn, terrain::Parent(drawn), ChunkId{}};
  BeginFrame();
  for (const auto& [id, slot] : slot_of_)
    if (std::find(kept.begin(), kept.end(), id) == kept.end()) cache_.Find(id);
  for (int frame = 0; frame < 5; ++frame) {
    BeginFrame();
    cache_.Used(slot_of_.at(drawn));
  }
  std::vector<ChunkId> finer;
  for (const ChunkId& parent : {ChunkId{2, 0, 0}, ChunkId{2, 3, 3}})
    for (const ChunkId& child : terrain::Children(parent)) finer.push_back(child);
  int frames = 0;
  for (; frames < 20 && !std::all_of(finer.begin(), finer.end(), [&](const ChunkId& id) { return slot_of_.contains(id); });
       ++frames) {
    BeginFrame();
    cache_.Used(slot_of_.at(drawn));
    cache_.Build(finer);
    TakeChanges();
  }
  EXPECT_LT(frames, 20) << "the finer chunks were never all built";
  // Five slots, and while emptied ones wait out the frames in flight, a frame that finds none
  // free empties one more.
  EXPECT_GE(emptied_.size(), 5u);
  EXPECT_LE(emptied_.size(), 5u + kFramesInFlight);
  for (const ChunkId& id : kept) EXPECT_FALSE(Emptied(id)) << id.level << "/" << id.x << "/" << id.y;
}

// Chunks built in the background are found only once FinishBackgroundBuilds took them in, then with
// the vertices and the facts of the chunk built directly (not through the shared chunks the cache
// reads), each in a slot of its own.
TEST_F(TerrainChunkCacheTest, ChunksBuiltInTheBackgroundAreFoundOnceTakenIn) {
  BeginFrame();
  const std::vector<ChunkId> ids = Level(1);
  cache_.BuildInBackground(ids);
  for (const ChunkId& id : ids) EXPECT_EQ(cache_.Find(id), nullptr) << "found before it was taken in";
  EXPECT_TRUE(cache_.TakeSlotChanges().empty());
  cache_.FinishBackgroundBuilds();
  TakeChanges();
  EXPECT_EQ(slot_of_.size(), ids.size());
  EXPECT_EQ(cache_.built_this_frame(), int(ids.size()));
  for (const ChunkId& id : ids) {
    const terrain::TerrainChunk reference = terrain::BuildTerrainChunk(id, kR);
    const terrain::ChunkInfo* info = cache_.Find(id);
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->geometric_error_m, reference.geometric_error_m);
    EXPECT_EQ(info->bounds.min, reference.bounds.min);
    EXPECT_EQ(info->bounds.max, reference.bounds.max);
    const std::byte* slot = cache_.vertices().mapped() + size_t(cache_.VertexOffset(id)) * sizeof(Vertex);
    EXPECT_EQ(std::memcmp(slot, reference.vertices.data(), reference.vertices.size() * sizeof(Vertex)), 0);
  }
}

// A chunk asked of Build while it is being built in the background is waited for, not built twice
// (the batch it is in is taken in whole); a Build of other chunks leaves the batch running.
TEST_F(TerrainChunkCacheTest, BuildWaitsForTheBackgroundOnlyForAChunkItIsBuilding) {
  BeginFrame();
  const ChunkId a{1, 0, 0}, b{1, 1, 0}, c{1, 0, 1}, d{1, 1, 1};
  const std::vector<ChunkId> batch = {a, b};
  cache_.BuildInBackground(batch);
  cache_.Build(std::vector<ChunkId>{d});
  EXPECT_NE(cache_.Find(d), nullptr);
  EXPECT_EQ(cache_.Find(a), nullptr) << "a Build of other chunks took the batch in";
  cache_.Build(std::vector<ChunkId>{a, c});
  for (const ChunkId& id : {a, b, c, d}) EXPECT_NE(cache_.Find(id), nullptr) << id.x << "/" << id.y;
  TakeChanges();
  EXPECT_EQ(cache_.size(), 4u);
  std::vector<uint32_t> slots;
  for (const auto& [id, slot] : slot_of_) slots.push_back(slot);
  std::sort(slots.begin(), slots.end());
  EXPECT_EQ(slot_of_.size(), 4u);
  EXPECT_EQ(std::unique(slots.begin(), slots.end()), slots.end()) << "two chunks in one slot";
}

// The frame's selection and the shadow tiles' may ask for the same chunk in one batch: it is built
// once, in one slot.
TEST_F(TerrainChunkCacheTest, AChunkAskedForTwiceInOneCallIsBuiltOnce) {
  BeginFrame();
  const ChunkId a{1, 0, 0}, b{1, 1, 0}, c{1, 0, 1};
  cache_.BuildInBackground(std::vector<ChunkId>{a, b, a});
  cache_.FinishBackgroundBuilds();
  cache_.Build(std::vector<ChunkId>{c, c});
  TakeChanges();
  EXPECT_EQ(cache_.built_this_frame(), 3);
  EXPECT_EQ(cache_.size(), 3u);
  EXPECT_EQ(slot_of_.size(), 3u);
}

}  // namespace
}  // namespace aerial::testing
