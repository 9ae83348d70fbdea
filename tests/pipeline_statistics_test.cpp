// Fragment-shader counts per pass (vk::GpuTimer with pipeline statistics, PassTime), where the
// device has the feature: aerial's own device enables it, and lavapipe has it.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "aerial/render/renderer.h"
#include "aerial/render/renderer_options.h"
#include "aerial/scene.h"
#include "aerial/validation/image_metrics.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

class PipelineStatistics : public GpuTest {};

// The opaque pass invokes its fragment shader at least once for every pixel its surfaces cover
// (counted from the surface image, not from the counts) and, on a rasterizer that shades 4x4
// stamps with overdraw, at most a few tens of times; a compute pass invokes none.
TEST_F(PipelineStatistics, OpaquePassCountsAtLeastItsCoveredPixelsAndComputeNone) {
  if (!SharedContext().physical_device().getFeatures().pipelineStatisticsQuery)
    GTEST_SKIP() << "the device has no pipeline statistics";
  const AtmosphereTables& tables = SmallTables();
  const Scene scene = BuildPreset("noon", tables.atmosphere().bottom_radius_m);
  Renderer renderer(tables, scene, {.width = 160, .height = 90});
  std::vector<PassTime> passes = renderer.Render(scene);
  auto count = [&](const std::string& name) {
    auto pass = std::find_if(passes.begin(), passes.end(), [&](const PassTime& p) { return p.pass == name; });
    EXPECT_NE(pass, passes.end()) << name;
    EXPECT_TRUE(pass != passes.end() && pass->fragment_shader_invocations.has_value()) << name;
    return pass != passes.end() ? pass->fragment_shader_invocations.value_or(0) : 0;
  };
  const ImageRgbF surface = renderer.ReadSurface();
  uint64_t covered = 0;
  for (int y = 0; y < surface.height; ++y)
    for (int x = 0; x < surface.width; ++x) covered += !validation::IsSky(surface, x, y);
  ASSERT_GT(covered, 1000u) << "the noon view shows terrain";
  const uint64_t opaque = count("opaque raster");
  EXPECT_GE(opaque, covered);
  EXPECT_LE(opaque, 64 * covered);
  EXPECT_EQ(count("froxel build"), 0u);
}

// aerial_bench_render's floor, the frame with its opaque shading left out, draws the surfaces'
// constant (0.05, opaque_fragment.glsl) on every pixel they cover, so no shading of theirs is left
// in it, and rasterizes what the shaded frame does: the same fragment invocations, counted before
// the depth test, and the same coverage.
TEST_F(PipelineStatistics, TheUnshadedFrameRasterizesTheShadedFramesStampsAndShadesNone) {
  const AtmosphereTables& tables = SmallTables();
  const Scene scene = BuildPreset("noon", tables.atmosphere().bottom_radius_m);
  // Without the transparent objects, which blend over some of the surfaces.
  RendererOptions shaded_options{{.width = 160, .height = 90}};
  shaded_options.passes.transparent = false;
  RendererOptions unshaded_options = shaded_options;
  unshaded_options.left_out_reads.shading = true;
  Renderer shaded(tables, scene, shaded_options), unshaded(tables, scene, unshaded_options);
  std::vector<PassTime> shaded_passes = shaded.Render(scene), unshaded_passes = unshaded.Render(scene);
  const ImageRgbF surface = shaded.ReadSurface(), shaded_image = shaded.ReadOutput(),
                  unshaded_image = unshaded.ReadOutput();
  int covered = 0, constant = 0, changed = 0;
  for (int y = 0; y < surface.height; ++y)
    for (int x = 0; x < surface.width; ++x) {
      if (validation::IsSky(surface, x, y)) continue;
      ++covered;
      const float *p = unshaded_image.pixel(x, y), *q = shaded_image.pixel(x, y);
      constant += p[0] == 0.05f && p[1] == 0.05f && p[2] == 0.05f;
      changed += q[0] != p[0] || q[1] != p[1] || q[2] != p[2];
    }
  ASSERT_GT(covered, 1000) << "the noon view shows terrain";
  EXPECT_EQ(constant, covered);
  EXPECT_EQ(changed, covered) << "the shaded frame's surfaces are not the constant";
  if (!SharedContext().physical_device().getFeatures().pipelineStatisticsQuery)
    GTEST_SKIP() << "the device has no pipeline statistics";
  auto opaque = [](const std::vector<PassTime>& passes) {
    auto pass = std::find_if(passes.begin(), passes.end(), [](const PassTime& p) { return p.pass == "opaque raster"; });
    return pass != passes.end() ? pass->fragment_shader_invocations : std::nullopt;
  };
  ASSERT_TRUE(opaque(shaded_passes).has_value());
  EXPECT_EQ(opaque(unshaded_passes), opaque(shaded_passes));
}

}  // namespace
}  // namespace aerial::testing
