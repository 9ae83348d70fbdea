#include "aerial/terrain/terrain_chunk.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

#include "aerial/scene/terrain.h"

namespace aerial::terrain {
namespace {

constexpr int N = kChunkCells;

// Surface heights of a chunk's grid with a border of one cell (for the normals' differences):
// sample (i, j), i and j in [-1, N + 1], at x0 + i * cell, y0 + j * cell.
class HeightGrid {
 public:
  HeightGrid(const Footprint& f, double planet_radius_m) : f_(f), R_(planet_radius_m) {
    points_.resize((N + 3) * (N + 3));
    for (int j = -1; j <= N + 1; ++j)
      for (int i = -1; i <= N + 1; ++i) points_[Index(i, j)] = TerrainPoint(X(i), Y(j), R_);
  }
  const glm::dvec3& operator()(int i, int j) const { return points_[Index(i, j)]; }
  double X(double i) const { return f_.x0 + i * f_.cell(); }
  double Y(double j) const { return f_.y0 + j * f_.cell(); }

 private:
  static int Index(int i, int j) { return (j + 1) * (N + 3) + (i + 1); }
  Footprint f_;
  double R_;
  std::vector<glm::dvec3> points_;
};

// Radial distance of a point from the planet's center.
double Radial(const glm::dvec3& p, double R) { return glm::length(p - glm::dvec3(0.0, 0.0, -R)); }

// The gap between the surface and the chunk's triangles at every cell centre: the midpoint of the
// diagonal from (i, j) to (i + 1, j + 1) that splits each cell.
double InteriorError(const HeightGrid& grid, double R) {
  double worst = 0.0;
  for (int j = 0; j < N; ++j) {
    for (int i = 0; i < N; ++i) {
      glm::dvec3 mesh = 0.5 * (grid(i, j) + grid(i + 1, j + 1));
      glm::dvec3 surface = TerrainPoint(grid.X(i + 0.5), grid.Y(j + 0.5), R);
      worst = std::max(worst, std::fabs(Radial(mesh, R) - Radial(surface, R)));
    }
  }
  return worst;
}

// One side of the chunk, walked from grid vertex (i0, j0) in steps (di, dj) over N cells; `global`
// is the index, along the side, of its first vertex in this level's lattice of the whole tree.
struct Side {
  int i0, j0, di, dj;
  long long global;
};

std::array<Side, 4> Sides(const ChunkId& id) {
  long long gx = (long long)id.x * N, gy = (long long)id.y * N;
  return {Side{0, 0, 1, 0, gx}, Side{0, N, 1, 0, gx}, Side{0, 0, 0, 1, gy}, Side{N, 0, 0, 1, gy}};
}

// Measured gaps along the chunk's sides. edge_error: between the surface and this chunk's edge,
// at quarter cells. coarser_gap: between this chunk's edge vertices and the edge of any coarser
// chunk (level - k) it may meet, whose vertices are every 2^k of ours along the side and, when
// they fall outside this chunk, are surface points computed here.
struct EdgeGaps {
  double edge_error = 0.0, coarser_gap = 0.0;
};

EdgeGaps MeasureEdges(const ChunkId& id, const HeightGrid& grid, double R) {
  EdgeGaps gaps;
  for (const Side& side : Sides(id)) {
    auto vertex = [&](int k) { return grid(side.i0 + k * side.di, side.j0 + k * side.dj); };
    auto surface_at = [&](double k) {
      return TerrainPoint(grid.X(side.i0 + k * side.di), grid.Y(side.j0 + k * side.dj), R);
    };
    for (int k = 0; k < N; ++k) {
      for (double q : {0.25, 0.5, 0.75}) {
        glm::dvec3 mesh = glm::mix(vertex(k), vertex(k + 1), q);
        gaps.edge_error =
            std::max(gaps.edge_error, std::fabs(Radial(mesh, R) - Radial(surface_at(k + q), R)));
      }
    }
    std::map<long long, glm::dvec3> outside;  // coarser vertices beyond this chunk's side
    auto point = [&](long long lattice) {
      long long local = lattice - side.global;
      if (local >= 0 && local <= N) return vertex(int(local));
      auto [it, added] = outside.try_emplace(local);
      if (added) it->second = surface_at(double(local));
      return it->second;
    };
    for (int coarser = 1; coarser <= id.level; ++coarser) {
      long long step = 1LL << coarser;
      for (int k = 0; k <= N; ++k) {
        long long g = side.global + k;
        long long a = (g / step) * step;  // g >= 0: the tree's lattice starts at its corner
        if (a == g) continue;             // a vertex of the coarser chunk too: no gap
        glm::dvec3 mesh = glm::mix(point(a), point(a + step), double(g - a) / double(step));
        gaps.coarser_gap =
            std::max(gaps.coarser_gap, std::fabs(Radial(mesh, R) - Radial(vertex(k), R)));
      }
    }
  }
  return gaps;
}

std::vector<uint32_t> GridIndices() {
  std::vector<uint32_t> indices;
  auto at = [](int i, int j) { return uint32_t(j * (N + 1) + i); };
  for (int j = 0; j < N; ++j) {
    for (int i = 0; i < N; ++i) {
      // Split along the diagonal (i, j)-(i + 1, j + 1), which InteriorError measures.
      indices.insert(indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      indices.insert(indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return indices;
}

// Walking the border counter-clockwise seen from above, the chunk is on the left: the quad from
// a to b and down to their skirt vertices faces right, outward.
void AppendSkirt(int side, std::vector<uint32_t>& indices) {
  static const std::vector<uint32_t> border = SkirtEdgeVertices();
  for (uint32_t k = side * N; k < uint32_t(side + 1) * N; ++k) {
    uint32_t next = (k + 1) % border.size();
    uint32_t a = border[k], b = border[next];
    uint32_t a_low = kChunkGridVertices + k, b_low = kChunkGridVertices + next;
    indices.insert(indices.end(), {a, a_low, b_low, a, b_low, b});
  }
}

// The grid's triangles block by block in `order` (GridIndices' two triangles per cell, row by row
// within each block).
std::vector<uint32_t> BlockGridIndices(int order) {
  const std::vector<uint32_t> grid = GridIndices();
  std::vector<uint32_t> indices;
  for (uint32_t position = 0; position < kBlocksPerChunk; ++position) {
    const uint32_t block = BlockAtPosition(order, position);
    const int bi = int(block) % kChunkBlocks, bj = int(block) / kChunkBlocks;
    for (int j = bj * kBlockCells; j < (bj + 1) * kBlockCells; ++j)
      for (int i = bi * kBlockCells; i < (bi + 1) * kBlockCells; ++i) {
        const auto cell = grid.begin() + 6 * (j * N + i);
        indices.insert(indices.end(), cell, cell + 6);
      }
  }
  return indices;
}

struct IndexLists {
  std::vector<uint32_t> indices;
  std::array<IndexRange, kAllSides + 1> ranges;
  std::array<std::array<IndexRange, kAllSides + 1>, kBlockOrders> block_ranges;
};

const IndexLists& Lists() {
  static const IndexLists lists = [] {
    IndexLists made;
    auto append = [&](const std::vector<uint32_t>& grid, bool skirts_first, uint32_t mask) {
      IndexRange range{.first = uint32_t(made.indices.size())};
      if (!skirts_first) made.indices.insert(made.indices.end(), grid.begin(), grid.end());
      for (int side = 0; side < 4; ++side)
        if (mask & (1u << side)) AppendSkirt(side, made.indices);
      if (skirts_first) made.indices.insert(made.indices.end(), grid.begin(), grid.end());
      range.count = uint32_t(made.indices.size()) - range.first;
      return range;
    };
    const std::vector<uint32_t> grid = GridIndices();
    for (uint32_t mask = 0; mask <= kAllSides; ++mask) made.ranges[mask] = append(grid, false, mask);
    for (int order = 0; order < kBlockOrders; ++order) {
      const std::vector<uint32_t> blocks = BlockGridIndices(order);
      for (uint32_t mask = 0; mask <= kAllSides; ++mask) made.block_ranges[order][mask] = append(blocks, true, mask);
    }
    return made;
  }();
  return lists;
}

}  // namespace

std::vector<uint32_t> SkirtEdgeVertices() {
  std::vector<uint32_t> border;
  auto at = [](int i, int j) { return uint32_t(j * (N + 1) + i); };
  for (int i = 0; i < N; ++i) border.push_back(at(i, 0));
  for (int j = 0; j < N; ++j) border.push_back(at(N, j));
  for (int i = N; i > 0; --i) border.push_back(at(i, N));
  for (int j = N; j > 0; --j) border.push_back(at(0, j));
  return border;
}

const std::vector<uint32_t>& ChunkIndices() { return Lists().indices; }

IndexRange ChunkIndexRange(uint32_t skirt_mask) { return Lists().ranges.at(skirt_mask & kAllSides); }

uint32_t BlockAtPosition(int order, uint32_t position) {
  const uint32_t line = position / kChunkBlocks, along = position % kChunkBlocks, last = kChunkBlocks - 1;
  switch (order) {
    case 0: return line * kChunkBlocks + along;           // rows, from the south
    case 1: return (last - line) * kChunkBlocks + along;  // rows, from the north
    case 2: return along * kChunkBlocks + line;           // columns, from the west
    case 3: return along * kChunkBlocks + (last - line);  // columns, from the east
  }
  throw std::out_of_range("block order");
}

std::array<glm::vec2, kBlocksPerChunk> BlockHeights(const std::array<float, kChunkCells * kChunkCells>& cell_lowest_m,
                                                     const std::array<float, kChunkCells * kChunkCells>& cell_highest_m) {
  std::array<glm::vec2, kBlocksPerChunk> blocks;
  blocks.fill(glm::vec2(INFINITY, -INFINITY));
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i) {
      glm::vec2& block = blocks[(j / kBlockCells) * kChunkBlocks + i / kBlockCells];
      block.x = std::min(block.x, cell_lowest_m[j * N + i]);
      block.y = std::max(block.y, cell_highest_m[j * N + i]);
    }
  return blocks;
}

IndexRange ChunkBlockIndexRange(uint32_t skirt_mask, int order) {
  return Lists().block_ranges.at(size_t(order)).at(skirt_mask & kAllSides);
}

TerrainChunk BuildTerrainChunk(const ChunkId& id, double planet_radius_m) {
  const double R = planet_radius_m;
  HeightGrid grid(FootprintOf(id), R);
  TerrainChunk chunk{.id = id};
  chunk.vertices.reserve(kChunkVertices);
  for (int j = 0; j <= N; ++j) {
    for (int i = 0; i <= N; ++i) {
      chunk.vertices.push_back(TerrainVertex(grid(i, j), grid(i + 1, j) - grid(i - 1, j),
                                             grid(i, j + 1) - grid(i, j - 1), R));
    }
  }
  for (int j = 0; j < N; ++j) {
    for (int i = 0; i < N; ++i) {
      double lowest = INFINITY, highest = -INFINITY;
      for (int corner = 0; corner < 4; ++corner) {
        const double height = Radial(grid(i + (corner & 1), j + (corner >> 1)), R) - R;
        lowest = std::min(lowest, height);
        highest = std::max(highest, height);
      }
      chunk.cell_lowest_m[j * N + i] = float(lowest);
      chunk.cell_highest_m[j * N + i] = float(highest);
      chunk.largest_rise_m = std::max(chunk.largest_rise_m, highest - lowest);
    }
  }
  // The surface's longest triangle edge: the cells' sides and both diagonals (whichever the
  // triangles share). The skirts are left out: they show only as slivers in the cracks between
  // levels of detail.
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i)
      for (glm::dvec3 edge : {grid(i + 1, j) - grid(i, j), grid(i, j + 1) - grid(i, j),
                              grid(i + 1, j + 1) - grid(i, j), grid(i, j + 1) - grid(i + 1, j)})
        chunk.longest_edge_m = std::max(chunk.longest_edge_m, glm::length(edge));
  EdgeGaps gaps = MeasureEdges(id, grid, R);
  chunk.geometric_error_m = std::max(InteriorError(grid, R), gaps.edge_error);
  chunk.skirt_depth_m = kSkirtMargin * std::max(gaps.edge_error, gaps.coarser_gap) + kSkirtMinimumM;
  // Skirt vertices: straight down along the local vertical, shaded like the edge above them.
  for (uint32_t k : SkirtEdgeVertices()) {
    Vertex low = chunk.vertices[k];
    glm::dvec3 p(low.position);
    glm::dvec3 up = glm::normalize(p - glm::dvec3(0.0, 0.0, -R));
    low.position = glm::vec3(p - up * chunk.skirt_depth_m);
    chunk.vertices.push_back(low);
  }
  chunk.bounds = {glm::dvec3(chunk.vertices.front().position), glm::dvec3(chunk.vertices.front().position)};
  for (const Vertex& v : chunk.vertices) {
    chunk.bounds.min = glm::min(chunk.bounds.min, glm::dvec3(v.position));
    chunk.bounds.max = glm::max(chunk.bounds.max, glm::dvec3(v.position));
  }
  return chunk;
}

}  // namespace aerial::terrain
