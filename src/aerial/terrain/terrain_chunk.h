#pragma once
// One chunk of the built-in terrain (scene/terrain.h) as a mesh: a regular grid of
// (kChunkCells + 1)^2 vertices on the curved ground, with a skirt hanging down from its four
// edges to close the cracks where it meets a chunk of another level (Ulrich 2002, section 4.3).
//
// Cracks. Along an edge shared with a coarser chunk, the coarser side interpolates linearly
// between vertices that the finer side also has, so the vertical gap is, at each vertex of the
// finer side, the distance between the surface and the coarser side's interpolation. The skirt
// depth covers that distance for every coarser level this chunk could meet (measured at its own
// edge vertices), and its own interpolation error along the edges (measured at quarter cells):
// whichever side is higher hangs a skirt below the other.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "aerial/scene.h"
#include "aerial/terrain/chunk_id.h"

namespace aerial::terrain {

// Axis-aligned bounds in the scene frame.
struct Bounds {
  glm::dvec3 min{0.0}, max{0.0};
};

struct TerrainChunk {
  ChunkId id;
  // Grid vertices first, row by row (x fastest), then the skirt's lower vertices in the order of
  // SkirtEdgeVertices.
  std::vector<Vertex> vertices;
  // The largest radial distance between the mesh and the surface, measured at every cell centre
  // (the middle of the triangles' shared diagonal) and at quarter points along the chunk's edges.
  double geometric_error_m = 0.0;
  double skirt_depth_m = 0.0;
  double longest_edge_m = 0.0;  // of any of its surface's triangles (not the skirts')
  double largest_rise_m = 0.0;  // the largest height difference within one of its cells
  // Per cell (row by row), the height above the sphere of its lowest corner: the mesh over the
  // cell never dips below it (occluders, screen_horizon.h).
  std::array<float, kChunkCells * kChunkCells> cell_lowest_m{};
  std::array<float, kChunkCells * kChunkCells> cell_highest_m{};
  Bounds bounds;  // of every vertex, the skirt included
};

TerrainChunk BuildTerrainChunk(const ChunkId& id, double planet_radius_m);

// The skirt's depth beyond the measured gaps, kSkirtMargin times them plus kSkirtMinimumM: the
// measurements sample the edges at quarter cells, so a peak of the surface between two samples
// may reach a little further.
inline constexpr double kSkirtMargin = 1.25;
inline constexpr double kSkirtMinimumM = 0.1;

inline constexpr uint32_t kChunkGridVertices = (kChunkCells + 1) * (kChunkCells + 1);
inline constexpr uint32_t kChunkVertices = kChunkGridVertices + 4 * kChunkCells;

// The chunk's sides, as bits of a skirt mask: a skirt is only needed along a side where the
// neighbouring chunk is drawn at another level (or not drawn).
enum ChunkSide : uint32_t { kSouth = 1, kEast = 2, kNorth = 4, kWest = 8 };
inline constexpr uint32_t kAllSides = kSouth | kEast | kNorth | kWest;

// The triangle lists every chunk shares, one per skirt mask (counter-clockwise seen from above
// and, for the skirts, from outside the chunk): two triangles per cell, then two per skirt
// segment of the masked sides. ChunkIndexRange(mask) is where mask's list lies in ChunkIndices().
const std::vector<uint32_t>& ChunkIndices();
struct IndexRange {
  uint32_t first = 0, count = 0;
};
IndexRange ChunkIndexRange(uint32_t skirt_mask);

// The cells in blocks of kBlockCells x kBlockCells, kChunkBlocks a side: block (i, j), numbered
// j * kChunkBlocks + i, holds cells [kBlockCells * i, kBlockCells * (i + 1)) x [kBlockCells * j,
// kBlockCells * (j + 1)). The GPU's selection tests blocks against the horizon, and leaves out of a
// chunk's draw the hidden blocks that come last in one of kBlockOrders orders: rows from the south
// (0) or from the north (1), columns from the west (2) or from the east (3).
inline constexpr int kBlockCells = 2;
inline constexpr int kChunkBlocks = kChunkCells / kBlockCells;
inline constexpr uint32_t kBlocksPerChunk = kChunkBlocks * kChunkBlocks;
inline constexpr uint32_t kBlockIndices = 6 * kBlockCells * kBlockCells;
inline constexpr int kBlockOrders = 4;
// The block at `position` (< kBlocksPerChunk) of `order`.
uint32_t BlockAtPosition(int order, uint32_t position);
// Per block, its cells' lowest and highest heights (x, y; TerrainChunk::cell_lowest_m,
// ::cell_highest_m): the mesh over the block lies between them.
std::array<glm::vec2, kBlocksPerChunk> BlockHeights(const std::array<float, kChunkCells * kChunkCells>& cell_lowest_m,
                                                     const std::array<float, kChunkCells * kChunkCells>& cell_highest_m);
// Where the list of ChunkIndexRange(skirt_mask)'s triangles lies in ChunkIndices() with the skirts
// first and then the cells block by block in `order`: its first count - k * kBlockIndices indices
// leave out the order's last k blocks.
IndexRange ChunkBlockIndexRange(uint32_t skirt_mask, int order);

// The grid vertex indices around the chunk's border, counter-clockwise seen from above, starting
// at the corner (0, 0): 4 * kChunkCells of them, kChunkCells per side in the order south, east,
// north, west. Skirt vertex kChunkGridVertices + k hangs below border vertex k.
std::vector<uint32_t> SkirtEdgeVertices();

}  // namespace aerial::terrain
