#pragma once
// The quadtree of terrain chunks (Ulrich 2002, "Rendering Massive Terrains using Chunked Level of
// Detail Control"). The root covers a square of kRootSizeM centered on the scene origin; each
// level halves the chunk size, and every chunk is a regular grid of kChunkCells x kChunkCells
// cells, so the cell size halves too: from 25.6 km at the root to 3.125 m at kMaxChunkLevel, finer
// than the 4 m nearest rings of the fixed polar mesh. Small chunks let the level of detail follow
// the error bound closely (8 x 8 cells draw 40% fewer triangles than 16 x 16 for the same bound
// at the default view); the draws they cost are cheap next to the triangles they save. The tree is fixed in the world; the selection
// (lod_selection.h) follows the camera, so the detail under the camera is the same everywhere.
#include <array>
#include <compare>
#include <cstdint>
#include <functional>

namespace aerial::terrain {

inline constexpr int kChunkCells = 8;
inline constexpr int kMaxChunkLevel = 13;
inline constexpr double kRootSizeM = 204800.0;

// Chunk (x, y) of its level: the square [x0, x0 + size] x [y0, y0 + size] of sea-level points
// (terrain.h), with x0 = -kRootSizeM / 2 + x * size and size = kRootSizeM / 2^level.
struct ChunkId {
  int level = 0, x = 0, y = 0;
  auto operator<=>(const ChunkId&) const = default;
};

// For hashed containers: x and y are below 2^kMaxChunkLevel, so the three fit in 32 bits apart.
struct ChunkIdHash {
  size_t operator()(const ChunkId& id) const {
    return std::hash<uint64_t>{}((uint64_t(id.level) << 56) ^ (uint64_t(uint32_t(id.x)) << 28) ^ uint32_t(id.y));
  }
};

struct Footprint {
  double x0, y0, size;
  double cell() const { return size / kChunkCells; }
};

Footprint FootprintOf(const ChunkId& id);
// The four chunks of the next level that tile this one.
std::array<ChunkId, 4> Children(const ChunkId& id);
// The chunk of the level above that holds this one (the root's parent is the root).
ChunkId Parent(const ChunkId& id);

}  // namespace aerial::terrain
