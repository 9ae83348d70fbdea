#include "aerial/render/shadow_terrain.h"

#include <gtest/gtest.h>

#include <map>

namespace aerial {
namespace {

using terrain::ChunkId;
using terrain::SelectedChunk;

// Chunks whose geometric error halves with each level from 64 m at the root, all built.
class HalvingErrors : public terrain::ChunkSource {
 public:
  const terrain::ChunkInfo* Find(const ChunkId& id) override {
    terrain::ChunkInfo& info = infos_[id];
    info.geometric_error_m = 64.0 / double(1 << id.level);
    return &info;
  }
  void Build(std::span<const ChunkId>) override {}

 private:
  std::map<ChunkId, terrain::ChunkInfo> infos_;
};

std::vector<SelectedChunk> Selection(std::initializer_list<ChunkId> ids) {
  std::vector<SelectedChunk> chunks;
  for (const ChunkId& id : ids) chunks.push_back({id});
  return chunks;
}

// With a tolerance of 4 m (the error of level 4), chunks of levels 5 and 6 become their level-4
// ancestors, each listed once; chunks at level 4 or coarser stay as they are.
TEST(CoarsenCasters, ChunksBecomeTheirCoarsestAncestorWithinTheTolerance) {
  HalvingErrors source;
  auto casters = CoarsenCasters(Selection({{6, 40, 12}, {6, 41, 13}, {5, 21, 7}, {4, 3, 3}, {2, 0, 0}}), 4.0, source);
  std::vector<ChunkId> ids;
  for (const SelectedChunk& c : casters) ids.push_back(c.id);
  EXPECT_EQ(ids, (std::vector<ChunkId>{{2, 0, 0}, {4, 3, 3}, {4, 10, 3}})) << "sorted, each once";
  // A finer tolerance keeps the level-5 chunk and merges the two level-6 ones into it.
  casters = CoarsenCasters(Selection({{6, 40, 12}, {6, 41, 13}, {5, 21, 7}}), 2.0, source);
  ASSERT_EQ(casters.size(), 2u);
  EXPECT_EQ(casters[0].id, (ChunkId{5, 20, 6}));
  EXPECT_EQ(casters[1].id, (ChunkId{5, 21, 7}));
  // A tolerance below every error changes nothing.
  EXPECT_EQ(CoarsenCasters(Selection({{6, 40, 12}}), 0.5, source).front().id, (ChunkId{6, 40, 12}));
}

// The coarsened list gets the skirts of its own neighbours: two chunks side by side at the same
// level need none on the side they share, every other side keeps one.
TEST(CoarsenCasters, SkirtsFollowTheCoarsenedNeighbours) {
  HalvingErrors source;
  auto casters = CoarsenCasters(Selection({{6, 40, 12}, {6, 42, 12}}), 4.0, source);  // -> (4,10,3), (4,10,3)
  ASSERT_EQ(casters.size(), 1u);
  EXPECT_EQ(casters[0].skirts, terrain::kAllSides);
  casters = CoarsenCasters(Selection({{6, 40, 12}, {6, 44, 12}}), 4.0, source);  // -> (4,10,3), (4,11,3)
  ASSERT_EQ(casters.size(), 2u);
  EXPECT_EQ(casters[0].skirts, terrain::kAllSides & ~uint32_t(terrain::kEast));
  EXPECT_EQ(casters[1].skirts, terrain::kAllSides & ~uint32_t(terrain::kWest));
}

}  // namespace
}  // namespace aerial
