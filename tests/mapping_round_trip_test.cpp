// Every texture-coordinate mapping of shaders/include/mappings.glsl round-trips: the texel centers
// of each table, mapped to (r, mu, mu_s, nu) and back, land on themselves. Run on the GPU because
// the mappings exist only in GLSL.
#include <gtest/gtest.h>

#include <array>
#include <cstring>

#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/vk/compute_pipeline.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

std::array<float, 5> MaxRoundTripErrors(const PrecomputeOptions& options) {
  vk::Context& context = SharedContext();
  AtmosphereTables tables(context, AtmosphereParameters::Earth(), options);
  vk::Buffer errors(context, {.size = 5 * sizeof(uint32_t),
                              .usage = ::vk::BufferUsageFlagBits::eStorageBuffer,
                              .host_visible = true});
  std::memset(errors.mapped(), 0, 5 * sizeof(uint32_t));
  vk::ComputePipeline pipeline(context, "test/mapping_round_trip.comp",
                               {{"AtmosphereBlock", vk::kUniform}, {"Errors", vk::kStorageBuffer}}, sizeof(int));
  const TableResolution& r = options.resolution;
  context.Submit([&](const auto& cmd) {
    // The scattering extent twice: its ray-length mu axis, then the densities' view-zenith one.
    std::array<::vk::Extent3D, 4> extents = {
        ::vk::Extent3D{uint32_t(r.transmittance_mu), uint32_t(r.transmittance_r), 1},
        ::vk::Extent3D{uint32_t(r.irradiance_mu_s), uint32_t(r.irradiance_r), 1},
        tables.rayleigh().extent(), tables.rayleigh().extent()};
    for (int table = 0; table < 4; ++table) {
      pipeline.Dispatch(cmd, {vk::UniformBufferSlot{&tables.uniform_buffer()}, vk::StorageBufferSlot{&errors}},
                        extents[table], {8, 8, 1}, &table);
    }
    vk::FullBarrier(cmd);
  });
  std::array<float, 5> result;
  std::memcpy(result.data(), errors.mapped(), sizeof result);
  return result;
}

class MappingRoundTrip : public GpuTest {};

// In float32, r near the ground carries an absolute error of half a meter (ulp at 6.4e6 m), which
// near the horizon moves a transmittance coordinate by up to ~0.03 texel (measured 0.027). 0.05
// texel is invisible in a bilinear fetch, and still fails on any real mapping mistake (those move
// coordinates by whole texels).
constexpr float kToleranceInTexels = 0.05f;

TEST_F(MappingRoundTrip, DefaultTablesLandOnTexelCenters) {
  auto errors = MaxRoundTripErrors(PrecomputeOptions{});
  EXPECT_LT(errors[0], kToleranceInTexels) << "transmittance";
  EXPECT_LT(errors[1], kToleranceInTexels) << "irradiance";
  EXPECT_LT(errors[2], kToleranceInTexels) << "scattering";
  EXPECT_LT(errors[4], kToleranceInTexels) << "scattering density (view zenith mu axis, azimuth axis)";
  EXPECT_EQ(errors[3], 0.0f) << "a scattering texel changed half (ground / sky) in the round trip";
}

TEST_F(MappingRoundTrip, SmallTablesLandOnTexelCenters) {
  auto errors = MaxRoundTripErrors(PrecomputeOptions::Small());
  EXPECT_LT(errors[0], kToleranceInTexels);
  EXPECT_LT(errors[1], kToleranceInTexels);
  EXPECT_LT(errors[2], kToleranceInTexels);
  EXPECT_LT(errors[4], kToleranceInTexels);
  EXPECT_EQ(errors[3], 0.0f);
}

}  // namespace
}  // namespace aerial::testing
