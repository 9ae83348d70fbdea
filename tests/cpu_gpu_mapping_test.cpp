// The mappings that C++ and GLSL both evaluate, run on the GPU (shaders/test/cpu_gpu_mappings.comp,
// froxel_axes.comp, sun_high_mirrors.comp) and held against their C++ side: the froxel depth
// mapping (FroxelGrid against shaders/include/froxel_depth.glsl), the froxel axes' placement
// (FroxelAxis against froxel_axes.glsl), the sky-view lattice's size (the renderer's images
// against what shaders/include/sky_view_lattice.glsl gives the passes), and what the choice of the
// variants for a high sun mirrors (froxel/sun_high_variant.h against mappings.glsl and
// transmittance.glsl).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "aerial/froxel_grid.h"
#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/render/sky_view_layout.h"
#include "aerial/shader_abi/froxel_axes.h"
#include "froxel/sun_high_variant.h"
#include "aerial/vk/compute_pipeline.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

// Both sides compute the same formula, the GPU in float32 from the same float inputs, the CPU in
// double. The slice distance takes a division (at most 2.5 ulp in Vulkan's GLSL), doubled by the
// square, and two products (0.5 ulp each): 6 ulp = 7.2e-7 relative at worst. The depth coordinate
// takes a division, halved by the square root, and the root (3 ulp): 4.25 ulp = 5.1e-7 (lavapipe
// measured 1.1e-7 and 8.2e-8). A wrong formula moves either by far more: an exponent of 2.0001
// instead of 2 moved the slice distances by up to 7.6e-4, 0.5001 for the root 2.0e-3.
constexpr double kRelativeTolerance = 1e-6;

struct FroxelCase {
  float slice_center, slices, far_m, distance;
};

struct GpuResults {
  std::vector<std::array<float, 2>> froxel;  // slice distance, depth coordinate
  std::vector<std::array<int32_t, 2>> lattice;
};

vk::Buffer HostBuffer(size_t bytes) {
  return vk::Buffer(SharedContext(), {.size = bytes, .usage = ::vk::BufferUsageFlagBits::eStorageBuffer,
                                      .host_visible = true});
}

// One dispatch of a test shader over `invocations` invocations in groups of 64, waited for.
void DispatchOnce(const std::string& shader, const vk::SlotLayout& layout, const std::vector<vk::Slot>& slots,
                  size_t invocations) {
  vk::Context& context = SharedContext();
  vk::ComputePipeline pipeline(context, shader, layout);
  context.Submit([&](const auto& cmd) {
    pipeline.Dispatch(cmd, slots, {uint32_t(invocations), 1, 1}, {64, 1, 1});
    vk::FullBarrier(cmd);
  });
}

GpuResults RunOnGpu(const std::vector<FroxelCase>& froxel, const std::vector<std::array<int32_t, 2>>& tables) {
  vk::Buffer froxel_in = HostBuffer(froxel.size() * sizeof(FroxelCase));
  vk::Buffer froxel_out = HostBuffer(froxel.size() * 2 * sizeof(float));
  vk::Buffer tables_in = HostBuffer(tables.size() * 2 * sizeof(int32_t));
  vk::Buffer lattice_out = HostBuffer(tables.size() * 2 * sizeof(int32_t));
  std::memcpy(froxel_in.mapped(), froxel.data(), froxel.size() * sizeof(FroxelCase));
  std::memcpy(tables_in.mapped(), tables.data(), tables.size() * 2 * sizeof(int32_t));
  DispatchOnce("test/cpu_gpu_mappings.comp",
               {{"FroxelInputs", vk::kStorageBuffer},
                {"FroxelOutputs", vk::kStorageBuffer},
                {"TableSizes", vk::kStorageBuffer},
                {"LatticeSizes", vk::kStorageBuffer}},
               {vk::StorageBufferSlot{&froxel_in}, vk::StorageBufferSlot{&froxel_out},
                vk::StorageBufferSlot{&tables_in}, vk::StorageBufferSlot{&lattice_out}},
               std::max(froxel.size(), tables.size()));
  GpuResults results{std::vector<std::array<float, 2>>(froxel.size()),
                     std::vector<std::array<int32_t, 2>>(tables.size())};
  std::memcpy(results.froxel.data(), froxel_out.mapped(), froxel.size() * 2 * sizeof(float));
  std::memcpy(results.lattice.data(), lattice_out.mapped(), tables.size() * 2 * sizeof(int32_t));
  return results;
}

// Slice centers every quarter slice over the whole grid and distances from behind the camera to
// past the far end, on the grid sizes and far distances FroxelGrid::Validate allows.
std::vector<FroxelCase> FroxelCases() {
  std::vector<FroxelCase> cases;
  for (float slices : {2.0f, 32.0f, 256.0f})
    for (float far_m : {150.0f, 128e3f, 1e6f}) {
      int quarters = int(4 * slices);
      for (int q = 0; q <= quarters; ++q) {
        float fraction = float(q) / float(quarters);
        float distance = q == 0 ? -1.0f : far_m * 1.5f * fraction * fraction * fraction;
        cases.push_back({0.25f * float(q) + 0.125f, slices, far_m, distance});
      }
    }
  return cases;
}

class CpuGpuMappings : public GpuTest {};

TEST_F(CpuGpuMappings, FroxelDepthMatchesFroxelGrid) {
  std::vector<FroxelCase> cases = FroxelCases();
  GpuResults gpu = RunOnGpu(cases, {{2, 4}});
  double worst_slice = 0.0, worst_depth = 0.0;
  for (size_t i = 0; i < cases.size(); ++i) {
    FroxelGrid grid;
    grid.depth = int(cases[i].slices);
    grid.far_m = cases[i].far_m;
    double slice = grid.SliceDistance(cases[i].slice_center);
    double depth = grid.DepthCoordinate(cases[i].distance);
    ASSERT_GT(slice, 0.0);
    worst_slice = std::max(worst_slice, std::abs(gpu.froxel[i][0] - slice) / slice);
    if (depth == 0.0) {
      EXPECT_EQ(gpu.froxel[i][1], 0.0f) << "distance " << cases[i].distance;
    } else {
      worst_depth = std::max(worst_depth, std::abs(gpu.froxel[i][1] - depth) / depth);
    }
  }
  std::printf("%zu cases, worst relative difference: slice distance %.2e, depth coordinate %.2e\n",
              cases.size(), worst_slice, worst_depth);
  EXPECT_LE(worst_slice, kRelativeTolerance);
  EXPECT_LE(worst_depth, kRelativeTolerance);
}

// Foci across the screen (the edges too, where the horizon or the sun is off it), spreads from the
// default's to the near-even columns' of a sun behind the camera (5), values every 1/64 of
// [0, 1]: the GPU's froxel coordinate and screen position against FroxelAxis
// in double from the same floats. Tolerance 5e-6 screen heights (1/280 of a 720p pixel): the float
// error of asinh as a log (3 ulp beyond [0.5, 2]) over a span of about 6, and of sinh's two
// exponentials (3 + 2|x| ulp, |x| <= 3.2) scaled by the spread, stay below 1e-6; a wrong term moves
// rows by far more (a spread of 0.0501 for 0.05 moves them by up to 2e-4).
TEST_F(CpuGpuMappings, FroxelAxisMatchesFroxelAxis) {
  std::vector<std::array<float, 4>> rows;
  std::vector<float> values;
  for (float focus : {0.0f, 0.2f, 0.6f, 1.0f})
    for (float spread : {float(kFroxelRowSpread), 0.03f, 0.5f, 5.0f})
      for (int step = 0; step <= 64; ++step) {
        rows.push_back(FroxelAxis{.focus = focus, .spread = spread}.Packed());
        values.push_back(float(step) / 64.0f);
      }
  vk::Buffer rows_in = HostBuffer(rows.size() * sizeof(rows[0]));
  vk::Buffer values_in = HostBuffer(values.size() * sizeof(float));
  vk::Buffer out = HostBuffer(rows.size() * 2 * sizeof(float));
  std::memcpy(rows_in.mapped(), rows.data(), rows.size() * sizeof(rows[0]));
  std::memcpy(values_in.mapped(), values.data(), values.size() * sizeof(float));
  DispatchOnce("test/froxel_axes.comp",
               {{"RowsInputs", vk::kStorageBuffer}, {"RowsValues", vk::kStorageBuffer}, {"RowsOutputs", vk::kStorageBuffer}},
               {vk::StorageBufferSlot{&rows_in}, vk::StorageBufferSlot{&values_in}, vk::StorageBufferSlot{&out}},
               rows.size());
  std::vector<std::array<float, 2>> gpu(rows.size());
  std::memcpy(gpu.data(), out.mapped(), gpu.size() * sizeof(gpu[0]));
  double worst_row = 0.0, worst_screen = 0.0;
  for (size_t i = 0; i < rows.size(); ++i) {
    FroxelAxis cpu = FroxelAxis::Unpack(rows[i]);
    worst_row = std::max(worst_row, std::abs(gpu[i][0] - cpu.Coordinate(values[i])));
    worst_screen = std::max(worst_screen, std::abs(gpu[i][1] - cpu.ScreenPosition(values[i])));
  }
  std::printf("%zu cases, worst difference: row coordinate %.2e, screen row %.2e\n", rows.size(), worst_row,
              worst_screen);
  EXPECT_LE(worst_row, 5e-6);
  EXPECT_LE(worst_screen, 5e-6);
}

// The lattice the renderer allocates (kSkyViewLatticeSize) is the one the passes index, and the
// shaders' size agrees with the C++ one for every table size up to 256 x 256.
TEST_F(CpuGpuMappings, SkyViewLatticeMatchesTheRenderersImages) {
  std::vector<std::array<int32_t, 2>> tables = {kSkyViewSize};
  for (int32_t width = 2; width <= 256; ++width)
    for (int32_t height = 4; height <= 256; ++height) tables.push_back({width, height});
  GpuResults gpu = RunOnGpu({{0.5f, 2.0f, 150.0f, 1.0f}}, tables);
  EXPECT_EQ(gpu.lattice[0], kSkyViewLatticeSize);
  int mismatches = 0;
  for (size_t i = 0; i < tables.size(); ++i) {
    std::array<int32_t, 2> cpu = {GetSkyViewLatticeWidth(tables[i][0]), GetSkyViewLatticeHeight(tables[i][1])};
    if (gpu.lattice[i] != cpu && ++mismatches <= 5)
      ADD_FAILURE() << "table " << tables[i][0] << "x" << tables[i][1] << ": GPU " << gpu.lattice[i][0] << "x"
                    << gpu.lattice[i][1] << ", C++ " << cpu[0] << "x" << cpu[1];
  }
  EXPECT_EQ(mismatches, 0);
}

struct SunHighMirrors {
  std::vector<std::array<float, 2>> mu_s;  // GetUnitRangeFromMuS(mu_s), GetMuSFromUnitRange(x)
  float one_tap_elevation = 0.0f;          // SUN_DISC_ONE_TAP_ELEVATION
};

// inputs: (mu_s, x) per case, with the Earth's atmosphere (its mu_s_min) in the AtmosphereBlock.
SunHighMirrors RunSunHighMirrors(const std::vector<std::array<float, 2>>& inputs) {
  AtmosphereTables tables(SharedContext(), AtmosphereParameters::Earth(), PrecomputeOptions::Small());
  vk::Buffer in = HostBuffer(inputs.size() * 2 * sizeof(float));
  vk::Buffer out = HostBuffer(inputs.size() * 2 * sizeof(float));
  vk::Buffer constants = HostBuffer(sizeof(float));
  std::memcpy(in.mapped(), inputs.data(), inputs.size() * 2 * sizeof(float));
  DispatchOnce("test/sun_high_mirrors.comp",
               {{"AtmosphereBlock", vk::kUniform},
                {"MuSInputs", vk::kStorageBuffer},
                {"MuSOutputs", vk::kStorageBuffer},
                {"Constants", vk::kStorageBuffer}},
               {vk::UniformBufferSlot{&tables.uniform_buffer()}, vk::StorageBufferSlot{&in},
                vk::StorageBufferSlot{&out}, vk::StorageBufferSlot{&constants}},
               inputs.size());
  SunHighMirrors results{std::vector<std::array<float, 2>>(inputs.size())};
  std::memcpy(results.mu_s.data(), out.mapped(), inputs.size() * 2 * sizeof(float));
  std::memcpy(&results.one_tap_elevation, constants.mapped(), sizeof(float));
  return results;
}

// The variants for a high sun are chosen on the CPU from copies of GLSL constants (the sun disc's
// one-tap elevation, the mu_s axis's centre and spread): a change on one side alone would let a
// variant run where it computes other values than the general pass. The axis is compared over
// mu_s in [mu_s_min, 1] and x in [0, 1]: float32's atan and tan (measured 1.2e-6 and 1.7e-6) stay
// far below 2e-5, while the C++ axis's centre moved to -0.1001 moved x by up to 2.5e-4, and its
// spread moved to 7.01 by up to 2.6e-4 (both failed here).
TEST_F(CpuGpuMappings, SunHighVariantMirrorsMatchTheShaders) {
  const double mu_s_min = AtmosphereParameters::Earth().mu_s_min;
  std::vector<std::array<float, 2>> inputs;
  for (int i = 0; i <= 200; ++i) {
    double t = i / 200.0;
    inputs.push_back({float(mu_s_min + (1.0 - mu_s_min) * t), float(t)});
  }
  SunHighMirrors gpu = RunSunHighMirrors(inputs);
  EXPECT_EQ(gpu.one_tap_elevation, float(kSunDiscOneTapSine));
  double worst_x = 0.0, worst_mu_s = 0.0;
  for (size_t i = 0; i < inputs.size(); ++i) {
    worst_x = std::max(worst_x, std::abs(gpu.mu_s[i][0] - UnitRangeFromMuS(inputs[i][0], mu_s_min)));
    worst_mu_s = std::max(worst_mu_s, std::abs(gpu.mu_s[i][1] - MuSFromUnitRange(inputs[i][1], mu_s_min)));
  }
  std::printf("%zu cases, worst absolute difference: x %.2e, mu_s %.2e\n", inputs.size(), worst_x, worst_mu_s);
  EXPECT_LE(worst_x, 2e-5);
  EXPECT_LE(worst_mu_s, 2e-5);
}

}  // namespace
}  // namespace aerial::testing
