#include "aerial/terrain/lod_selection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <random>

#include "aerial/scene.h"
#include "aerial/scene/terrain.h"

namespace aerial::terrain {
namespace {

constexpr double kR = 6360e3;  // the default atmosphere's bottom radius
const glm::dvec3 kCenter(0.0, 0.0, -kR);
constexpr double kAspect = 16.0 / 9.0;
constexpr double kErrorPx = 4.0;  // the renderer's default bound (kDefaultTerrainErrorPx)

double Radial(const glm::dvec3& p) { return glm::length(p - kCenter); }

// Builds chunks on the CPU as the renderer's cache does, keeping them whole for the checks, and
// builds at most `budget` of them (unlimited when empty).
class CpuChunks : public ChunkSource {
 public:
  explicit CpuChunks(std::optional<int> budget = std::nullopt) : budget_(budget) {}
  const ChunkInfo* Find(const ChunkId& id) override {
    auto it = chunks_.find(id);
    return it == chunks_.end() ? nullptr : &it->second.info;
  }
  void Build(std::span<const ChunkId> ids) override {
    for (const ChunkId& id : ids) {
      if (budget_ && *budget_ <= 0) return;
      if (budget_) --*budget_;
      TerrainChunk chunk = BuildTerrainChunk(id, kR);
      chunks_[id] = {InfoOf(chunk), std::move(chunk)};
    }
  }
  const TerrainChunk& Chunk(const ChunkId& id) const { return chunks_.at(id).chunk; }

 private:
  struct Entry {
    ChunkInfo info;
    TerrainChunk chunk;
  };
  std::optional<int> budget_;
  std::map<ChunkId, Entry> chunks_;
};

Camera NoonCamera() {
  Scene scene;
  ApplyPresetView(scene, "noon", kR);
  return scene.camera;
}

// The noon view moved north along the corridor, at the same height above its floor.
Camera NorthCamera(double y_m) {
  Camera camera = NoonCamera();
  double above = camera.position.z - TerrainHeightM(0.0, 0.0);
  camera.position = SurfacePoint(0.0, y_m, TerrainHeightM(0.0, y_m) + above, kR);
  return camera;
}

// The point of a chunk's mesh over fractional grid coordinates (u, v) in [0, kChunkCells]: on
// the triangle of its cell that holds it (cells split along the (i, j)-(i + 1, j + 1) diagonal).
glm::dvec3 MeshPoint(const TerrainChunk& chunk, double u, double v) {
  int i = std::min(int(u), kChunkCells - 1), j = std::min(int(v), kChunkCells - 1);
  double s = u - i, t = v - j;
  auto p = [&](int di, int dj) {
    return glm::dvec3(chunk.vertices[(j + dj) * (kChunkCells + 1) + (i + di)].position);
  };
  if (s >= t) return p(0, 0) + s * (p(1, 0) - p(0, 0)) + t * (p(1, 1) - p(1, 0));
  return p(0, 0) + t * (p(0, 1) - p(0, 0)) + s * (p(1, 1) - p(0, 1));
}

// Radial distance between a mesh point and the surface over the same sea-level point.
double HeightError(const glm::dvec3& mesh) {
  glm::dvec3 sea_level = kCenter + kR * glm::normalize(mesh - kCenter);
  return std::fabs(Radial(mesh) - kR - TerrainHeightM(sea_level.x, sea_level.y));
}

TEST(LodSelection, EveryDrawnChunkMeetsTheErrorBound) {
  CpuChunks chunks;
  LodView view = MakeLodView(NoonCamera(), kAspect, 720, kErrorPx, kR);
  Selection selection = SelectChunks(view, chunks);
  ASSERT_GT(selection.chunks.size(), 100u);
  EXPECT_EQ(selection.deferred, 0);
  for (const SelectedChunk& s : selection.chunks) {
    const ChunkInfo& info = *chunks.Find(s.id);
    EXPECT_TRUE(IntersectsFrustum(view, info.bounds));
    if (s.id.level < kMaxChunkLevel) {
      EXPECT_LE(ScreenSpaceErrorPx(view, info.geometric_error_m, info.bounds), kErrorPx);
    }
  }
}

// The bound checked independently of how the chunks measure their own error: random points of
// every drawn chunk's triangles against the surface, projected from the camera. The chunks
// measure at cell centres and along their edges only, so a peak of the fractal surface between
// those samples may exceed the bound a little: 25% at most.
TEST(LodSelection, RandomPointsOfTheMeshStayWithinTheBoundOnScreen) {
  CpuChunks chunks;
  Camera camera = NoonCamera();
  LodView view = MakeLodView(camera, kAspect, 720, kErrorPx, kR);
  Selection selection = SelectChunks(view, chunks);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, kChunkCells);
  int samples = 0;
  double worst = 0.0;
  for (const SelectedChunk& s : selection.chunks) {
    const TerrainChunk& chunk = chunks.Chunk(s.id);
    for (int n = 0; n < 64; ++n) {
      glm::dvec3 p = MeshPoint(chunk, unit(random), unit(random));
      double px = HeightError(p) * view.pixels_per_radian / glm::length(p - camera.position);
      worst = std::max(worst, px);
      ++samples;
    }
  }
  std::printf("%d random points of %zu chunks: worst %.2f px (bound %.0f px)\n", samples,
              selection.chunks.size(), worst, kErrorPx);
  ASSERT_GT(samples, 10000);
  EXPECT_LE(worst, 1.25 * kErrorPx);
}

// The tree is fixed in the world and the selection follows the camera: 40 km up the corridor, where
// the fixed polar mesh's cells are 700 m, the ground near the camera is drawn as finely as at the
// origin: within the error bound on screen, with cells of at most 100 m (the flat valley floor
// needs no finer ones; 40 km out the hills get finer cells than the floor at the origin).
TEST(LodSelection, SameBoundUnderTheCamera40KmAway) {
  for (const Camera& camera : {NoonCamera(), NorthCamera(40e3)}) {
    CpuChunks chunks;
    Camera down = camera;
    down.pitch_deg = -60.0;  // the ground around the camera in view
    LodView view = MakeLodView(down, kAspect, 720, kErrorPx, kR);
    Selection selection = SelectChunks(view, chunks);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(0.0, kChunkCells);
    int near = 0;
    double worst = 0.0, coarsest = 0.0;
    for (const SelectedChunk& s : selection.chunks) {
      if (DistanceToBounds(camera.position, chunks.Find(s.id)->bounds) > 1000.0) continue;
      ++near;
      coarsest = std::max(coarsest, FootprintOf(s.id).cell());
      for (int n = 0; n < 64; ++n) {
        glm::dvec3 p = MeshPoint(chunks.Chunk(s.id), unit(random), unit(random));
        worst = std::max(worst, HeightError(p) * view.pixels_per_radian / glm::length(p - camera.position));
      }
    }
    std::printf("camera at y = %.0f m: %d chunks within 1 km, cells up to %.1f m, worst %.2f px\n",
                camera.position.y, near, coarsest, worst);
    EXPECT_GE(near, 1);
    EXPECT_LE(coarsest, 100.0);
    EXPECT_LE(worst, 1.25 * kErrorPx);
  }
}

// Along every side shared by two drawn chunks of different levels, sampled 16 times per cell of
// the finer one, the higher edge's skirt reaches below the lower edge.
TEST(LodSelection, SkirtsCloseTheCracksBetweenLevels) {
  CpuChunks chunks;
  Selection selection = SelectChunks(MakeLodView(NoonCamera(), kAspect, 720, kErrorPx, kR), chunks);
  std::map<ChunkId, uint32_t> drawn;
  for (const SelectedChunk& s : selection.chunks) drawn[s.id] = s.skirts;
  // The height of a chunk's edge at world coordinate w along its south (y0) or west (x0) side.
  auto edge_height = [&](const ChunkId& id, bool south, double w) {
    Footprint f = FootprintOf(id);
    double u = (w - (south ? f.x0 : f.y0)) / f.cell();
    return Radial(south ? MeshPoint(chunks.Chunk(id), u, 0.0) : MeshPoint(chunks.Chunk(id), 0.0, u));
  };
  auto north_height = [&](const ChunkId& id, double x) {
    Footprint f = FootprintOf(id);
    return Radial(MeshPoint(chunks.Chunk(id), (x - f.x0) / f.cell(), kChunkCells));
  };
  auto east_height = [&](const ChunkId& id, double y) {
    Footprint f = FootprintOf(id);
    return Radial(MeshPoint(chunks.Chunk(id), kChunkCells, (y - f.y0) / f.cell()));
  };
  int pairs = 0, samples = 0;
  for (const auto& [fine, fine_skirts] : drawn) {
    Footprint f = FootprintOf(fine);
    for (const auto& [coarse, coarse_skirts] : drawn) {
      if (coarse.level >= fine.level) continue;
      Footprint c = FootprintOf(coarse);
      bool below = c.y0 + c.size == f.y0, left = c.x0 + c.size == f.x0;
      bool overlaps_x = c.x0 < f.x0 + f.size && f.x0 < c.x0 + c.size;
      bool overlaps_y = c.y0 < f.y0 + f.size && f.y0 < c.y0 + c.size;
      if (!((below && overlaps_x) || (left && overlaps_y))) continue;  // the other sides: symmetric cases below
      ++pairs;
      EXPECT_TRUE(fine_skirts & (below ? kSouth : kWest));
      EXPECT_TRUE(coarse_skirts & (below ? kNorth : kEast));
      for (int k = 0; k <= kChunkCells * 16; ++k) {
        double w = (below ? f.x0 : f.y0) + f.cell() * k / 16.0;
        double fine_h = edge_height(fine, below, w);
        double coarse_h = below ? north_height(coarse, w) : east_height(coarse, w);
        double gap = std::fabs(fine_h - coarse_h);
        double skirt = fine_h > coarse_h ? chunks.Chunk(fine).skirt_depth_m : chunks.Chunk(coarse).skirt_depth_m;
        ASSERT_LE(gap, skirt) << "level " << fine.level << " against " << coarse.level << " at " << w;
        ++samples;
      }
    }
  }
  std::printf("%d level boundaries (south and west sides of the finer chunk), %d samples\n", pairs, samples);
  EXPECT_GT(pairs, 20);
}

// A chunk whose children are not built yet is drawn in their place: with room for only the
// root, the root alone is drawn and the refinement it lacks is counted.
TEST(LodSelection, UnbuiltChildrenLeaveTheirParentDrawn) {
  CpuChunks root_only(1);
  Selection selection = SelectChunks(MakeLodView(NoonCamera(), kAspect, 720, kErrorPx, kR), root_only);
  ASSERT_EQ(selection.chunks.size(), 1u);
  EXPECT_EQ(selection.chunks[0].id, ChunkId{});
  EXPECT_EQ(selection.deferred, 1);
}

// Front to back: whenever the line from the camera (seen from above) to a chunk's center crosses
// another chunk, that one is in front and must come first.
TEST(LodSelection, FrontToBack) {
  CpuChunks chunks;
  LodView view = MakeLodView(NoonCamera(), kAspect, 720, kErrorPx, kR);
  view.occlusion_culling = false;  // every chunk in view
  Selection selection = SelectChunks(view, chunks);
  glm::dvec3 eye = kCenter + kR * glm::normalize(view.camera - kCenter);
  // Liang and Barsky: whether the segment from a to b meets the open rectangle f.
  auto crosses = [](glm::dvec2 a, glm::dvec2 b, const Footprint& f) {
    double t0 = 0.0, t1 = 1.0;
    glm::dvec2 d = b - a;
    for (auto [p, q] : {std::pair{-d.x, a.x - f.x0}, std::pair{d.x, f.x0 + f.size - a.x},
                        std::pair{-d.y, a.y - f.y0}, std::pair{d.y, f.y0 + f.size - a.y}}) {
      if (p == 0.0) {
        if (q <= 0.0) return false;
      } else if (p < 0.0) {
        t0 = std::max(t0, q / p);
      } else {
        t1 = std::min(t1, q / p);
      }
    }
    return t0 < t1;
  };
  int checked = 0;
  for (size_t b = 0; b < selection.chunks.size(); ++b) {
    Footprint fb = FootprintOf(selection.chunks[b].id);
    glm::dvec2 center(fb.x0 + fb.size / 2, fb.y0 + fb.size / 2);
    for (size_t a = 0; a < selection.chunks.size(); ++a) {
      if (a == b || !crosses(glm::dvec2(eye), center, FootprintOf(selection.chunks[a].id))) continue;
      ++checked;
      ASSERT_LT(a, b) << "level " << selection.chunks[a].id.level << " chunk in front of level "
                      << selection.chunks[b].id.level << " comes after it";
    }
  }
  EXPECT_GT(checked, 1000);
}

// Behind the camera nothing is drawn: the frustum's planes cull it.
std::vector<ChunkId> Ids(const Selection& selection) {
  std::vector<ChunkId> ids;
  for (const SelectedChunk& chunk : selection.chunks) ids.push_back(chunk.id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

// The slack both ways: any camera closer than it selects the same chunks, and a camera just past
// it, moved along the distance's gradient of the chunk whose test is nearest to flipping, does not.
// Without occlusion culling, as the shadow casters' selection, whose planes do not follow the camera.
TEST(LodSelection, TheCameraSlackIsHowFarItMayMoveForTheSameChunks) {
  CpuChunks chunks;
  LodView view = MakeLodView(NoonCamera(), kAspect, 720, kErrorPx, kR);
  view.occlusion_culling = false;
  const Selection selected = SelectChunks(view, chunks);
  const double slack = selected.camera_slack_m;
  ASSERT_EQ(selected.deferred, 0);
  ASSERT_GT(slack, 0.0);
  ASSERT_LT(slack, 1e4) << "the noon view's chunks are refined up to metres from the camera";
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  for (int i = 0; i < 20; ++i) {
    glm::dvec3 direction = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
    LodView moved = view;
    moved.camera += 0.99 * slack * direction;
    EXPECT_EQ(Ids(SelectChunks(moved, chunks)), Ids(selected)) << "moved along " << direction.x << ", "
                                                               << direction.y << ", " << direction.z;
  }
  // The tested chunk nearest its threshold, among the drawn ones and all their ancestors.
  std::optional<ChunkId> nearest;
  for (const SelectedChunk& drawn : selected.chunks)
    for (ChunkId id = drawn.id;; id = Parent(id)) {
      const ChunkInfo& info = *chunks.Find(id);
      if (id.level < kMaxChunkLevel &&
          std::fabs(RefinementSlackM(view, info.geometric_error_m, info.bounds) - slack) < 1e-9)
        nearest = id;
      if (id.level == 0) break;
    }
  ASSERT_TRUE(nearest) << "the slack is some tested chunk's";
  const ChunkInfo& info = *chunks.Find(*nearest);
  glm::dvec3 closest = glm::clamp(view.camera, info.bounds.min, info.bounds.max);
  ASSERT_GT(glm::length(view.camera - closest), 2.0 * slack) << "the camera is outside the chunk's bounds";
  glm::dvec3 away = glm::normalize(view.camera - closest);
  bool refined = ScreenSpaceErrorPx(view, info.geometric_error_m, info.bounds) > kErrorPx;
  LodView moved = view;
  moved.camera += (refined ? 1.01 : -1.01) * slack * away;  // across its threshold
  EXPECT_NE(Ids(SelectChunks(moved, chunks)), Ids(selected));
}

TEST(LodSelection, NothingBehindTheCamera) {
  CpuChunks chunks;
  Camera camera = NoonCamera();  // looking north from the origin
  Selection selection = SelectChunks(MakeLodView(camera, kAspect, 720, kErrorPx, kR), chunks);
  for (const SelectedChunk& s : selection.chunks)
    EXPECT_GT(chunks.Find(s.id)->bounds.max.y, camera.position.y - 1.0) << s.id.level;
}

}  // namespace
}  // namespace aerial::terrain
