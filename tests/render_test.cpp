// The per-frame renderer on the built-in scene: froxel aerial perspective against the per-pixel
// reference path, transparent objects per vertex against per pixel, clean output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "aerial/render/renderer.h"
#include "aerial/scene/presets.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 180;

ImageRgbF RenderPreset(const std::string& preset, AerialMode mode, LutVariant variant = LutVariant::k4D) {
  const AtmosphereTables& tables = FullTables(4, variant);
  Scene scene = BuildPreset(preset, tables.atmosphere().bottom_radius_m);
  Renderer renderer(tables, scene, {.width = kWidth, .height = kHeight, .mode = mode});
  renderer.Render(scene);
  return renderer.ReadOutput();
}

class Render : public GpuTest {};

TEST_F(Render, OutputIsFiniteAndNonNegative) {
  for (const std::string& preset : PresetNames()) {
    ImageRgbF image = RenderPreset(preset, AerialMode::kFroxel);
    size_t bad = 0;
    for (float v : image.rgba) bad += !(std::isfinite(v) && v >= 0.0f);
    EXPECT_EQ(bad, 0u) << preset;
  }
}

TEST_F(Render, FroxelMatchesPerPixel) {
  ImageRgbF froxel = RenderPreset("noon", AerialMode::kFroxel);
  ImageRgbF per_pixel = RenderPreset("noon", AerialMode::kPerPixel);
  double sum_squared = 0.0, sum_reference = 0.0, worst = 0.0;
  for (size_t i = 0; i < froxel.rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c) {
      double a = froxel.rgba[i + c], b = per_pixel.rgba[i + c];
      sum_squared += (a - b) * (a - b);
      sum_reference += b * b;
      worst = std::max(worst, std::abs(a - b) / std::max(b, 1e-6));
    }
  }
  double rmse = std::sqrt(sum_squared / sum_reference);
  std::printf("froxel vs per-pixel: relative RMSE %.4f%%, worst pixel %.2f%%\n", 100 * rmse, 100 * worst);
  EXPECT_LT(rmse, 0.02);
}

}  // namespace
}  // namespace aerial::testing
