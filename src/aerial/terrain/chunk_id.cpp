#include "aerial/terrain/chunk_id.h"

namespace aerial::terrain {

Footprint FootprintOf(const ChunkId& id) {
  double size = kRootSizeM / double(1 << id.level);
  return {-kRootSizeM / 2 + id.x * size, -kRootSizeM / 2 + id.y * size, size};
}

std::array<ChunkId, 4> Children(const ChunkId& id) {
  int l = id.level + 1, x = 2 * id.x, y = 2 * id.y;
  return {ChunkId{l, x, y}, ChunkId{l, x + 1, y}, ChunkId{l, x, y + 1}, ChunkId{l, x + 1, y + 1}};
}

ChunkId Parent(const ChunkId& id) {
  if (id.level == 0) return id;
  return {id.level - 1, id.x / 2, id.y / 2};
}

}  // namespace aerial::terrain
