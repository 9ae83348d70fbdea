// The marched per-pixel path's mesh passes (opaque and transparent) in their variant for a high sun
// (aerial/render/sun_high_variant.h, Renderer::MeshPipelinesFor) against the general passes: the
// same image where the renderer picks it, and not picked where the sun is low.
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
  bool sun_high;           // the last frame's mesh passes were the variant
};

// Two frames of a preset on the marched per-pixel path, shadows on, with the variants allowed or not.
Frames RenderPerPixel(const std::string& preset, bool sun_high_variants) {
  const AtmosphereTables& tables = SmallTables();
  Scene scene = BuildPreset(preset, tables.atmosphere().bottom_radius_m);
  RendererOptions options{{.width = 160, .height = 90, .mode = AerialMode::kPerPixel}};
  options.sun_high_variants = sun_high_variants;
  Renderer renderer(tables, scene, options);
  renderer.Render(scene);
  ImageRgbF first = renderer.ReadOutput();
  renderer.Render(scene);
  EXPECT_TRUE(renderer.frame_info().sun_visibility_cached) << "the still frame should read the sun visibility back";
  return {std::move(first), renderer.ReadOutput(), renderer.mesh_sun_high()};
}

class MeshSunHighVariantGpu : public GpuTest {};

// At noon (the balloon, the panes and the particle cloud in front of the terrain) the marched
// points take the same branches in both passes, and the variant has only
// dropped the ones not taken: the same pixels to float rounding (1e-5: the compiler may fold the
// constants in another order; the froxel vs per-pixel target is 2%).
TEST_F(MeshSunHighVariantGpu, SameImageWhereTheSunIsHighOverEverySurface) {
  Frames variant = RenderPerPixel("noon", true);
  Frames general = RenderPerPixel("noon", false);
  EXPECT_TRUE(variant.sun_high);
  EXPECT_FALSE(general.sun_high);
  double first = LargestDifference(general.first, variant.first);
  double still = LargestDifference(general.still, variant.still);
  std::printf("noon: the variant against the general pass, largest relative difference %.3g, still frame %.3g\n",
              first, still);
  EXPECT_LE(first, 1e-5);
  EXPECT_LE(still, 1e-5);
}

// At sunset the far terrain's air has the sun's disc cut by the horizon: not picked.
TEST_F(MeshSunHighVariantGpu, NotPickedWhereTheSunIsLow) {
  EXPECT_FALSE(RenderPerPixel("sunset", true).sun_high);
}

}  // namespace
}  // namespace aerial::testing
