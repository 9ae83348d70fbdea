#include "aerial/render/shadow_terrain.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "aerial/terrain/chunk_id.h"

namespace aerial {
namespace {

using terrain::ChunkId;
using terrain::SelectedChunk;

// Chunks 100 m tall over their footprint, whose geometric error halves with each level from 64 m
// at the root, all built.
class HalvingErrors : public terrain::ChunkSource {
 public:
  const terrain::ChunkInfo* Find(const ChunkId& id) override {
    terrain::ChunkInfo& info = infos_[id];
    info.geometric_error_m = 64.0 / double(1 << id.level);
    terrain::Footprint f = terrain::FootprintOf(id);
    info.bounds = {{f.x0, f.y0, 0.0}, {f.x0 + f.size, f.y0 + f.size, 100.0}};
    return &info;
  }
  void Build(std::span<const ChunkId>) override {}

 private:
  std::map<ChunkId, terrain::ChunkInfo> infos_;
};

// A camera 250 m over the middle of the terrain (150 m over its chunks), its rule at 4 px; every cascade's box holds the
// whole terrain, the cascades differing only in their texel.
terrain::LodView View() {
  terrain::LodView view;
  view.camera = {0.0, 0.0, 250.0};
  view.planet_radius_m = 6360e3;
  view.pixels_per_radian = 1000.0;
  view.max_error_px = 4.0;
  return view;
}
ShadowCascades WholeTerrainCascades(std::array<double, kShadowCascades> texel_m) {
  ShadowCascades cascades;
  for (int i = 0; i < kShadowCascades; ++i) {
    cascades[i].texel_m = texel_m[i];
    cascades[i].planes.fill(glm::dvec4(0.0, 0.0, 0.0, 1.0));  // every point inside
  }
  return cascades;
}

std::vector<ChunkId> Ids(const std::vector<SelectedChunk>& chunks) {
  std::vector<ChunkId> ids;
  for (const SelectedChunk& c : chunks) ids.push_back(c.id);
  return ids;
}

// Each chunk replaced by its coarsest ancestor whose error is within the tolerance: walked up
// from the chunk, independently of the selection's walk down.
std::vector<ChunkId> Coarsened(const std::vector<SelectedChunk>& chunks, double tolerance_m,
                               terrain::ChunkSource& source) {
  std::set<ChunkId> coarse;
  for (const SelectedChunk& chunk : chunks) {
    ChunkId id = chunk.id;
    while (id.level > 0 && source.Find(terrain::Parent(id))->geometric_error_m <= tolerance_m) id = terrain::Parent(id);
    coarse.insert(id);
  }
  return {coarse.begin(), coarse.end()};
}

// A texel of 16 m resolves 4 m, the error of level 4: the rule's chunks of levels 5 and finer
// become their level-4 ancestors, each listed once, and those at level 4 or coarser stay. A texel
// of 0 resolves nothing, so that cascade draws the rule's own chunks.
// Every cascade's casters, selected one by one.
ShadowTerrain SelectAll(const ShadowCascades& cascades, terrain::ChunkSource& source) {
  ShadowTerrain chunks;
  for (int i = 0; i < kShadowCascades; ++i) {
    CascadeCasters selected = SelectCascadeCasters(View(), cascades[i], source);
    EXPECT_EQ(selected.deferred, 0);
    chunks[i] = std::move(selected.chunks);
  }
  return chunks;
}

TEST(ShadowTerrain, EachCascadeDrawsTheRulesChunksAsCoarseAsItsTexelsResolve) {
  HalvingErrors source;
  ShadowTerrain selection = SelectAll(WholeTerrainCascades({0.0, 4.0, 16.0, 64.0}), source);
  const std::vector<SelectedChunk>& rule = selection[0];
  int finest = 0;
  for (const SelectedChunk& c : rule) finest = std::max(finest, c.id.level);
  ASSERT_EQ(finest, 7) << "the camera's rule refines below the levels the texels resolve";
  for (int i = 1; i < kShadowCascades; ++i) {
    double tolerance_m = 0.25 * WholeTerrainCascades({0.0, 4.0, 16.0, 64.0})[i].texel_m;
    EXPECT_EQ(Ids(selection[i]), Coarsened(rule, tolerance_m, source)) << "cascade " << i;
    EXPECT_LT(selection[i].size(), selection[i - 1].size()) << "cascade " << i;
    for (const SelectedChunk& c : selection[i])
      EXPECT_LE(c.id.level, 8 - 2 * i) << "cascade " << i;  // 64 m / 2^level <= texel / 4
  }
}

// Each list gets the skirts of its own neighbours: none on a side where the chunk across it at the
// same level is in the same list, one on every other side.
TEST(ShadowTerrain, SkirtsFollowEachCascadesOwnChunks) {
  HalvingErrors source;
  for (const auto& chunks : SelectAll(WholeTerrainCascades({0.0, 4.0, 16.0, 64.0}), source)) {
    std::set<ChunkId> listed;
    for (const SelectedChunk& c : chunks) listed.insert(c.id);
    for (const SelectedChunk& c : chunks) {
      const ChunkId& id = c.id;
      uint32_t expected = 0;
      if (!listed.contains({id.level, id.x, id.y - 1})) expected |= terrain::kSouth;
      if (!listed.contains({id.level, id.x + 1, id.y})) expected |= terrain::kEast;
      if (!listed.contains({id.level, id.x, id.y + 1})) expected |= terrain::kNorth;
      if (!listed.contains({id.level, id.x - 1, id.y})) expected |= terrain::kWest;
      EXPECT_EQ(c.skirts, expected) << "chunk " << id.level << " " << id.x << " " << id.y;
    }
  }
}

}  // namespace
}  // namespace aerial
