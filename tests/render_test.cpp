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

// The Mie halo is centered on the sun: with the sun just above the horizon ahead of the camera,
// the sky luminance a few degrees left and right of the projected sun position is the same (the
// halo is symmetric about the sun), and the brightest pixel is the sun itself.
TEST_F(Render, SunHaloIsCenteredOnTheSun) {
  const AtmosphereTables& tables = FullTables();
  Scene scene = BuildPreset("noon", tables.atmosphere().bottom_radius_m);
  scene.meshes.clear();  // sky only
  scene.sun = {.zenith_deg = 80.0, .azimuth_deg = 0.0};
  scene.camera.yaw_deg = 0.0;
  scene.camera.pitch_deg = 10.0;
  Renderer renderer(tables, scene, {.width = kWidth, .height = kHeight});
  renderer.Render(scene);
  ImageRgbF image = renderer.ReadOutput();
  // The sun is straight ahead horizontally: its column is the image's middle.
  auto luminance = [&](int x, int y) {
    const float* p = image.pixel(x, y);
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
  };
  int brightest_x = 0, brightest_y = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      if (luminance(x, y) > luminance(brightest_x, brightest_y)) brightest_x = x, brightest_y = y;
  EXPECT_NEAR(brightest_x, kWidth / 2, 1) << "the sun disc is at the middle column";
  for (int dx : {4, 12, 30}) {
    double left = luminance(kWidth / 2 - 1 - dx, brightest_y);
    double right = luminance(kWidth / 2 + dx, brightest_y);
    // Symmetric pixels about the sun's column (the middle falls between pixels 159 and 160); 1%
    // covers the froxel interpolation, which is not involved for sky pixels, and float rounding.
    EXPECT_NEAR(left / right, 1.0, 0.01) << "halo at " << dx << " px";
  }
}

}  // namespace
}  // namespace aerial::testing
