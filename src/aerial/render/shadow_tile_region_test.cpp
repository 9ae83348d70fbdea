#include "aerial/render/shadow_tile_region.h"

#include <gtest/gtest.h>

#include <map>

namespace aerial {
namespace {

using terrain::ChunkId;
using terrain::SelectedChunk;

constexpr int kTile = 1024;

// A cascade whose tile spans x and y from -1000 to 1000 m of the scene frame: 512 texels a km,
// the scene's x along the tile's x and its y along the tile's y.
ShadowCascade Cascade() {
  ShadowCascade cascade;
  cascade.clip_from_world = glm::dmat4(1.0);
  cascade.clip_from_world[0][0] = 1e-3;
  cascade.clip_from_world[1][1] = 1e-3;
  return cascade;
}

// Chunks of given bounds; the others unknown (not built).
class KnownChunks : public terrain::ChunkSource {
 public:
  explicit KnownChunks(std::map<ChunkId, terrain::Bounds> bounds) {
    for (const auto& [id, b] : bounds) infos_[id].bounds = b;
  }
  const terrain::ChunkInfo* Find(const ChunkId& id) override {
    auto it = infos_.find(id);
    return it == infos_.end() ? nullptr : &it->second;
  }
  void Build(std::span<const ChunkId>) override {}

 private:
  std::map<ChunkId, terrain::ChunkInfo> infos_;
};

// A 100 m square chunk from (x, y) up, 0-300 m high.
terrain::Bounds Square(double x, double y) { return {{x, y, 0.0}, {x + 100.0, y + 100.0, 300.0}}; }

const ChunkId kA{5, 0, 0}, kB{5, 1, 0}, kC{5, 2, 0}, kFar{5, 3, 0}, kUnbuilt{5, 4, 0};

KnownChunks Chunks() {
  return KnownChunks({{kA, Square(-900.0, -900.0)},
                      {kB, Square(0.0, 0.0)},
                      {kC, Square(100.0, 0.0)},
                      {kFar, Square(800.0, 800.0)}});
}

TEST(ShadowTileRegion, ABoxCoversTheTexelsOfItsCornersAndOneMore) {
  // x from 0 to 100 m: texels 512 to 563.2, widened to [511, 565).
  EXPECT_EQ(BoxTexels(Cascade(), kTile, Square(0.0, 0.0)), (TileTexels{{511, 511}, {565, 565}}));
  // Outside the tile: nothing; across its edge: up to it.
  EXPECT_TRUE(BoxTexels(Cascade(), kTile, Square(1500.0, 0.0)).Empty());
  EXPECT_EQ(BoxTexels(Cascade(), kTile, Square(950.0, -1050.0)), (TileTexels{{997, 0}, {kTile, 27}}));
}

TEST(ShadowTileRegion, OnlyTheChunksThatChangedAreRedrawn) {
  KnownChunks chunks = Chunks();
  const std::vector<SelectedChunk> drawn = {{kA}, {kB}};
  // B replaced by C: both their squares, not A's.
  std::optional<TileTexels> region = ChangedCastersTexels(Cascade(), kTile, drawn, {{kA}, {kC}}, chunks);
  ASSERT_TRUE(region.has_value());
  EXPECT_EQ(*region, (TileTexels{{511, 511}, {616, 565}}));
  EXPECT_FALSE(region->Overlaps(BoxTexels(Cascade(), kTile, Square(-900.0, -900.0))));
  // The same chunks: nothing; one with other skirts: its square.
  region = ChangedCastersTexels(Cascade(), kTile, drawn, drawn, chunks);
  ASSERT_TRUE(region.has_value());
  EXPECT_TRUE(region->Empty());
  region = ChangedCastersTexels(Cascade(), kTile, drawn, {{kA}, {kB, terrain::kNorth}}, chunks);
  ASSERT_TRUE(region.has_value());
  EXPECT_EQ(*region, BoxTexels(Cascade(), kTile, Square(0.0, 0.0)));
}

TEST(ShadowTileRegion, UnknownOrScatteredChangesRedrawTheWholeTile) {
  KnownChunks chunks = Chunks();
  // An unbuilt chunk's bounds are not known.
  EXPECT_FALSE(ChangedCastersTexels(Cascade(), kTile, {{kA}}, {{kA}, {kUnbuilt}}, chunks).has_value());
  // A and the far chunk changed together: their rectangle spans 81% of the tile.
  EXPECT_FALSE(ChangedCastersTexels(Cascade(), kTile, {{kB}}, {{kA}, {kB}, {kFar}}, chunks).has_value());
}

TEST(ShadowTileRegion, TheCastersDrawnAreThoseThatReachTheRegion) {
  KnownChunks chunks = Chunks();
  const TileTexels around_b = BoxTexels(Cascade(), kTile, Square(0.0, 0.0));
  const std::vector<SelectedChunk> reaching =
      CastersReaching(Cascade(), kTile, {{kA}, {kB}, {kC}, {kFar}, {kUnbuilt}}, around_b, chunks);
  // C shares B's edge (and the texel of widening); an unknown chunk is drawn to be safe.
  ASSERT_EQ(reaching.size(), 3u);
  EXPECT_EQ(reaching[0].id, kB);
  EXPECT_EQ(reaching[1].id, kC);
  EXPECT_EQ(reaching[2].id, kUnbuilt);
}

}  // namespace
}  // namespace aerial
