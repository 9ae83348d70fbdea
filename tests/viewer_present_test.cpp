// The viewer's GPU tone map (shaders/include/tone_map.glsl) against the CPU's
// (src/aerial/image/tone_map.cpp), which writes the PNGs: the window must show what a PNG of the
// same frame holds.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>

#include "aerial/api/impl.h"
#include "aerial/image/tone_map.h"
#include "aerial/viewer/display_passes.h"
#include "aerial/vk/compute_pipeline.h"
#include "display_target.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

constexpr uint32_t kRampSize = 1024;

// Radiance from 0 to 12 (far into the curve's shoulder, which starts at 0.76), cubed so that the
// sRGB toe (below 0.0031308) and the curve's toe (below 0.08) get most of the samples; each channel
// a different slice, so that the colour changes along the ramp as the curve's mixing needs.
ImageRgbF Ramp(double scale) {
  ImageRgbF ramp{int(kRampSize), 1, std::vector<float>(kRampSize * 4)};
  for (uint32_t i = 0; i < kRampSize; ++i) {
    double s = double(i) / (kRampSize - 1);
    ramp.rgba[4 * i + 0] = float(scale * 12.0 * s * s * s);
    ramp.rgba[4 * i + 1] = float(scale * 1.0 * s * s);
    ramp.rgba[4 * i + 2] = float(scale * 0.01 * s);
    ramp.rgba[4 * i + 3] = 1.0f;
  }
  return ramp;
}

class ViewerToneMap : public GpuTest {};

// Before rounding to 8 bits. The GPU evaluates the same expressions in float32 against the CPU's
// double: the curve's rational shoulder and pow(x, 1/2.4) each lose a few ulps (~1e-6 relative), so 1e-3
// (a quarter of an 8-bit step) leaves three orders of magnitude of margin and still catches any
// change of a constant or of a branch point.
TEST_F(ViewerToneMap, GpuMatchesCpuBeforeRounding) {
  vk::Context& context = SharedContext();
  ImageRgbF ramp = Ramp(1.0);
  vk::Image input = Upload(ramp);
  vk::Image output(context, {.extent = {kRampSize, 1, 1}});
  ::vk::raii::Sampler sampler = vk::CreateLinearClampSampler(context);
  vk::ComputePipeline pipeline(context, "test/tone_map.comp", {{"radiance_image", vk::kSampled}, {"display_values", vk::kStorageImage}});
  context.Submit([&](const auto& cmd) {
    output.InitializeLayout(cmd);
    pipeline.Dispatch(cmd, {vk::SampledImageSlot{&input, *sampler}, vk::StorageImageSlot{&output}},
                      {kRampSize, 1, 1}, {64, 1, 1});
    vk::FullBarrier(cmd);
  });
  std::vector<std::byte> bytes = ReadBack(output);
  std::vector<float> gpu(kRampSize * 4);
  std::memcpy(gpu.data(), bytes.data(), bytes.size());
  double worst = 0.0;
  for (size_t i = 0; i < kRampSize; ++i) {
    const float* in = &ramp.rgba[4 * i];
    std::array<double, 3> cpu = ToneMapColour({in[0], in[1], in[2]});
    for (size_t c = 0; c < 3; ++c) worst = std::max(worst, std::abs(gpu[4 * i + c] - cpu[c]));
  }
  std::printf("GPU vs CPU tone map, worst difference before rounding: %.2e\n", worst);
  EXPECT_LT(worst, 1e-3);
}

// The viewer's present pass, exposure and dither included, against the PNG encoder: equal bytes
// except where the two sit on either side of a rounding boundary (1 step, given the 1e-3 above; an
// _SRGB target's dither goes through the encoding's slope approximated, within a fraction of a
// step). In every display
// format: the swapchain's is often BGRA, and the shader's store must land in the right channels;
// an _SRGB one encodes with the driver's conversion instead of the shader's.
TEST_F(ViewerToneMap, PresentPassMatchesPngBytes) {
  vk::Context& context = SharedContext();
  const float exposure = 8.0f;
  ImageRgbF ramp = Ramp(1.0 / exposure);
  vk::Image input = Upload(ramp);
  // The present pass reads images as the public API hands them out (the pass's own sampler).
  SampledImage sampled_input = ToSampledImage({&input, VK_NULL_HANDLE});
  std::vector<uint8_t> png = ToneMapToSrgb8(ramp, {.exposure = exposure});
  for (auto [format, red] : {std::pair{::vk::Format::eR8G8B8A8Unorm, 0}, std::pair{::vk::Format::eB8G8R8A8Unorm, 2},
                             std::pair{::vk::Format::eR8G8B8A8Srgb, 0}, std::pair{::vk::Format::eB8G8R8A8Srgb, 2}}) {
    DisplayTarget target(context, kRampSize, 1, format);
    viewer::DisplayPasses passes(context, target.render_pass(), format);
    std::vector<uint8_t> display =
        target.Draw([&](const auto& cmd) { passes.RecordToneMap(cmd, target.extent(), sampled_input, exposure); });
    int worst = 0, differing = 0;
    for (size_t i = 0; i < kRampSize; ++i) {
      for (int c = 0; c < 3; ++c) {
        int stored = c == 1 ? 1 : (c == 0 ? red : 2 - red);  // where channel c sits in the format
        int d = std::abs(int(display[4 * i + stored]) - int(png[4 * i + c]));
        worst = std::max(worst, d);
        differing += d > 0;
      }
    }
    std::printf("present pass (%s) vs PNG bytes: %d of %u differ, by at most %d\n",
                ::vk::to_string(format).c_str(), differing, 3 * kRampSize, worst);
    EXPECT_LE(worst, 1) << ::vk::to_string(format);
  }
}

}  // namespace
}  // namespace aerial::testing
