// Supersampling (`aerial render --supersample N`: the mean of N x N frames, each drawn with the
// camera jittered to a sub-pixel's centre): the noon frame's edges (ridges against the sky, the
// landmarks, the balloon) against the mean of 4 x 4 such frames, in display values at one fixed
// exposure; and the jittered mean against a frame drawn larger and box-filtered down.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "aerial/image.h"
#include "aerial/image/exposure.h"
#include "aerial/image/resample.h"
#include "aerial/render/renderer.h"
#include "aerial/scene.h"
#include "aerial/scene/camera.h"
#include "aerial/validation/image_metrics.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

constexpr int kWidth = 160, kHeight = 90;

// The noon preset, rendered `factor` times larger on each side and box-filtered to 160x90. The
// fixed terrain mesh, so that the frames differ in their sampling alone (the level of detail
// would follow their sizes); the ground's detail, which each frame fades by its own pixel's
// footprint (ground_detail.glsl), on or off.
ImageRgbF RenderLarger(int factor, bool ground_detail) {
  const AtmosphereTables& tables = SmallTables();
  Scene scene = BuildPreset("noon", tables.atmosphere().bottom_radius_m);
  RendererOptions options{{.width = kWidth * factor, .height = kHeight * factor}, TerrainMode::kStaticMesh};
  options.ground_detail = ground_detail;
  Renderer renderer(tables, scene, options);
  renderer.Render(scene);
  return DownsampleBox(renderer.ReadOutput(), factor);
}

// RMSE of the display values (0 to 1, undithered) over the pixels whose 3x3 neighbourhood in the
// reference spans more than 0.1 in some channel: the edges, where sampling once per pixel makes
// stair steps.
double EdgeRmse(const std::vector<uint8_t>& image, const std::vector<uint8_t>& reference, size_t& edges) {
  double sum = 0.0;
  edges = 0;
  for (int y = 1; y + 1 < kHeight; ++y) {
    for (int x = 1; x + 1 < kWidth; ++x) {
      bool edge = false;
      for (int c = 0; c < 3 && !edge; ++c) {
        int low = 255, high = 0;
        for (int j = -1; j <= 1; ++j)
          for (int i = -1; i <= 1; ++i) {
            int v = reference[4 * (size_t(y + j) * kWidth + size_t(x + i)) + c];
            low = std::min(low, v), high = std::max(high, v);
          }
        edge = high - low > 0.1 * 255;
      }
      if (!edge) continue;
      edges += 1;
      for (int c = 0; c < 3; ++c) {
        size_t k = 4 * (size_t(y) * kWidth + size_t(x)) + c;
        sum += std::pow((double(image[k]) - reference[k]) / 255.0, 2);
      }
    }
  }
  return edges ? std::sqrt(sum / double(3 * edges)) : 0.0;
}

// The noon preset at 160x90, one sample per pixel, as the mean of frames drawn with the camera
// jittered to each of `jitters` (Camera::jitter_px), as `aerial render` supersamples and the
// viewer refines a still view.
ImageRgbF RenderJitteredMean(const std::vector<glm::dvec2>& jitters, bool ground_detail = true) {
  const AtmosphereTables& tables = SmallTables();
  Scene scene = BuildPreset("noon", tables.atmosphere().bottom_radius_m);
  RendererOptions options{{.width = kWidth, .height = kHeight}, TerrainMode::kStaticMesh};
  options.ground_detail = ground_detail;
  Renderer renderer(tables, scene, options);
  ImageRgbF mean{kWidth, kHeight, std::vector<float>(size_t(4) * kWidth * kHeight, 0.0f)};
  for (glm::dvec2 jitter : jitters) {
    scene.camera.jitter_px = jitter;
    renderer.Render(scene);
    ImageRgbF frame = renderer.ReadOutput();
    for (size_t i = 0; i < mean.rgba.size(); ++i) mean.rgba[i] += frame.rgba[i] / float(jitters.size());
  }
  return mean;
}

ImageRgbF RenderSupersampled(int n) { return RenderJitteredMean(SupersampleJitters(n)); }

class Antialiasing : public GpuTest {};

// One sample per pixel is far from the 16-sample reference on the edges; the command's default 2x2
// is less than half as far (0.029 and 0.013 measured at this size; `aerial render` at 640x360
// gives the figures of docs/speed.md, "Figures"). The bounds sit between the two.
TEST_F(Antialiasing, SupersamplingRemovesTheStairSteps) {
  ImageRgbF reference = RenderSupersampled(4);
  ToneMapOptions display{.exposure = Exposure{}.MultiplierFor(reference), .dither = false};
  std::vector<uint8_t> reference8 = ToneMapToSrgb8(reference, display);
  size_t edges = 0;
  double once = EdgeRmse(ToneMapToSrgb8(RenderSupersampled(1), display), reference8, edges);
  double twice = EdgeRmse(ToneMapToSrgb8(RenderSupersampled(2), display), reference8, edges);
  std::printf("edge RMSE against 4x4 samples (%zu edge pixels): 1 sample %.4f, 2x2 samples %.4f\n", edges, once,
              twice);
  EXPECT_GT(edges, size_t(kWidth * kHeight / 50));  // the frame has edges to measure
  EXPECT_GT(once, 0.025);
  EXPECT_LE(twice, 0.018);
}

// Four frames jittered to the centres of each pixel's quadrants sample the points that a frame
// twice as large samples, so their mean antialiases as that frame does (edge RMSE against 4x4
// samples measured 0.0133, the larger frame's 0.0136). It is not that frame to the bit: each
// jittered frame builds its froxel volume for its own frustum, and what follows the pixel's size
// differs, such as the triangles whose froxel reads are per pixel rather than per vertex
// (surface_reads.h): measured 6.6e-3 relative RMSE between the two, where one sample per pixel is
// 5.1e-2. The ground's detail is left out of this comparison: each frame fades it by its own
// pixel's footprint, which the larger frame halves (with it, 1.6e-2). One jitter alone is the
// 1-sample frame moved, as far from the reference as no jitter.
TEST_F(Antialiasing, FourJitteredFramesSampleWhatAFrameTwiceAsLargeSamples) {
  ImageRgbF reference = RenderJitteredMean(SupersampleJitters(4), false);
  ToneMapOptions display{.exposure = Exposure{}.MultiplierFor(reference), .dither = false};
  std::vector<uint8_t> reference8 = ToneMapToSrgb8(reference, display);
  ImageRgbF mean = RenderJitteredMean(SupersampleJitters(2), false), larger = RenderLarger(2, false);
  double to_larger = validation::EnergyWeightedRelativeRmse(mean, larger);
  size_t edges = 0;
  double jittered = EdgeRmse(ToneMapToSrgb8(mean, display), reference8, edges);
  double in_larger = EdgeRmse(ToneMapToSrgb8(larger, display), reference8, edges);
  ImageRgbF once = RenderJitteredMean({{0.25, 0.25}}, false);
  double shifted = EdgeRmse(ToneMapToSrgb8(once, display), reference8, edges);
  std::printf("4 jittered frames: %.2e from the 2x larger frame (one: %.2e), edge RMSE %.4f against 4x4 (larger "
              "frame %.4f, one %.4f)\n",
              to_larger, validation::EnergyWeightedRelativeRmse(once, larger), jittered, in_larger, shifted);
  EXPECT_LT(to_larger, 1e-2);
  EXPECT_LE(jittered, 0.018);
  EXPECT_LE(in_larger, 0.018);
  EXPECT_GT(shifted, 0.025);
}

}  // namespace
}  // namespace aerial::testing
