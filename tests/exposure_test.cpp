// Pictures exposed as a camera would at the defaults: every preset's PNG within the brightness a
// viewer expects, and the viewer's GPU meter reading what the PNG's meter reads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "aerial/api/impl.h"
#include "aerial/image.h"
#include "aerial/image/exposure.h"
#include "aerial/scene.h"
#include "aerial/viewer/exposure_meter.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

constexpr int kWidth = 160, kHeight = 90;

struct PictureStats {
  double median_luma;     // Rec. 709 luma of the 8-bit values, over full scale
  double clipped;         // fraction of pixels with a channel at 255
  double near_black;      // fraction of pixels with every channel at or below 3
};

PictureStats Measure(const std::vector<uint8_t>& rgba) {
  std::vector<double> luma;
  size_t clipped = 0, near_black = 0;
  for (size_t i = 0; i < rgba.size(); i += 4) {
    uint8_t r = rgba[i], g = rgba[i + 1], b = rgba[i + 2];
    luma.push_back((0.2126 * r + 0.7152 * g + 0.0722 * b) / 255.0);
    clipped += std::max({r, g, b}) == 255;
    near_black += std::max({r, g, b}) <= 3;
  }
  std::nth_element(luma.begin(), luma.begin() + luma.size() / 2, luma.end());
  double n = double(luma.size());
  return {luma[luma.size() / 2], double(clipped) / n, double(near_black) / n};
}

class Exposure_ : public GpuTest {};

// The bounds on the default exposure: median luma 0.25-0.6 of full scale, at most 1% of
// pixels clipped, at most 5% at or below 3/255. Twilight's median may be darker: its ground, lit
// by the sky alone, is about 5 stops under the glow above the horizon, and the meter keeps the
// glow from clipping (aerial/image/exposure.h; 0.23 measured at 160x90 with the small tables); not below 0.2.
TEST_F(Exposure_, EveryPresetIsWellExposedAtTheDefaults) {
  for (const std::string& preset : PresetNames()) {
    Scene scene = BuildPreset(preset, SmallPublicTables().atmosphere().bottom_radius_m);
    SceneRenderer renderer(SmallPublicTables(), scene, RenderOptions{.width = kWidth, .height = kHeight});
    renderer.Render(scene);
    ImageRgbF frame = renderer.ReadOutput();
    PictureStats stats = Measure(ToneMapToSrgb8(frame, {.exposure = Exposure{}.MultiplierFor(frame)}));
    std::printf("%-14s median luma %.3f, clipped %.2f%%, near black %.2f%%\n", preset.c_str(), stats.median_luma,
                100 * stats.clipped, 100 * stats.near_black);
    EXPECT_GE(stats.median_luma, preset == "twilight" ? 0.2 : 0.25) << preset;
    EXPECT_LE(stats.median_luma, 0.6) << preset;
    EXPECT_LE(stats.clipped, 0.01) << preset;
    EXPECT_LE(stats.near_black, 0.05) << preset;
  }
}

// The viewer meters on the GPU (a 64x64 lattice into a histogram of 0.1875-stop bins) what a PNG
// meters on the CPU (every pixel, sorted): within 0.25 stop, a bin's width plus the lattice's
// sampling of a 160x90 frame, on a daylight, a twilight and a high-altitude frame (measured 0.05,
// 0.0 and 0.01 stop). A meter that read the wrong channels (blue alone weighs 0.07) or the wrong
// end of the histogram would be off by stops.
TEST_F(Exposure_, TheViewersGpuMeterReadsWhatThePngMeterReads) {
  viewer::ExposureMeter meter(SharedContext(), 1);
  for (const char* preset : {"noon", "twilight", "high-altitude"}) {
    Scene scene = BuildPreset(preset, SmallPublicTables().atmosphere().bottom_radius_m);
    SceneRenderer renderer(SmallPublicTables(), scene, RenderOptions{.width = kWidth, .height = kHeight});
    renderer.Render(scene);
    SharedContext().Submit([&](const vk::CommandBuffer& cmd) { meter.Record(cmd, 0, renderer.output()); });
    std::optional<double> gpu = meter.TakeAverageLuminance(0);
    ASSERT_TRUE(gpu) << preset;
    double cpu = LogAverageLuminance(renderer.ReadOutput());
    std::printf("%-14s meter: GPU %.1f cd/m^2, CPU %.1f cd/m^2\n", preset, *gpu, cpu);
    EXPECT_NEAR(std::log2(*gpu / cpu), 0.0, 0.25) << preset;
    EXPECT_FALSE(meter.TakeAverageLuminance(0)) << "a reading is taken once";
  }
}

// The viewer's adaptation: exponential toward the metered value, a time constant of 1 s.
TEST(AutoExposure, AdaptsTowardTheMeterOverTime) {
  EXPECT_DOUBLE_EQ(viewer::AdaptEv100(10.0, 14.0, 0.0), 10.0);
  EXPECT_NEAR(viewer::AdaptEv100(10.0, 14.0, 1.0), 14.0 - 4.0 / std::exp(1.0), 1e-12);
  EXPECT_NEAR(viewer::AdaptEv100(10.0, 14.0, 100.0), 14.0, 1e-9);
  // Two half steps are one whole step: the frame rate does not change the speed.
  EXPECT_NEAR(viewer::AdaptEv100(viewer::AdaptEv100(10.0, 14.0, 0.5), 14.0, 0.5), viewer::AdaptEv100(10.0, 14.0, 1.0),
              1e-12);
}

}  // namespace
}  // namespace aerial::testing
