// The aerial perspective applied once per pixel in a full-screen pass after the opaque pass
// (aerial_composite.frag) against the opaque fragments computing it themselves: the froxels read
// there (SurfaceFroxelReads::kFullScreenPass), and the per-pixel modes' march or table reads (their
// default). The same reads or march at the same screen position and distance, so the same frame but
// for float rounding, with shadows and with the sun's visibility cached.
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

class AerialCompositePass : public GpuTest {};

// Both ways differ only in where the view ray's direction comes from: the pass interpolates it
// over the screen (sky.vert), the fragment takes it from its interpolated position, a few float
// roundings apart in the phase functions' nu: measured 8.9e-9 (noon) and 2.8e-8 (evening). A pass
// that skipped the transmittance was 6.7% and 1.9% off; one that left pixels unwritten or read the
// froxels at another distance would be off by as much.
TEST_F(AerialCompositePass, DrawsTheFrameOfPerPixelReads) {
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

// At a quarter of the pixels: marched in the fragments, these frames take seconds.
RendererOptions PerPixelOptions(AerialMode mode, bool full_screen_pass) {
  RendererOptions options = Options(SurfaceFroxelReads::kPerVertexWhereThin);
  options.width = kWidth / 2;
  options.height = kHeight / 2;
  options.mode = mode;
  options.per_pixel_in_full_screen_pass = full_screen_pass;
  return options;
}

// The marched per-pixel path and the two table reads per pixel, in the full-screen pass against
// the opaque fragments. The view ray comes from the screen position in the one and from the
// interpolated position in the other, a few float roundings apart; the march takes the segment's
// parameters from it, and the table difference S(x) - T S(p) cancels most of what it reads, which
// amplifies a rounding of mu. Measured with the small tables at 160x90: marched 2.2e-6 (noon) and
// 1.1e-6 (evening, shadows on), table difference 6.0e-6 and 5.8e-6. A pass that read another
// distance or dropped the transmittance would be percents off.
TEST_F(AerialCompositePass, DrawsThePerPixelModesFrame) {
  const AtmosphereTables& tables = SmallTables();
  for (AerialMode mode : {AerialMode::kPerPixel, AerialMode::kTableDifference})
    for (const char* preset : {"noon", "evening"}) {
      Scene scene = BuildPreset(preset, tables.atmosphere().bottom_radius_m);
      Renderer deferred(tables, scene, PerPixelOptions(mode, true));
      Renderer forward(tables, scene, PerPixelOptions(mode, false));
      deferred.Render(scene);
      forward.Render(scene);
      const double rmse = validation::EnergyWeightedRelativeRmse(deferred.ReadOutput(), forward.ReadOutput());
      std::printf("%s, mode %d: full-screen pass against the opaque fragments, relative RMSE %.3g\n", preset,
                  int(mode), rmse);
      EXPECT_LT(rmse, 2e-5) << preset << " mode " << int(mode);
    }
}

// The surfaces' radiance follows the render scale as the other targets do.
TEST_F(AerialCompositePass, FollowsTheRenderScale) {
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
