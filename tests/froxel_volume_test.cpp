// FroxelVolume::Build for a caller with no shadow map (froxel/froxel_volume.h, docs/api.md): the
// caller fills the FrameBlock for its camera and records the build into its command buffer.
#include <gtest/gtest.h>

#include <algorithm>
#include <span>

#include "aerial/render/frame_uniforms.h"
#include "aerial/render/renderer.h"
#include "aerial/scene/presets.h"
#include "froxel/froxel_volume.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

class FroxelVolumeBuild : public GpuTest {};

// The volume equals, bit for bit, the one aerial's renderer builds with shadows off for the same
// camera and sun (sunset: the Earth's shadow and a long, reddened path through the volume), and
// it holds light: the far slices scatter and attenuate.
TEST_F(FroxelVolumeBuild, WithoutAShadowMapEqualsTheRenderersUnshadowedVolume) {
  const AtmosphereTables& tables = SmallTables();
  const vk::Context& context = tables.context();
  const double R = tables.atmosphere().bottom_radius_m;
  Scene scene = BuildPreset("sunset", R);
  RenderOptions options{.width = 160, .height = 90, .shadows = false};
  Renderer renderer(tables, scene, options);
  renderer.Render(scene);
  FroxelTexels expected = renderer.froxels().Read(context);

  FroxelVolume volume(context, options.froxels);
  vk::Buffer frame(context, vk::UniformBufferInfo(sizeof(FrameUniforms)));
  FrameUniforms uniforms = MakeFrameUniforms(scene, R, options.width, options.height, options.froxels);
  frame.Write(std::as_bytes(std::span(&uniforms, 1)));
  context.Submit([&](const vk::CommandBuffer& cmd) {
    volume.Build(cmd, tables, frame);
    vk::FullBarrier(cmd);
  });
  FroxelTexels built = volume.Read(context);

  const size_t texels = size_t(options.froxels.width) * options.froxels.height * options.froxels.depth;
  ASSERT_EQ(built.rayleigh.size(), 4 * texels);
  EXPECT_TRUE(built.rayleigh == expected.rayleigh);
  EXPECT_TRUE(built.mie == expected.mie);
  EXPECT_TRUE(built.transmittance == expected.transmittance);
  EXPECT_GT(*std::max_element(built.rayleigh.begin(), built.rayleigh.end()), 0.0f);
  EXPECT_LT(*std::min_element(built.transmittance.begin(), built.transmittance.end()), 0.9f);
}

}  // namespace
}  // namespace aerial::testing
