// ReadTable (shaders/include/table_read.glsl) under each AERIAL_TABLE_FILTERING: tables whose
// values are linear in the texel index, so that the exact bilinear and trilinear blends are known,
// read between their texels. The shader's blend is exact in float; the emulated hardware blend
// uses the weights rounded to 1/256 of a texel, as GPUs' samplers do (subTexelPrecisionBits = 8).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "aerial/error.h"
#include "aerial/vk/compute_pipeline.h"
#include "aerial/vk/context.h"
#include "aerial/vk/resources.h"
#include "scoped_table_filtering.h"

namespace aerial::testing {
namespace {

// Value at texel (x, y, z) of both tables: linear, so the blend of the 8 (or 4) texels around a
// point is the same linear function of the blend weights.
float TexelValue(int x, int y, int z) { return float(x) + 2.0f * float(y) + 4.0f * float(z); }

struct Read {
  float value_2d, value_3d;
};

// Reads a 2x2 and a 2x2x2 table at the weights (fractions of the way from texel 0 to texel 1).
std::vector<Read> ReadBetweenTexels(const std::vector<std::array<float, 3>>& weights) {
  vk::Context context({.validation = true});
  vk::Image table_2d(context, {.extent = {2, 2, 1}});
  vk::Image table_3d(context, {.extent = {2, 2, 2}});
  std::vector<float> texels;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x)
        for (int c = 0; c < 4; ++c) texels.push_back(TexelValue(x, y, z));
  auto host_buffer = [&](size_t bytes) {
    return vk::Buffer(context, {.size = bytes,
                                .usage = ::vk::BufferUsageFlagBits::eStorageBuffer |
                                         ::vk::BufferUsageFlagBits::eTransferSrc,
                                .host_visible = true});
  };
  vk::Buffer texel_buffer = host_buffer(texels.size() * sizeof(float));
  std::memcpy(texel_buffer.mapped(), texels.data(), texels.size() * sizeof(float));
  // A coordinate at weight w between the centres of texels 0 and 1 of a 2-texel axis.
  std::vector<float> uvw;
  for (const auto& w : weights)
    for (int axis = 0; axis < 4; ++axis) uvw.push_back(axis < 3 ? (0.5f + w[axis]) / 2.0f : 0.0f);
  vk::Buffer queries = host_buffer(uvw.size() * sizeof(float));
  std::memcpy(queries.mapped(), uvw.data(), uvw.size() * sizeof(float));
  vk::Buffer results = host_buffer(weights.size() * 32);
  ::vk::raii::Sampler sampler = vk::CreateLinearClampSampler(context);
  vk::ComputePipeline read(context, "test/table_read.comp",
                           {{"table_2d", vk::kSampled}, {"table_3d", vk::kSampled},
                            {"Queries", vk::kStorageBuffer}, {"Results", vk::kStorageBuffer}});
  context.Submit([&](const auto& cmd) {
    table_2d.InitializeLayout(cmd);
    table_3d.InitializeLayout(cmd);
    table_2d.CopyFromBuffer(cmd, texel_buffer);  // the first 4 texels: z = 0
    table_3d.CopyFromBuffer(cmd, texel_buffer);
    vk::FullBarrier(cmd);
    read.Dispatch(cmd, {vk::SampledImageSlot{&table_2d, *sampler}, vk::SampledImageSlot{&table_3d, *sampler},
                        vk::StorageBufferSlot{&queries}, vk::StorageBufferSlot{&results}},
                  {uint32_t(weights.size()), 1, 1}, {64, 1, 1});
    vk::FullBarrier(cmd);
  });
  std::vector<Read> reads(weights.size());
  const float* values = reinterpret_cast<const float*>(results.mapped());
  for (size_t i = 0; i < reads.size(); ++i) reads[i] = {values[8 * i], values[8 * i + 4]};
  return reads;
}

// Weights that are not multiples of 1/256, on every axis, spread over the texel cell.
std::vector<std::array<float, 3>> Weights() {
  std::vector<std::array<float, 3>> weights;
  for (int i = 0; i < 100; ++i)
    weights.push_back({(float(i) + 0.37f) / 100.0f, std::fmod(float(i) * 0.173f + 0.011f, 1.0f),
                       std::fmod(float(i) * 0.291f + 0.0043f, 1.0f)});
  return weights;
}

float Blend2d(const std::array<float, 3>& w) { return w[0] + 2.0f * w[1]; }
float Blend3d(const std::array<float, 3>& w) { return w[0] + 2.0f * w[1] + 4.0f * w[2]; }
std::array<float, 3> RoundedTo256ths(const std::array<float, 3>& w) {
  return {std::round(w[0] * 256.0f) / 256.0f, std::round(w[1] * 256.0f) / 256.0f, std::round(w[2] * 256.0f) / 256.0f};
}

// Float rounding of the coordinate and of the blend, on values up to 7: well under 1e-5. The
// rounding to 1/256 moves a weight by up to 1/512 = 2e-3 and the sum by up to 7/512 = 1.4e-2,
// so a blend that skipped or misplaced the rounding fails by orders of magnitude more.
constexpr float kTolerance = 1e-5f;

TEST(TableRead, TheShaderBlendsInFloat) {
  ScopedTableFiltering filtering(vk::TableFiltering::kShader);
  std::vector<std::array<float, 3>> weights = Weights();
  std::vector<Read> reads = ReadBetweenTexels(weights);
  for (size_t i = 0; i < weights.size(); ++i) {
    EXPECT_NEAR(reads[i].value_2d, Blend2d(weights[i]), kTolerance) << "query " << i;
    EXPECT_NEAR(reads[i].value_3d, Blend3d(weights[i]), kTolerance) << "query " << i;
  }
}

TEST(TableRead, EmulatedHardwareRoundsTheWeightsTo256ths) {
  ScopedTableFiltering filtering(vk::TableFiltering::kEmulatedHardware);
  std::vector<std::array<float, 3>> weights = Weights();
  std::vector<Read> reads = ReadBetweenTexels(weights);
  int apart_from_float = 0;
  for (size_t i = 0; i < weights.size(); ++i) {
    EXPECT_NEAR(reads[i].value_2d, Blend2d(RoundedTo256ths(weights[i])), kTolerance) << "query " << i;
    EXPECT_NEAR(reads[i].value_3d, Blend3d(RoundedTo256ths(weights[i])), kTolerance) << "query " << i;
    if (std::abs(reads[i].value_3d - Blend3d(weights[i])) > 10.0f * kTolerance) ++apart_from_float;
  }
  // The rounding shows: most weights are not within 1e-5 of a 256th.
  EXPECT_GT(apart_from_float, 90);
}

TEST(TableRead, AnUnknownFilteringIsANamedError) {
  ::setenv("AERIAL_TABLE_FILTERING", "bilinear", 1);
  try {
    vk::TableFilteringFromEnvironment();
    ADD_FAILURE() << "accepted AERIAL_TABLE_FILTERING=bilinear";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "AERIAL_TABLE_FILTERING");
    EXPECT_NE(std::string(e.what()).find("bilinear"), std::string::npos) << e.what();
  }
  ::unsetenv("AERIAL_TABLE_FILTERING");
}

}  // namespace
}  // namespace aerial::testing
