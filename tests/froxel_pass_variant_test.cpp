// CTest label "sanitizer": the froxel pass's variants: run under the sanitizers too.
// The froxel pass's variant for a high sun (froxel/froxel_pass_variant.h) against the general
// pass, both built from the same frame block: the same volume where the renderer would pick it,
// and a different one where the sun is low, which is why it is not picked there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>

#include "aerial/render/frame_uniforms.h"
#include "aerial/scene.h"
#include "aerial/vk/resources.h"
#include "froxel/froxel_volume.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

// The largest relative difference over every froxel's Rayleigh, Mie and transmittance channels.
double LargestDifference(const FroxelTexels& a, const FroxelTexels& b) {
  double worst = 0.0;
  for (auto member : {&FroxelTexels::rayleigh, &FroxelTexels::mie, &FroxelTexels::transmittance}) {
    const std::vector<float>& x = a.*member;
    const std::vector<float>& y = b.*member;
    for (size_t i = 0; i < x.size(); ++i) {
      if (i % 4 == 3) continue;  // w: unused
      double scale = std::max(std::abs(double(x[i])), 1e-30);
      worst = std::max(worst, std::abs(double(y[i]) - double(x[i])) / scale);
    }
  }
  return worst;
}

struct Comparison {
  FroxelPassVariant chosen;  // for the preset's frame
  double difference;         // LargestDifference of the variant's volume from the general pass's
};

// A preset's frame block, its volume built by both passes, and the variant the renderer chooses.
Comparison CompareVariants(const std::string& preset) {
  const AtmosphereTables& tables = SmallTables();
  const vk::Context& context = tables.context();
  const double R = tables.atmosphere().bottom_radius_m;
  const FroxelGrid grid{.width = 16, .height = 16, .depth = 32};
  FrameUniforms frame = MakeFrameUniforms(BuildPreset(preset, R), R, 320, 180, grid);
  vk::Buffer block(context, vk::UniformBufferInfo(sizeof(FrameUniforms)));
  block.Write(std::as_bytes(std::span(&frame, 1)));
  auto build = [&](FroxelPassVariant variant) {
    FroxelVolume volume(context, grid);
    context.Submit([&](const vk::CommandBuffer& cmd) { volume.Build(cmd, tables, block, variant); });
    return volume.Read(context, frame);
  };
  Comparison result{ChooseFroxelPassVariant(frame, R),
                    LargestDifference(build(FroxelPassVariant::kGeneral), build(FroxelPassVariant::kSunHigh))};
  std::printf("%s: the variant against the general pass, largest relative difference %.3g\n", preset.c_str(),
              result.difference);
  return result;
}

class FroxelPassVariantGpu : public GpuTest {};

// At noon both passes take the same branches at every point, and the variant has only dropped the
// ones not taken: the same texels, to float rounding (1e-5: the compiler may fold the constants in
// another order; the froxel vs per-pixel target is 2%).
TEST_F(FroxelPassVariantGpu, SameVolumeWhereTheSunIsHighOverEveryFroxel) {
  Comparison noon = CompareVariants("noon");
  EXPECT_EQ(noon.chosen, FroxelPassVariant::kSunHigh);
  EXPECT_LE(noon.difference, 1e-5);
}

// At sunset the disc is cut by the horizon and J_ms is in the Earth's shadow for some froxels:
// the variant would be wrong there (more than 1% somewhere), and it is not chosen.
TEST_F(FroxelPassVariantGpu, DifferentVolumeWhereTheSunIsLowAndNotChosenThere) {
  Comparison sunset = CompareVariants("sunset");
  EXPECT_EQ(sunset.chosen, FroxelPassVariant::kGeneral);
  EXPECT_GT(sunset.difference, 1e-2);
}

}  // namespace
}  // namespace aerial::testing
