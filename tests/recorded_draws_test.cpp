// What a frame records (FrameInfo::draws, ::draw_binds), counted from the scene it draws: a call per
// opaque mesh and per terrain chunk, one for the sky and one for the transparent objects, and the
// shadow tiles' own when the map is redrawn.
#include <gtest/gtest.h>

#include <algorithm>

#include "aerial/render/renderer.h"
#include "aerial/scene.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

class RecordedDraws : public GpuTest {};

FrameInfo RenderOnce(const Scene& scene, bool shadows) {
  const AtmosphereTables& tables = SmallTables();
  RendererOptions options;
  options.width = 160;
  options.height = 90;
  options.shadows = shadows;
  Renderer renderer(tables, scene, options);
  renderer.Render(scene);
  return renderer.frame_info();
}

TEST_F(RecordedDraws, AreACallPerMeshAndChunkAndOneEachForTheSkyAndTheTransparentObjects) {
  Scene scene = BuildPreset("noon", SmallTables().atmosphere().bottom_radius_m);
  const auto opaque = std::count_if(scene.meshes.begin(), scene.meshes.end(),
                                    [](const Mesh& m) { return !m.transparent && !m.indices.empty(); });
  const bool transparent = std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return m.transparent; });
  ASSERT_GT(opaque, 0);
  ASSERT_TRUE(transparent);

  scene.terrain = false;
  const FrameInfo meshes = RenderOnce(scene, false);
  EXPECT_EQ(meshes.draws, opaque + 2);
  // One pipeline for the opaque surfaces that read the froxels per pixel and one for those that
  // read them per vertex (surface_reads.h), the sky's and the transparent objects'.
  EXPECT_GE(meshes.draw_binds, 3);
  EXPECT_LE(meshes.draw_binds, 4);

  scene.terrain = true;
  const FrameInfo terrain = RenderOnce(scene, false);
  ASSERT_GT(terrain.chunks, 10u);
  EXPECT_EQ(terrain.draws, opaque + int(terrain.chunks) + 2);
  EXPECT_EQ(terrain.draw_binds, meshes.draw_binds);

  // A first frame draws every shadow tile: each binds once and draws the meshes and its chunks.
  const FrameInfo shadowed = RenderOnce(scene, true);
  ASSERT_EQ(shadowed.shadow_tiles_redrawn, 4);
  EXPECT_EQ(shadowed.draw_binds, terrain.draw_binds + 4);
  EXPECT_GT(shadowed.draws, terrain.draws + 4 + 4);
}

}  // namespace
}  // namespace aerial::testing
