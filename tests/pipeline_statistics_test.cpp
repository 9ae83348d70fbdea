// Fragment-shader counts per pass (vk::GpuTimer with pipeline statistics, PassTime), where the
// device has the feature: aerial's own device enables it, and lavapipe has it.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "aerial/render/renderer.h"
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

}  // namespace
}  // namespace aerial::testing
