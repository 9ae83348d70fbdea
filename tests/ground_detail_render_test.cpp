// The ground's albedo detail (shaders/include/ground_detail.glsl) in the noon frame of the terrain
// alone, against the same frame without it: texture where a pixel resolves it, the materials'
// brightness kept on average, and none where a pixel spans its wavelengths.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "aerial/render/renderer.h"
#include "aerial/scene.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

constexpr int kWidth = 320, kHeight = 180;

struct GroundFrames {
  ImageRgbF surface, output;  // the lit ground (distance in alpha), and the frame through the air
};

GroundFrames RenderNoonGround(bool detail) {
  const AtmosphereTables& tables = FullTables();
  Scene scene = BuildPreset("noon", tables.atmosphere().bottom_radius_m);
  scene.meshes.clear();
  RendererOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.ground_detail = detail;
  Renderer renderer(tables, scene, options);
  renderer.Render(scene);
  return {renderer.ReadSurface(), renderer.ReadOutput()};
}

double Luminance(const ImageRgbF& image, size_t pixel) {
  const float* p = &image.rgba[4 * pixel];
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

// Per ground pixel within [near_m, far_m) of the camera: the ratio of the two frames' luminance.
struct RatioStats {
  size_t count = 0;
  double mean = 0.0, rms_deviation = 0.0, largest_deviation = 0.0;  // of ratio - 1
};

RatioStats Ratios(const ImageRgbF& with, const ImageRgbF& without, const ImageRgbF& surface, double near_m,
                  double far_m) {
  RatioStats stats;
  double sum = 0.0, sum_squares = 0.0;
  for (size_t p = 0; p < surface.rgba.size() / 4; ++p) {
    double distance = surface.rgba[4 * p + 3];
    if (!(distance >= near_m && distance < far_m)) continue;
    double deviation = Luminance(with, p) / Luminance(without, p) - 1.0;
    ++stats.count;
    sum += deviation;
    sum_squares += deviation * deviation;
    stats.largest_deviation = std::max(stats.largest_deviation, std::abs(deviation));
  }
  if (stats.count == 0) return stats;
  stats.mean = 1.0 + sum / double(stats.count);
  stats.rms_deviation = std::sqrt(sum_squares / double(stats.count));
  return stats;
}

class GroundDetail : public GpuTest {};

TEST_F(GroundDetail, TexturesTheNearGroundKeepsItsBrightnessAndFadesBeyondWhatPixelsResolve) {
  const GroundFrames with = RenderNoonGround(true), without = RenderNoonGround(false);
  // The detail multiplies the lit ground's two parts by one factor, so the ratio of the surfaces
  // is the factor itself; through the air the frame is L T + S, with S the same in both.
  const RatioStats near = Ratios(with.surface, without.surface, with.surface, 0.0, 1000.0);
  const RatioStats near_seen = Ratios(with.output, without.output, with.surface, 0.0, 1000.0);
  const RatioStats mid = Ratios(with.surface, without.surface, with.surface, 2000.0, 5000.0);
  const RatioStats mid_seen = Ratios(with.output, without.output, with.surface, 2000.0, 5000.0);
  const RatioStats all = Ratios(with.surface, without.surface, with.surface, 0.0, 1e9);
  // Beyond 16 km a pixel of this frame (60 degrees over 180 rows: 5.8 mrad) spans more than 93 m
  // of ground, more than half the longest wavelength (70 m): both octaves are faded out.
  const RatioStats far = Ratios(with.surface, without.surface, with.surface, 16e3, 1e9);
  std::printf("ground detail, noon, %dx%d: within 1 km %zu pixels, rms %.4f (in the frame %.4f); all %zu pixels, "
              "mean %.4f; 2-5 km rms %.4f (in the frame %.4f); beyond 16 km %zu pixels, largest %.2e\n",
              kWidth, kHeight, near.count, near.rms_deviation, near_seen.rms_deviation, all.count, all.mean,
              mid.rms_deviation, mid_seen.rms_deviation, far.count, far.largest_deviation);
  ASSERT_GT(near.count, 5000u);
  ASSERT_GT(far.count, 1000u);
  // Two octaves of amplitude 0.12 and 0.16 of value noise whose deviation is about 0.4: about
  // 0.08 where both are resolved. Measured 0.067; the lower bound fails without the detail (0),
  // the upper one with the amplitudes doubled.
  EXPECT_GT(near.rms_deviation, 0.04);
  EXPECT_LT(near.rms_deviation, 0.12);
  // Through the air the detail's contrast is that of L T against L T + S: within 1 km the
  // inscatter S is a few per mille of the ground's radiance (measured 0.996 of the surface's
  // contrast), at 2-5 km about a sixth of it (0.86). Detail applied after the air would keep 1.
  EXPECT_GT(near_seen.rms_deviation / near.rms_deviation, 0.97);
  EXPECT_LT(mid_seen.rms_deviation / mid.rms_deviation, 0.95);
  EXPECT_GT(mid_seen.rms_deviation / mid.rms_deviation, 0.6);
  // The factor's mean is 1 over its lattice; the frame samples a few hundred cells of the short
  // octave and tens of the long one, so its mean is 1 within about 0.16 / sqrt(30) = 3% (measured
  // 0.997).
  EXPECT_NEAR(all.mean, 1.0, 0.03);
  // Frequency clamping: no noise where a pixel cannot resolve it (it would alias).
  EXPECT_LT(far.largest_deviation, 1e-5);
}

}  // namespace
}  // namespace aerial::testing
