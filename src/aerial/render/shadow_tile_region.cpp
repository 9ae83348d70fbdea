#include "aerial/render/shadow_tile_region.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace aerial {

bool TileTexels::Overlaps(const TileTexels& other) const {
  return !Empty() && !other.Empty() && min.x < other.max.x && other.min.x < max.x && min.y < other.max.y &&
         other.min.y < max.y;
}

TileTexels WholeTile(int tile_texels) { return {{0, 0}, {tile_texels, tile_texels}}; }

TileTexels BoxTexels(const ShadowCascade& cascade, int tile_texels, const terrain::Bounds& box) {
  glm::dvec2 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                       (corner & 4) ? box.max.z : box.min.z);
    const glm::dvec4 clip = cascade.clip_from_world * glm::dvec4(p, 1.0);
    const glm::dvec2 texel = (glm::dvec2(clip) / clip.w + 1.0) * (0.5 * tile_texels);  // Vulkan's viewport
    low = glm::min(low, texel);
    high = glm::max(high, texel);
  }
  const glm::dvec2 lo = glm::clamp(glm::floor(low) - 1.0, 0.0, double(tile_texels));
  const glm::dvec2 hi = glm::clamp(glm::ceil(high) + 1.0, 0.0, double(tile_texels));
  return {glm::ivec2(lo), glm::ivec2(hi)};
}

std::optional<TileTexels> ChangedCastersTexels(const ShadowCascade& cascade, int tile_texels,
                                               const std::vector<terrain::SelectedChunk>& drawn,
                                               const std::vector<terrain::SelectedChunk>& selected,
                                               terrain::ChunkSource& source) {
  TileTexels region{{tile_texels, tile_texels}, {0, 0}};
  bool known = true;
  auto add = [&](const terrain::SelectedChunk& chunk) {
    const terrain::ChunkInfo* info = source.Find(chunk.id);
    if (!info) {
      known = false;
      return;
    }
    const TileTexels texels = BoxTexels(cascade, tile_texels, info->bounds);
    if (texels.Empty()) return;
    region.min = glm::min(region.min, texels.min);
    region.max = glm::max(region.max, texels.max);
  };
  // Both lists are sorted by id and hold each id once: walk them together.
  auto a = drawn.begin(), b = selected.begin();
  while (known && (a != drawn.end() || b != selected.end())) {
    if (b == selected.end() || (a != drawn.end() && a->id < b->id)) {
      add(*a++);
    } else if (a == drawn.end() || b->id < a->id) {
      add(*b++);
    } else {
      if (a->skirts != b->skirts) add(*b);
      ++a;
      ++b;
    }
  }
  if (!known) return std::nullopt;
  if (region.Empty()) return TileTexels{};
  const glm::dvec2 size(region.max - region.min);
  if (size.x * size.y > kWholeTileRedrawFraction * double(tile_texels) * tile_texels) return std::nullopt;
  return region;
}

std::vector<terrain::SelectedChunk> CastersReaching(const ShadowCascade& cascade, int tile_texels,
                                                    const std::vector<terrain::SelectedChunk>& casters,
                                                    const TileTexels& region, terrain::ChunkSource& source) {
  std::vector<terrain::SelectedChunk> reaching;
  for (const terrain::SelectedChunk& chunk : casters) {
    const terrain::ChunkInfo* info = source.Find(chunk.id);
    if (!info || BoxTexels(cascade, tile_texels, info->bounds).Overlaps(region)) reaching.push_back(chunk);
  }
  return reaching;
}

}  // namespace aerial
