// The viewer's GPU meter reading what the PNG's meter reads, and its adaptation over time (the
// presets' pictures themselves: preset_pictures_test.cpp).
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

class Exposure_ : public GpuTest {};

// The viewer meters on the GPU (a 64x64 lattice into histograms of 0.1875-stop bins) what a PNG
// meters on the CPU (every pixel, sorted), the average and the highlight: each within 0.25 stop, a
// bin's width plus the lattice's sampling of a 160x90 frame, on a daylight, a twilight and a
// high-altitude frame (at most 0.05 stop for the average, 0.08 for the highlight). A meter that
// read the wrong channels (blue alone weighs 0.07) or the wrong end of the histogram would be off
// by stops.
TEST_F(Exposure_, TheViewersGpuMeterReadsWhatThePngMeterReads) {
  viewer::ExposureMeter meter(SharedContext(), 1);
  for (const char* preset : {"noon", "twilight", "high-altitude"}) {
    Scene scene = BuildPreset(preset, SmallPublicTables().atmosphere().bottom_radius_m);
    SceneRenderer renderer(SmallPublicTables(), scene, RenderOptions{.width = kWidth, .height = kHeight});
    renderer.Render(scene);
    const std::array<double, 3> gains = {0.9, 1.0, 1.1};
    SharedContext().Submit([&](const vk::CommandBuffer& cmd) { meter.Record(cmd, 0, renderer.output(), gains); });
    std::optional<MeterReading> gpu = meter.TakeReading(0);
    ASSERT_TRUE(gpu) << preset;
    MeterReading cpu = ReadMeter(renderer.ReadOutput(), gains);
    std::printf("%-14s meter: GPU %.1f, highlight %.1f cd/m^2; CPU %.1f, highlight %.1f cd/m^2\n", preset,
                gpu->average_luminance, gpu->highlight, cpu.average_luminance, cpu.highlight);
    EXPECT_NEAR(std::log2(gpu->average_luminance / cpu.average_luminance), 0.0, 0.25) << preset;
    EXPECT_NEAR(std::log2(gpu->highlight / cpu.highlight), 0.0, 0.25) << preset;
    EXPECT_FALSE(meter.TakeReading(0)) << "a reading is taken once";
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
