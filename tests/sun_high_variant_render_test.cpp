// The frame's passes in their variants for a high sun (froxel/sun_high_variant.h) against the
// general passes: on the marched per-pixel path the mesh passes (opaque and transparent,
// Renderer::MeshPipelinesFor) and the sky (Renderer::SkyPipelineFor); in froxel mode the froxel
// pass and the sky-view lattice's correction (Renderer::SkyViewCorrectionPipelineFor). The same
// image where the renderer picks them, and not picked where the sun is too low.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "aerial/render/renderer.h"
#include "aerial/scene.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

// The largest relative difference over every pixel's channels.
double LargestDifference(const ImageRgbF& a, const ImageRgbF& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.rgba.size(); ++i) {
    double scale = std::max(std::abs(double(a.rgba[i])), 1e-30);
    worst = std::max(worst, std::abs(double(b.rgba[i]) - double(a.rgba[i])) / scale);
  }
  return worst;
}

struct Frames {
  ImageRgbF first, still;  // the first frame (sun visibility looked up and written) and a still one (read back)
  bool mesh_sun_high, sky_sun_high;  // the last frame's passes were the variants
};

// Two frames of a preset, shadows on, with the variants allowed or not.
Frames RenderFrames(const AtmosphereTables& tables, const std::string& preset, AerialMode mode,
                    bool sun_high_variants) {
  Scene scene = BuildPreset(preset, tables.atmosphere().bottom_radius_m);
  RendererOptions options{{.width = 160, .height = 90, .mode = mode}};
  options.sun_high_variants = sun_high_variants;
  Renderer renderer(tables, scene, options);
  renderer.Render(scene);
  ImageRgbF first = renderer.ReadOutput();
  renderer.Render(scene);
  EXPECT_TRUE(renderer.frame_info().sun_visibility_cached) << "the still frame should read the sun visibility back";
  return {std::move(first), renderer.ReadOutput(), renderer.mesh_sun_high(), renderer.sky_sun_high()};
}

// The variants' frames against the general passes'. Where the variants are picked, the marched
// points take the same branches in both, and the variants have only dropped the ones not taken:
// the same pixels to float rounding (1e-5: the compiler may fold the constants in another order;
// the froxel vs per-pixel target is 2%).
Frames CompareAtNoon(const AtmosphereTables& tables, AerialMode mode, const char* name) {
  Frames variant = RenderFrames(tables, "noon", mode, true);
  Frames general = RenderFrames(tables, "noon", mode, false);
  EXPECT_FALSE(general.mesh_sun_high || general.sky_sun_high);
  double first = LargestDifference(general.first, variant.first);
  double still = LargestDifference(general.still, variant.still);
  std::printf("noon, %s: the variants against the general passes, largest relative difference %.3g, still frame %.3g\n",
              name, first, still);
  EXPECT_LE(first, 1e-5);
  EXPECT_LE(still, 1e-5);
  return variant;
}

class SunHighVariantRenderGpu : public GpuTest {};

// The default tables' 36 mu_s texels: the sky's lowest marched sun (the texel below the read's
// pair) is 23 degrees up at noon, and both variants are picked. The balloon, the panes and the
// particle cloud stand in front of the terrain.
TEST_F(SunHighVariantRenderGpu, PerPixelSameImageWithBothVariantsAtNoonWithTheDefaultTables) {
  Frames variant = CompareAtNoon(FullTables(), AerialMode::kPerPixel, "per pixel, default tables");
  EXPECT_TRUE(variant.mesh_sun_high);
  EXPECT_TRUE(variant.sky_sun_high);
}

// The small tables' 16 mu_s texels put that sun 9.8 degrees up, too low for the 7.9 degrees of arc
// of the longest sky ray: the sky keeps its general pass.
TEST_F(SunHighVariantRenderGpu, PerPixelSameImageWithTheMeshVariantAtNoonWithTheSmallTables) {
  Frames variant = CompareAtNoon(SmallTables(), AerialMode::kPerPixel, "per pixel, small tables");
  EXPECT_TRUE(variant.mesh_sun_high);
  EXPECT_FALSE(variant.sky_sun_high);
}

// At sunset the far terrain's air and the sky have the sun's disc cut by the horizon: neither.
TEST_F(SunHighVariantRenderGpu, PerPixelNeitherPickedWhereTheSunIsLow) {
  Frames sunset = RenderFrames(FullTables(), "sunset", AerialMode::kPerPixel, true);
  EXPECT_FALSE(sunset.mesh_sun_high);
  EXPECT_FALSE(sunset.sky_sun_high);
}

// In froxel mode the first frame makes the whole sky-view lattice, with its variant at noon with
// the default tables; the froxel pass takes its own (froxel_pass_variant.h). The mesh passes march
// nothing there.
TEST_F(SunHighVariantRenderGpu, FroxelModeSameImageWithTheSkyViewVariantAtNoon) {
  Frames variant = CompareAtNoon(FullTables(), AerialMode::kFroxel, "froxels, default tables");
  EXPECT_FALSE(variant.mesh_sun_high);
  EXPECT_TRUE(variant.sky_sun_high);
  EXPECT_FALSE(RenderFrames(FullTables(), "sunset", AerialMode::kFroxel, true).sky_sun_high);
}

}  // namespace
}  // namespace aerial::testing
