#include "aerial/terrain/terrain_chunk.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <set>
#include <stdexcept>

#include "aerial/scene/terrain.h"

namespace aerial::terrain {
namespace {

constexpr double kR = 6360e3;  // the default atmosphere's bottom radius
const glm::dvec3 kCenter(0.0, 0.0, -kR);

double Radial(const glm::dvec3& p) { return glm::length(p - kCenter); }

// The terrain height at the sea-level point below p (on the radial line through it).
double SurfaceHeightBelow(const glm::dvec3& p) {
  glm::dvec3 sea_level = kCenter + kR * glm::normalize(p - kCenter);
  return TerrainHeightM(sea_level.x, sea_level.y);
}

// A flat valley chunk at the origin, a mountain chunk on the corridor's wall 20 km out and a
// coarse one reaching 100 km.
const std::vector<ChunkId> kChunks = {ChunkId{13, 4096, 4096}, ChunkId{9, 250, 281}, ChunkId{3, 6, 7}};

TEST(TerrainChunk, GridVerticesLieOnTheSurface) {
  for (const ChunkId& id : kChunks) {
    TerrainChunk chunk = BuildTerrainChunk(id, kR);
    ASSERT_EQ(chunk.vertices.size(), kChunkVertices);
    for (uint32_t k = 0; k < kChunkGridVertices; ++k) {
      glm::dvec3 p(chunk.vertices[k].position);
      // Float positions up to 100 km out are rounded to ~4 mm per axis; slopes below 3 turn that
      // into at most ~1.2 cm of height along the radial line, so 5 cm leaves room.
      ASSERT_NEAR(Radial(p) - kR, SurfaceHeightBelow(p), 0.05) << "level " << id.level << " vertex " << k;
    }
  }
}

// Each cell's lowest and highest heights bound its four grid vertices' heights above the sphere
// and are reached by one of them (float vertices: within the 5 cm of the test above); the mesh's
// triangles over the cell lie between its corners, so the horizon's occluders and targets
// (terrain_occluders.comp) bound it.
TEST(TerrainChunk, CellHeightsAreTheirCornersExtremes) {
  for (const ChunkId& id : kChunks) {
    TerrainChunk chunk = BuildTerrainChunk(id, kR);
    for (int j = 0; j < kChunkCells; ++j) {
      for (int i = 0; i < kChunkCells; ++i) {
        double lowest = INFINITY, highest = -INFINITY;
        for (int corner = 0; corner < 4; ++corner) {
          const int vertex = (j + (corner >> 1)) * (kChunkCells + 1) + i + (corner & 1);
          const double height = Radial(glm::dvec3(chunk.vertices[vertex].position)) - kR;
          lowest = std::min(lowest, height);
          highest = std::max(highest, height);
        }
        const int cell = j * kChunkCells + i;
        EXPECT_NEAR(chunk.cell_lowest_m[cell], lowest, 0.05) << "level " << id.level << " cell " << cell;
        EXPECT_NEAR(chunk.cell_highest_m[cell], highest, 0.05) << "level " << id.level << " cell " << cell;
        EXPECT_LE(chunk.cell_lowest_m[cell], chunk.cell_highest_m[cell]);
      }
    }
  }
}

TEST(TerrainChunk, SkirtsHangStraightDownByTheirDepth) {
  for (const ChunkId& id : kChunks) {
    TerrainChunk chunk = BuildTerrainChunk(id, kR);
    std::vector<uint32_t> border = SkirtEdgeVertices();
    ASSERT_EQ(border.size(), 4u * kChunkCells);
    EXPECT_GT(chunk.skirt_depth_m, 0.0);
    for (uint32_t k = 0; k < border.size(); ++k) {
      glm::dvec3 top(chunk.vertices[border[k]].position);
      glm::dvec3 low(chunk.vertices[kChunkGridVertices + k].position);
      // Straight down the local vertical, by the depth (float rounding as above).
      EXPECT_NEAR(Radial(top) - Radial(low), chunk.skirt_depth_m, 0.05);
      EXPECT_LT(glm::length(glm::cross(glm::normalize(top - kCenter), top - low)), 0.05);
    }
  }
}

TEST(TerrainChunk, IndexListsHoldTheGridAndTheMaskedSides) {
  const std::vector<uint32_t>& indices = ChunkIndices();
  constexpr uint32_t kGrid = kChunkCells * kChunkCells * 6, kSide = kChunkCells * 6;
  for (uint32_t mask = 0; mask <= kAllSides; ++mask) {
    IndexRange range = ChunkIndexRange(mask);
    uint32_t sides = std::popcount(mask);
    EXPECT_EQ(range.count, kGrid + sides * kSide) << mask;
    ASSERT_LE(range.first + range.count, indices.size());
    for (uint32_t i = range.first; i < range.first + range.count; ++i) ASSERT_LT(indices[i], kChunkVertices);
  }
}

// The block lists draw the same triangles as the row lists, skirts first, then block by block:
// each group of kBlockIndices indices is the order's next block's cells, every block once.
TEST(TerrainChunk, BlockListsHoldTheSameTrianglesBlockByBlock) {
  const std::vector<uint32_t>& indices = ChunkIndices();
  constexpr uint32_t kSide = kChunkCells * 6;
  auto triangles = [&](IndexRange range) {
    std::multiset<std::array<uint32_t, 3>> made;
    for (uint32_t i = range.first; i < range.first + range.count; i += 3)
      made.insert({indices[i], indices[i + 1], indices[i + 2]});
    return made;
  };
  for (int order = 0; order < kBlockOrders; ++order) {
    std::set<uint32_t> blocks;
    for (uint32_t position = 0; position < kBlocksPerChunk; ++position)
      blocks.insert(BlockAtPosition(order, position));
    EXPECT_EQ(blocks.size(), kBlocksPerChunk) << "order " << order;
    for (uint32_t mask = 0; mask <= kAllSides; ++mask) {
      const IndexRange range = ChunkBlockIndexRange(mask, order);
      ASSERT_LE(range.first + range.count, indices.size());
      EXPECT_EQ(triangles(range), triangles(ChunkIndexRange(mask))) << "order " << order << ", mask " << mask;
      const uint32_t grid_first = range.first + std::popcount(mask) * kSide;
      ASSERT_EQ(range.first + range.count - grid_first, kBlocksPerChunk * kBlockIndices);
      for (uint32_t position = 0; position < kBlocksPerChunk; ++position) {
        const uint32_t block = BlockAtPosition(order, position);
        const uint32_t i0 = kBlockCells * (block % kChunkBlocks), j0 = kBlockCells * (block / kChunkBlocks);
        for (uint32_t k = 0; k < kBlockIndices; ++k) {
          const uint32_t vertex = indices[grid_first + position * kBlockIndices + k];
          const uint32_t i = vertex % (kChunkCells + 1), j = vertex / (kChunkCells + 1);
          EXPECT_TRUE(i >= i0 && i <= i0 + kBlockCells && j >= j0 && j <= j0 + kBlockCells)
              << "order " << order << ", position " << position << ": vertex " << vertex << " outside block " << block;
        }
      }
    }
  }
  // The orders run from the south, the north, the west and the east.
  EXPECT_EQ(BlockAtPosition(0, 0), 0u);
  EXPECT_EQ(BlockAtPosition(1, 0), uint32_t(kChunkBlocks * (kChunkBlocks - 1)));
  EXPECT_EQ(BlockAtPosition(2, 1), uint32_t(kChunkBlocks));
  EXPECT_EQ(BlockAtPosition(3, 0), uint32_t(kChunkBlocks - 1));
  EXPECT_THROW(ChunkBlockIndexRange(0, kBlockOrders), std::out_of_range);
}

// A block's heights are the lowest and highest of its 2 x 2 cells' (a cell at (i, j) holding
// i + 10 j as its lowest and 100 + i + 10 j as its highest): block (1, 2), cells (2-3, 4-5).
TEST(TerrainChunk, BlockHeightsAreTheirCellsExtremes) {
  std::array<float, kChunkCells * kChunkCells> lowest, highest;
  for (int j = 0; j < kChunkCells; ++j)
    for (int i = 0; i < kChunkCells; ++i) {
      lowest[j * kChunkCells + i] = float(i + 10 * j);
      highest[j * kChunkCells + i] = float(100 + i + 10 * j);
    }
  const std::array<glm::vec2, kBlocksPerChunk> blocks = BlockHeights(lowest, highest);
  EXPECT_EQ(blocks[2 * kChunkBlocks + 1], glm::vec2(42.0f, 153.0f));
  EXPECT_EQ(blocks[0], glm::vec2(0.0f, 111.0f));
  EXPECT_EQ(blocks[kBlocksPerChunk - 1], glm::vec2(66.0f, 177.0f));
}

// Counter-clockwise seen from the side the terrain faces: grid triangles face up, skirt
// triangles face away from the chunk, so back faces can be culled.
TEST(TerrainChunk, TrianglesFaceUpAndSkirtsFaceOut) {
  TerrainChunk chunk = BuildTerrainChunk(kChunks[0], kR);  // flat valley floor
  const std::vector<uint32_t>& indices = ChunkIndices();
  IndexRange all = ChunkIndexRange(kAllSides);
  glm::dvec3 middle(chunk.vertices[kChunkGridVertices / 2].position);
  int grid = 0, skirt = 0;
  for (uint32_t i = all.first; i < all.first + all.count; i += 3) {
    glm::dvec3 a(chunk.vertices[indices[i]].position), b(chunk.vertices[indices[i + 1]].position),
        c(chunk.vertices[indices[i + 2]].position);
    glm::dvec3 normal = glm::cross(b - a, c - a);
    if (i - all.first < kChunkCells * kChunkCells * 6) {
      EXPECT_GT(normal.z, 0.0) << "grid triangle " << i / 3;
      ++grid;
    } else {
      glm::dvec3 outward = (a + b + c) / 3.0 - middle;
      outward.z = 0.0;
      EXPECT_GT(glm::dot(normal, outward), 0.0) << "skirt triangle " << i / 3;
      ++skirt;
    }
  }
  EXPECT_EQ(grid, kChunkCells * kChunkCells * 2);
  EXPECT_EQ(skirt, 4 * kChunkCells * 2);
}

}  // namespace
}  // namespace aerial::terrain
