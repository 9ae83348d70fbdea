// The terrain's selection made by the GPU (src/aerial/render/gpu_chunk_selection.h) against the
// CPU's (src/aerial/terrain/lod_selection.h), which applies the same rule in double precision to
// the same built chunks: the same chunks, skirts and order; a chunk whose children are not built
// drawn in their place, and the children asked for; from the root alone, the asked-for chunks
// lead to the CPU's selection; its split by froxel reads and each shadow cascade's casters are the
// CPU's; a selection in flight keeps the tree it was recorded with. With occlusion culling, each
// chunk it leaves out is hidden from the camera by the terrain itself, ray-marched on the CPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <string>

#include "aerial/render/gpu_chunk_selection.h"
#include "aerial/render/shadow_terrain.h"
#include "aerial/render/surface_reads.h"
#include "aerial/scene.h"
#include "aerial/scene/terrain.h"
#include "aerial/terrain/built_chunks.h"
#include "aerial/terrain/terrain_chunk.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

using terrain::ChunkId;
using terrain::SelectedChunk;

constexpr double kR = 6360e3;  // the default atmosphere's bottom radius
constexpr double kAspect = 16.0 / 9.0;
constexpr uint32_t kSlots = 8192;
constexpr uint32_t kGroundInstance = 1;

// Where a chunk reads the froxels: the distance within which it reads them per pixel.
using ReadsRule = std::function<double(const terrain::ChunkInfo&)>;
const ReadsRule kPerPixelEverywhere = [](const terrain::ChunkInfo&) { return INFINITY; };

// Built chunks (from the process's shared store), each put into the GPU's tree as it is built;
// building can be turned off, so that the CPU's selection, like the GPU's, draws a chunk in place
// of children that are not built.
class TreeChunks : public terrain::ChunkSource {
 public:
  TreeChunks(GpuChunkSelection& gpu, ReadsRule reads) : gpu_(gpu), reads_(std::move(reads)) {}
  const terrain::ChunkInfo* Find(const ChunkId& id) override {
    auto it = infos_.find(id);
    return it == infos_.end() ? nullptr : &it->second;
  }
  void Build(std::span<const ChunkId> ids) override {
    if (!building_) return;
    for (const ChunkId& id : ids) {
      if (infos_.contains(id)) continue;
      const terrain::ChunkInfo& info = infos_[id] = terrain::InfoOf(*terrain::BuiltChunks::Shared().Get(id, kR));
      gpu_.Insert(next_slot_++, id, info, reads_(info));
    }
  }
  void Drop(const ChunkId& id) {
    gpu_.Remove(*gpu_.SlotOf(id));
    infos_.erase(id);
  }
  void set_building(bool building) { building_ = building; }
  size_t size() const { return infos_.size(); }

 private:
  GpuChunkSelection& gpu_;
  ReadsRule reads_;
  std::map<ChunkId, terrain::ChunkInfo> infos_;
  uint32_t next_slot_ = 0;
  bool building_ = true;
};

terrain::LodView ViewOf(const std::string& preset, int height_px, double error_px) {
  Scene scene;
  ApplyPresetView(scene, preset, kR);
  terrain::LodView view = terrain::MakeLodView(scene.camera, kAspect, height_px, error_px, kR);
  view.occlusion_culling = false;
  return view;
}

// Whether the terrain hides `p` from `camera`: the sight line passes under the ground somewhere
// before the last 2 % of the way (the chunk's own ground is not what hides it), marched in steps
// of at most 10 m, finer than any ridge of the heightfield (its finest octave is longer).
bool TerrainHides(const glm::dvec3& camera, const glm::dvec3& p) {
  const int steps = std::max(100, int(glm::length(p - camera) / 10.0));
  for (int s = 1; s < steps * 49 / 50; ++s)
    if (HeightAboveTerrainM(glm::mix(camera, p, double(s) / steps), kR) < 0.0) return true;
  return false;
}

// Whether `p` lies outside the view's frustum (behind one of its sides or its near plane).
bool OutsideView(const terrain::LodView& view, const glm::dvec3& p) {
  for (const glm::dvec4& plane : view.planes)
    if (glm::dot(glm::dvec3(plane), p) + plane.w < 0.0) return true;
  return false;
}

// How many of the chunks have a vertex of their cells in the view.
size_t ChunksInView(const terrain::LodView& view, const std::vector<SelectedChunk>& chunks) {
  size_t in_view = 0;
  for (const SelectedChunk& chunk : chunks) {
    const terrain::Footprint f = terrain::FootprintOf(chunk.id);
    bool seen = false;
    for (int j = 0; j <= terrain::kChunkCells && !seen; ++j)
      for (int i = 0; i <= terrain::kChunkCells && !seen; ++i)
        seen = !OutsideView(view, TerrainPoint(f.x0 + f.size * i / terrain::kChunkCells,
                                               f.y0 + f.size * j / terrain::kChunkCells, kR));
    in_view += seen;
  }
  return in_view;
}

class GpuChunkSelectionTest : public GpuTest {
 protected:
  GpuChunkSelection::Result SelectOnGpu(const terrain::LodView& view) {
    SharedContext().Submit([&](const vk::CommandBuffer& cmd) { gpu_.Record(cmd, view); });
    return gpu_.Read();
  }
  // The CPU's selection of what is built, building nothing.
  terrain::Selection SelectOnCpu(const terrain::LodView& view) {
    chunks_.set_building(false);
    terrain::Selection selection = terrain::SelectChunks(view, chunks_);
    chunks_.set_building(true);
    return selection;
  }

  GpuChunkSelection gpu_{SharedContext(), kSlots, terrain::kChunkVertices, kGroundInstance};
  TreeChunks chunks_{gpu_, kPerPixelEverywhere};
};

// The camera's slack, the least over the refinement tests, is the CPU's within single precision: a
// distance of up to 100 km (the terrain's radius) rounded to 8 mm, a few times over. Slacks are
// metres to kilometres, so an error in which test is the least would show.
void ExpectSlack(const GpuChunkSelection::Result& gpu, double cpu_slack_m) {
  ASSERT_TRUE(std::isfinite(cpu_slack_m));
  EXPECT_NEAR(gpu.camera_slack_m, cpu_slack_m, 0.05 + 1e-5 * cpu_slack_m);
}

std::string Describe(const std::vector<SelectedChunk>& chunks) {
  std::string text;
  for (const SelectedChunk& c : chunks)
    text += std::to_string(c.id.level) + "/" + std::to_string(c.id.x) + "/" + std::to_string(c.id.y) + ":" +
            std::to_string(c.skirts) + " ";
  return text;
}

// Over the chunks the CPU's selection built for itself, the GPU draws the same chunks in the same
// order with the same skirts, and asks for nothing. The views: the default one at 720 and 2160
// rows, the sunset view along the ridges at a 1 px bound, and the ground from 10 km up.
TEST_F(GpuChunkSelectionTest, DrawsWhatTheCpuSelectionDraws) {
  struct Case {
    std::string preset;
    int height_px;
    double error_px;
  };
  for (const Case& c : {Case{"noon", 720, 4.0}, Case{"noon", 2160, 4.0}, Case{"sunset", 720, 1.0},
                        Case{"high-altitude", 720, 4.0}}) {
    const terrain::LodView view = ViewOf(c.preset, c.height_px, c.error_px);
    const terrain::Selection cpu = terrain::SelectChunks(view, chunks_);
    ASSERT_EQ(cpu.deferred, 0);
    const GpuChunkSelection::Result gpu = SelectOnGpu(view);
    SCOPED_TRACE(c.preset + " " + std::to_string(c.height_px));
    EXPECT_GT(cpu.chunks.size(), 50u);
    EXPECT_EQ(gpu.chunks, cpu.chunks) << "GPU: " << Describe(gpu.chunks) << "\nCPU: " << Describe(cpu.chunks);
    EXPECT_TRUE(gpu.requested.empty());
    EXPECT_EQ(gpu.deferred, 0);
    ExpectSlack(gpu, cpu.camera_slack_m);
  }
}

// A drawn chunk of the finest level drawn, so that its parent has drawn children.
ChunkId FinestDrawn(const terrain::Selection& selection) {
  return std::max_element(selection.chunks.begin(), selection.chunks.end(),
                          [](const SelectedChunk& a, const SelectedChunk& b) { return a.id.level < b.id.level; })
      ->id;
}

// A drawn chunk that goes (evicted from the cache) leaves no hole: its parent is drawn in place of
// its children, as the CPU's selection draws it when it may not build, and the chunk is asked for.
TEST_F(GpuChunkSelectionTest, DrawsTheParentOfAChunkThatIsNotBuiltAndAsksForIt) {
  const terrain::LodView view = ViewOf("noon", 720, 4.0);
  const ChunkId id = FinestDrawn(terrain::SelectChunks(view, chunks_)), parent = terrain::Parent(id);
  chunks_.Drop(id);

  const terrain::Selection cpu = SelectOnCpu(view);
  const GpuChunkSelection::Result gpu = SelectOnGpu(view);
  EXPECT_EQ(gpu.chunks, cpu.chunks) << "GPU: " << Describe(gpu.chunks) << "\nCPU: " << Describe(cpu.chunks);
  EXPECT_EQ(gpu.deferred, cpu.deferred);
  EXPECT_EQ(gpu.deferred, 1);
  EXPECT_TRUE(std::any_of(gpu.chunks.begin(), gpu.chunks.end(), [&](const SelectedChunk& c) { return c.id == parent; }));
  EXPECT_EQ(gpu.requested, std::vector<ChunkId>{id});
}

// A selection that compares reports whether the chunks it draws (their slots, fills and skirts)
// differ from those the last one that compared drew: the first one, and after a drawn chunk went
// (its parent drawn instead, its neighbours' skirts changed), but not the same view again. One
// that is redrawn anyway reports a change; one that does not compare, none.
TEST_F(GpuChunkSelectionTest, ReportsWhetherTheChunksItDrawsChanged) {
  using Compare = GpuChunkSelection::Compare;
  const terrain::LodView view = ViewOf("noon", 720, 4.0);
  const ChunkId id = FinestDrawn(terrain::SelectChunks(view, chunks_));
  auto changed = [&](Compare compare) {
    SharedContext().Submit([&](const vk::CommandBuffer& cmd) { gpu_.Record(cmd, view, 0, compare); });
    return gpu_.Read().changed;
  };
  EXPECT_TRUE(changed(Compare::kWithTheLast));
  EXPECT_FALSE(changed(Compare::kWithTheLast));
  chunks_.Drop(id);
  EXPECT_TRUE(changed(Compare::kWithTheLast));
  EXPECT_FALSE(changed(Compare::kWithTheLast));
  EXPECT_TRUE(changed(Compare::kRedrawn));
  EXPECT_FALSE(changed(Compare::kWithTheLast));
  EXPECT_FALSE(changed(Compare::kNothing));
}

// Two selections recorded into one command buffer with a chunk dropped between them: the first
// still draws it, as a frame in flight must, and the second draws its parent instead.
TEST_F(GpuChunkSelectionTest, EachSelectionWalksTheTreeAsItWasWhenRecorded) {
  const terrain::LodView view = ViewOf("noon", 720, 4.0);
  const terrain::Selection full = terrain::SelectChunks(view, chunks_);
  const ChunkId id = FinestDrawn(full);
  const int32_t vertex_offset = int32_t(*gpu_.SlotOf(id) * terrain::kChunkVertices);
  vk::Buffer first(SharedContext(), {.size = gpu_.draws().size(),
                                     .usage = ::vk::BufferUsageFlagBits::eTransferDst,
                                     .host_visible = true});
  SharedContext().Submit([&](const vk::CommandBuffer& cmd) {
    gpu_.Record(cmd, view);
    cmd.copyBuffer(gpu_.draws().handle(), first.handle(), ::vk::BufferCopy{.size = gpu_.draws().size()});
    chunks_.Drop(id);
    gpu_.Record(cmd, view);
  });
  uint32_t first_count = 0;
  std::memcpy(&first_count, first.mapped(), sizeof(first_count));
  const auto* commands =
      reinterpret_cast<const ::vk::DrawIndexedIndirectCommand*>(first.mapped() + GpuChunkSelection::kDrawsOffset);
  EXPECT_EQ(first_count, full.chunks.size());
  EXPECT_TRUE(std::any_of(commands, commands + first_count,
                          [&](const ::vk::DrawIndexedIndirectCommand& c) { return c.vertexOffset == vertex_offset; }))
      << "the first selection did not draw the chunk dropped after it was recorded";
  const GpuChunkSelection::Result second = gpu_.Read();
  EXPECT_EQ(second.requested, std::vector<ChunkId>{id});
  EXPECT_FALSE(std::any_of(second.chunks.begin(), second.chunks.end(), [&](const SelectedChunk& c) { return c.id == id; }));
}

// Starting from nothing built, each selection asks for the next level's chunks; building them
// leads, in at most one selection a level (and one for the root), to the CPU's selection, and
// nothing the CPU would not have built is asked for.
TEST_F(GpuChunkSelectionTest, ChunksAskedForLeadToTheCpuSelection) {
  const terrain::LodView view = ViewOf("noon", 720, 4.0);
  GpuChunkSelection::Result gpu;
  int selections = 0;
  do {
    gpu = SelectOnGpu(view);
    chunks_.Build(gpu.requested);
    ++selections;
  } while (!gpu.requested.empty() && selections <= terrain::kMaxChunkLevel + 2);
  EXPECT_LE(selections, terrain::kMaxChunkLevel + 2);
  EXPECT_EQ(gpu.deferred, 0);
  const size_t built = chunks_.size();
  const terrain::Selection cpu = terrain::SelectChunks(view, chunks_);
  EXPECT_EQ(chunks_.size(), built) << "the CPU's selection needed chunks the GPU did not ask for";
  EXPECT_EQ(gpu.chunks, cpu.chunks) << "GPU: " << Describe(gpu.chunks) << "\nCPU: " << Describe(cpu.chunks);
}

// The chunks come in two lists, as the renderer draws them (Renderer::ChooseFroxelReads): those
// that read the froxels per pixel by the rule of surface_reads.h at their bounds' distance, then
// the others, each front to back. Both lists are drawn from, in the default and the sunset views;
// at a 64 px bound, near chunks are coarse enough that their distance decides.
TEST_F(GpuChunkSelectionTest, SplitsTheChunksByWhereTheyReadTheFroxelsAsTheRendererDoes) {
  const FroxelGrid grid;
  const AirScales air = MakeAirScales(AtmosphereParameters::Earth());
  GpuChunkSelection gpu(SharedContext(), kSlots, terrain::kChunkVertices, kGroundInstance);
  TreeChunks chunks(gpu, [&](const terrain::ChunkInfo& info) {
    return PerPixelReadsWithinM(grid, air, info.longest_edge_m, info.largest_rise_m);
  });
  int by_distance = 0;  // chunks read per pixel only because they are near
  for (const auto& [preset, error_px] : {std::pair{"noon", 4.0}, std::pair{"sunset", 4.0}, std::pair{"noon", 64.0}}) {
    const terrain::LodView view = ViewOf(preset, 720, error_px);
    std::vector<SelectedChunk> expected = terrain::SelectChunks(view, chunks).chunks;
    auto per_vertex = std::stable_partition(expected.begin(), expected.end(), [&](const SelectedChunk& chunk) {
      const terrain::ChunkInfo& info = *chunks.Find(chunk.id);
      return ReadsFroxelsPerPixel(grid, air, info.longest_edge_m, info.largest_rise_m,
                                  terrain::DistanceToBounds(view.camera, info.bounds));
    });
    SharedContext().Submit([&](const vk::CommandBuffer& cmd) { gpu.Record(cmd, view); });
    const GpuChunkSelection::Result result = gpu.Read();
    const size_t per_pixel = size_t(per_vertex - expected.begin());
    for (const SelectedChunk& chunk : expected) {
      const terrain::ChunkInfo& info = *chunks.Find(chunk.id);
      const double within = PerPixelReadsWithinM(grid, air, info.longest_edge_m, info.largest_rise_m);
      by_distance += std::isfinite(within) && terrain::DistanceToBounds(view.camera, info.bounds) < within;
    }
    std::printf("%s: %zu of %zu chunks read per pixel\n", preset, per_pixel, expected.size());
    EXPECT_GT(per_pixel, 0u);
    EXPECT_LT(per_pixel, expected.size());
    EXPECT_EQ(result.per_pixel, per_pixel);
    EXPECT_EQ(result.chunks, expected) << "GPU: " << Describe(result.chunks) << "\nCPU: " << Describe(expected);
  }
  EXPECT_GT(by_distance, 0);
}

// Each shadow cascade's casters, selected by the GPU for the cascade's view (CascadeCasterView: its
// box, the resolved error of its texels, no occlusion culling), are the CPU's, skirts included:
// the noon and sunset views, whose low sun stretches the last cascade's box over the terrain.
TEST_F(GpuChunkSelectionTest, SelectsEachCascadesCastersAsTheCpuDoes) {
  auto by_id = [](std::vector<SelectedChunk> chunks) {
    std::sort(chunks.begin(), chunks.end(), [](const SelectedChunk& a, const SelectedChunk& b) { return a.id < b.id; });
    return chunks;
  };
  size_t casters = 0;
  for (const std::string preset : {"noon", "sunset"}) {
    const Scene scene = BuildPreset(preset, kR);
    const terrain::LodView frame_view = terrain::MakeLodView(scene.camera, kAspect, 720, 4.0, kR);
    const CascadeFitInput fit{.camera = scene.camera,
                              .aspect = kAspect,
                              .sun = scene.sun.Direction(),
                              .casters = {.radius_m = kTerrainRadiusM + 10e3,
                                          .top_radius_m = kR + kTerrainMaxHeightM,
                                          .bottom_radius_m = kR + kTerrainMinHeightM}};
    for (const ShadowCascade& cascade : FitShadowCascades(fit)) {
      const CascadeCasters cpu = SelectCascadeCasters(frame_view, cascade, chunks_);
      ASSERT_EQ(cpu.deferred, 0);
      const GpuChunkSelection::Result gpu = SelectOnGpu(CascadeCasterView(frame_view, cascade));
      SCOPED_TRACE(preset + ", cascade to " + std::to_string(cascade.far_m) + " m");
      EXPECT_FALSE(cpu.chunks.empty());
      casters += cpu.chunks.size();
      EXPECT_EQ(by_id(gpu.chunks), cpu.chunks) << "GPU: " << Describe(by_id(gpu.chunks)) << "\nCPU: " << Describe(cpu.chunks);
      EXPECT_EQ(gpu.deferred, 0);
      ExpectSlack(gpu, cpu.camera_slack_m);
    }
  }
  EXPECT_GT(casters, 1000u);
}

// With occlusion culling, the GPU leaves out only chunks, and blocks of chunks, that the terrain
// hides or the view does not hold: every vertex of a 5 x 5 lattice over each chunk left out (the
// corners of its blocks of 2 x 2 cells, each tested on its own), and of a 3 x 3 lattice over each
// block left out of a chunk's draw, is behind the ground as the CPU marches it or outside the
// frustum, and the chunks drawn are the rest of those without culling, in the same order. Blocks
// of the chunks on the frustum's edges are left out for lying outside it. Over the chunks with
// ground in view, it hides about as much as the CPU's horizon on the screen
// (terrain/screen_horizon.h): a different rule (a horizon per azimuth around the camera's vertical,
// by bands of distance, with blocks of 2 x 2 cells as occluders at their lowest and as targets at
// their highest), within 10 % more chunks drawn and no fewer than 90 % of them. The views: noon
// and sunset at 720 rows, and the ground from 2 km up, looking down.
TEST_F(GpuChunkSelectionTest, LeavesOutOnlyTheTerrainNotSeen) {
  Scene above;
  ApplyPresetView(above, "noon", kR);
  above.camera.position = SurfacePoint(-1500.0, 9000.0, 2000.0 + TerrainHeightM(-1500.0, 9000.0), kR);
  above.camera.pitch_deg = -55.0;
  above.camera.yaw_deg = 300.0;
  terrain::LodView above_view = terrain::MakeLodView(above.camera, kAspect, 720, 4.0, kR);
  above_view.occlusion_culling = false;
  // Looking along the ground, a fifth of the drawn chunks' blocks are left out (0.20 at noon and
  // sunset); looking down, few are hidden.
  const std::array<double, 3> least_blocks_left_out = {0.1, 0.1, 0.0};
  int v = 0;
  for (terrain::LodView view : {ViewOf("noon", 720, 4.0), ViewOf("sunset", 720, 4.0), above_view}) {
    terrain::SelectChunks(view, chunks_);
    const GpuChunkSelection::Result all = SelectOnGpu(view);
    view.occlusion_culling = true;
    const GpuChunkSelection::Result culled = SelectOnGpu(view);
    const terrain::Selection cpu = SelectOnCpu(view);
    const size_t gpu_in_view = ChunksInView(view, culled.chunks), cpu_in_view = ChunksInView(view, cpu.chunks);
    std::printf("drawn of %zu: GPU %zu (%d left out), CPU %zu; with a vertex in view: GPU %zu, CPU %zu\n",
                all.chunks.size(), culled.chunks.size(), culled.hidden, cpu.chunks.size(), gpu_in_view, cpu_in_view);
    EXPECT_EQ(all.hidden, 0);
    EXPECT_EQ(culled.chunks.size() + size_t(culled.hidden), all.chunks.size());
    // The CPU's selection keeps every chunk whose bounds meet the frustum; those that the view
    // holds none of are left out of the comparison of the two horizons.
    EXPECT_LE(double(gpu_in_view), 1.1 * double(cpu_in_view));
    EXPECT_GE(double(gpu_in_view), 0.9 * double(cpu_in_view));
    // The GPU tests each block's ground against the frustum: few chunks it draws have no vertex in
    // view (a triangle may cross the view between vertices outside it). Looking down, three in four
    // of the CPU's have none, their bounds reaching into the view with heights their ground lacks.
    EXPECT_LE(double(culled.chunks.size() - gpu_in_view), 0.05 * double(culled.chunks.size()));

    size_t next = 0, points = 0, seen = 0, blocks_left_out = 0, blocks_outside = 0;
    // The points of a chunk's footprint at (i, j) / 8 of its side that the camera sees; whether
    // every one of them is outside the view.
    auto check_hidden = [&](const ChunkId& id, int i0, int i1, int j0, int j1, int step, const char* what) {
      const terrain::Footprint f = terrain::FootprintOf(id);
      bool outside = true;
      for (int j = j0; j <= j1; j += step)
        for (int i = i0; i <= i1; i += step) {
          ++points;
          const glm::dvec3 p = TerrainPoint(f.x0 + f.size * i / 8, f.y0 + f.size * j / 8, kR);
          if (OutsideView(view, p)) continue;
          outside = false;
          if (!TerrainHides(view.camera, p)) {
            ++seen;
            ADD_FAILURE() << "chunk " << id.level << "/" << id.x << "/" << id.y << ": " << what << ", its point ("
                          << i << ", " << j << ") / 8 seen";
          }
        }
      return outside;
    };
    for (const SelectedChunk& chunk : all.chunks) {
      if (next < culled.chunks.size() && culled.chunks[next].id == chunk.id) {
        // Blocks of 2 x 2 cells, a quarter of the side: their corners and the middles of their sides.
        for (uint32_t block = 0; block < terrain::kBlocksPerChunk; ++block) {
          if (!(culled.blocks_left_out[next] >> block & 1u)) continue;
          ++blocks_left_out;
          const int i = 2 * int(block % terrain::kChunkBlocks), j = 2 * int(block / terrain::kChunkBlocks);
          if (check_hidden(chunk.id, i, i + 2, j, j + 2, 1, "block left out")) ++blocks_outside;
        }
        ++next;
        continue;
      }
      check_hidden(chunk.id, 0, 8, 0, 8, 2, "left out");
    }
    std::printf("blocks left out of the chunks drawn: %zu of %zu, %zu of them outside the view\n", blocks_left_out,
                culled.chunks.size() * terrain::kBlocksPerChunk, blocks_outside);
    EXPECT_GE(double(blocks_left_out),
              least_blocks_left_out[v++] * double(culled.chunks.size() * terrain::kBlocksPerChunk));
    EXPECT_EQ(next, culled.chunks.size()) << "a chunk drawn with culling, not without, or out of order";
    EXPECT_EQ(seen, 0u) << "of " << points;
  }
}

}  // namespace
}  // namespace aerial::testing
