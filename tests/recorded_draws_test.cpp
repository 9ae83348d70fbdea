// What a frame records (FrameInfo::draws, ::draw_binds) does not grow with the scene's terrain:
// the opaque pass records an indirect draw per run of commands that share their state (meshes with
// back faces culled, double-sided meshes, terrain chunks; for the surfaces that read the froxels
// per pixel and for those that read them per vertex), whatever the number of meshes and chunks; one
// draw each for the sky, the sun's disc over it and the transparent objects; and each redrawn
// shadow tile two: the meshes and its chunks.
#include <gtest/gtest.h>

#include <algorithm>

#include "aerial/render/renderer.h"
#include "aerial/scene.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

class RecordedDraws : public GpuTest {};

FrameInfo RenderOnce(const Scene& scene, bool shadows, double terrain_error_px = 4.0) {
  const AtmosphereTables& tables = SmallTables();
  RendererOptions options;
  options.width = 160;
  options.height = 90;
  options.shadows = shadows;
  options.terrain_error_px = terrain_error_px;
  Renderer renderer(tables, scene, options);
  renderer.Render(scene);
  return renderer.frame_info();
}

TEST_F(RecordedDraws, AreAFewIndirectDrawsWhateverTheTerrainDraws) {
  Scene scene = BuildPreset("noon", SmallTables().atmosphere().bottom_radius_m);
  const auto opaque = std::count_if(scene.meshes.begin(), scene.meshes.end(),
                                    [](const Mesh& m) { return !m.transparent && !m.indices.empty(); });
  const bool transparent = std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return m.transparent; });
  ASSERT_GT(opaque, 4);
  ASSERT_TRUE(transparent);

  // The meshes: at most two runs (culled, double-sided) in each of the two pipelines, which the
  // surfaces that read the froxels per pixel and those that read them per vertex take; then the
  // sky, the sun's disc and the transparent objects.
  scene.terrain = false;
  const FrameInfo meshes = RenderOnce(scene, false);
  EXPECT_GE(meshes.draws, 1 + 3);
  EXPECT_LE(meshes.draws, 4 + 3);
  EXPECT_LT(meshes.draws, opaque + 3);
  EXPECT_GE(meshes.draw_binds, 4);
  EXPECT_LE(meshes.draw_binds, 5);

  // The terrain adds one run per pipeline, at any level of detail: four times finer draws several
  // times the chunks and records the same.
  scene.terrain = true;
  const FrameInfo terrain = RenderOnce(scene, false);
  const FrameInfo fine = RenderOnce(scene, false, 1.0);
  ASSERT_GT(terrain.chunks, 10u);
  ASSERT_GT(fine.chunks, 2 * terrain.chunks);
  EXPECT_GE(terrain.draws, meshes.draws + 1);
  EXPECT_LE(terrain.draws, meshes.draws + 2);
  EXPECT_EQ(fine.draws, terrain.draws);
  EXPECT_EQ(terrain.draw_binds, meshes.draw_binds);
  EXPECT_EQ(fine.draw_binds, terrain.draw_binds);

  // A first frame draws every shadow tile: each binds once and draws the meshes and its chunks.
  const FrameInfo shadowed = RenderOnce(scene, true);
  ASSERT_EQ(shadowed.shadow_tiles_redrawn, 4);
  EXPECT_EQ(shadowed.draw_binds, terrain.draw_binds + 4);
  EXPECT_EQ(shadowed.draws, terrain.draws + 4 * 2);
}

}  // namespace
}  // namespace aerial::testing
