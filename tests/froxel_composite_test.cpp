// The froxels read once per pixel in a full-screen pass after the opaque pass
// (SurfaceFroxelReads::kFullScreenPass, froxel_composite.frag) against the opaque fragments
// reading them per pixel themselves: the same reads at the same screen position and distance, so
// the same frame but for float rounding, with shadows and with the sun's visibility cached.
#include <gtest/gtest.h>

#include <cstdio>

#include "aerial/render/renderer.h"
#include "aerial/scene.h"
#include "aerial/validation/image_metrics.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

constexpr int kWidth = 320, kHeight = 180;

RendererOptions Options(SurfaceFroxelReads reads, double render_scale = 1.0) {
  RendererOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.render_scale = render_scale;
  options.surface_froxel_reads = reads;
  return options;
}

class FroxelCompositePass : public GpuTest {};

// Both ways differ only in where the view ray's direction comes from: the pass interpolates it
// over the screen (sky.vert), the fragment takes it from its interpolated position, a few float
// roundings apart in the phase functions' nu: measured 8.9e-9 (noon) and 2.8e-8 (evening). A pass
// that skipped the transmittance was 6.7% and 1.9% off; one that left pixels unwritten or read the
// froxels at another distance would be off by as much.
TEST_F(FroxelCompositePass, DrawsTheFrameOfPerPixelReads) {
  const AtmosphereTables& tables = FullTables();
  for (const char* preset : {"noon", "evening"}) {
    Scene scene = BuildPreset(preset, tables.atmosphere().bottom_radius_m);
    Renderer deferred(tables, scene, Options(SurfaceFroxelReads::kFullScreenPass));
    Renderer forward(tables, scene, Options(SurfaceFroxelReads::kPerPixel));
    deferred.Render(scene);
    forward.Render(scene);
    const double first = validation::EnergyWeightedRelativeRmse(deferred.ReadOutput(), forward.ReadOutput());
    // The next frame of the same view reads the sun's visibility the first one cached.
    deferred.Render(scene);
    forward.Render(scene);
    EXPECT_TRUE(deferred.frame_info().sun_visibility_cached) << preset;
    const double cached = validation::EnergyWeightedRelativeRmse(deferred.ReadOutput(), forward.ReadOutput());
    std::printf("%s: full-screen pass against per-pixel reads, relative RMSE %.3g (sun visibility cached: %.3g)\n",
                preset, first, cached);
    EXPECT_LT(first, 1e-6) << preset;
    EXPECT_LT(cached, 1e-6) << preset;
  }
}

// The surfaces' radiance follows the render scale as the other targets do.
TEST_F(FroxelCompositePass, FollowsTheRenderScale) {
  const AtmosphereTables& tables = FullTables();
  Scene scene = BuildPreset("noon", tables.atmosphere().bottom_radius_m);
  Renderer rescaled(tables, scene, Options(SurfaceFroxelReads::kFullScreenPass));
  rescaled.Render(scene);
  rescaled.SetRenderScale(0.5);
  rescaled.Render(scene);
  Renderer built(tables, scene, Options(SurfaceFroxelReads::kFullScreenPass, 0.5));
  built.Render(scene);
  EXPECT_EQ(validation::EnergyWeightedRelativeRmse(rescaled.ReadOutput(), built.ReadOutput()), 0.0);
}

}  // namespace
}  // namespace aerial::testing
