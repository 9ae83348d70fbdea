#include "aerial/terrain/built_chunks.h"

#include <gtest/gtest.h>

#include <cstring>
#include <thread>
#include <vector>

namespace aerial::terrain {
namespace {

constexpr double kR = 6360e3;  // the default atmosphere's bottom radius

bool SameVertices(const TerrainChunk& a, const TerrainChunk& b) {
  return a.vertices.size() == b.vertices.size() &&
         std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vertex)) == 0;
}

// A kept chunk is the chunk BuildTerrainChunk builds, to the bit, and is handed out again.
TEST(BuiltChunks, KeepsTheChunkThatWasBuilt) {
  BuiltChunks chunks(8);
  const ChunkId id{9, 250, 281};
  std::shared_ptr<const TerrainChunk> first = chunks.Get(id, kR);
  EXPECT_TRUE(SameVertices(*first, BuildTerrainChunk(id, kR)));
  EXPECT_EQ(first->geometric_error_m, BuildTerrainChunk(id, kR).geometric_error_m);
  EXPECT_EQ(chunks.Get(id, kR), first);
  EXPECT_EQ(chunks.size(), 1u);
}

// The planet's radius is part of what a chunk is: another radius builds another chunk.
TEST(BuiltChunks, TellsPlanetsApart) {
  BuiltChunks chunks(8);
  const ChunkId id{3, 6, 7};
  std::shared_ptr<const TerrainChunk> earth = chunks.Get(id, kR);
  std::shared_ptr<const TerrainChunk> smaller = chunks.Get(id, 3390e3);
  EXPECT_NE(earth, smaller);
  EXPECT_FALSE(SameVertices(*earth, *smaller));
  EXPECT_EQ(chunks.size(), 2u);
}

// Past its capacity it drops the chunks asked for longest ago, and keeps the one just asked for
// and those asked for again since.
TEST(BuiltChunks, DropsTheChunksAskedForLongestAgo) {
  BuiltChunks chunks(8);
  for (int x = 0; x < 8; ++x) chunks.Get({13, 4096 + x, 4096}, kR);
  std::shared_ptr<const TerrainChunk> asked_again = chunks.Get({13, 4096, 4096}, kR);
  std::shared_ptr<const TerrainChunk> newest = chunks.Get({13, 4200, 4096}, kR);
  // Nine chunks for eight: the trim keeps the newest six.
  EXPECT_EQ(chunks.size(), 6u);
  EXPECT_EQ(chunks.Get({13, 4096, 4096}, kR), asked_again);
  EXPECT_EQ(chunks.Get({13, 4200, 4096}, kR), newest);
  EXPECT_EQ(chunks.size(), 6u);
  // The oldest unasked one was dropped: asking builds it again.
  chunks.Get({13, 4097, 4096}, kR);
  EXPECT_EQ(chunks.size(), 7u);
}

// Threads asking for the same chunks at once all get equal chunks, one kept per id.
TEST(BuiltChunks, ThreadsShareOneChunkPerId) {
  BuiltChunks chunks(64);
  std::vector<std::shared_ptr<const TerrainChunk>> got(4 * 8);
  {
    std::vector<std::jthread> threads;
    for (int t = 0; t < 4; ++t)
      threads.emplace_back([&, t] {
        for (int x = 0; x < 8; ++x) got[size_t(t * 8 + x)] = chunks.Get({12, 2048 + x, 2048}, kR);
      });
  }
  EXPECT_EQ(chunks.size(), 8u);
  for (int t = 1; t < 4; ++t)
    for (int x = 0; x < 8; ++x) EXPECT_TRUE(SameVertices(*got[size_t(t * 8 + x)], *got[size_t(x)]));
}

}  // namespace
}  // namespace aerial::terrain
