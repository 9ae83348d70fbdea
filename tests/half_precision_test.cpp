// CTest label "sanitizer": the half-float tables: run under the sanitizers too.
// Half-precision tables (--precision float16, the 4D default) read like the float32 ones: the
// Rayleigh table and the multiple density table J_ms (times kMultipleDensityScale, which lifts its
// values into half floats' normal range) store 16-bit floats, while Mie's single scattering, whose
// values fall below that range, stays float32 (atmosphere_tables.cpp).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "aerial/precompute/precomputer.h"
#include "aerial/probe/table_probe.h"
#include "comparison.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

class HalfPrecision : public GpuTest {};

TEST_F(HalfPrecision, SkyAndRadianceToPointReadLikeFloat32Tables) {
  PrecomputeOptions options = PrecomputeOptions::Small();
  options.precision = TablePrecision::kFloat16;
  AtmosphereTables half(SharedContext(), AtmosphereParameters::Earth(), options);
  Precompute(half, nullptr);
  const TableCache downloaded = half.Download();
  ASSERT_EQ(downloaded.tables[2].name, std::string("rayleigh"));
  ASSERT_EQ(downloaded.tables[2].format, TexelFormat::kRgba16f);
  ASSERT_EQ(downloaded.tables[5].name, std::string("multiple_density"));
  ASSERT_EQ(downloaded.tables[5].format, TexelFormat::kRgba16f);

  // Daylight, a low sun and twilight; on the ground and 10 km up; up, along and below the horizon.
  std::vector<ViewAngles> views = ViewGrid({0.0, 10e3}, {30.0, 88.0, 120.0}, {30.0, 88.0, 100.0},
                                           {0.0, 90.0});
  std::vector<ProbeQuery> queries;
  for (const ViewAngles& view : views)
    queries.push_back({ToRayParameters(view, AtmosphereParameters::Earth()), 1e4});
  auto half_results = ProbeTables(half, queries);
  auto float_results = ProbeTables(SmallTables(), queries);

  // Relative to values above 1e-6 W/m^2/sr/nm (the twilight sky's dimmest, 1e-5 of the noon sky).
  WorstError sky(1e-6), to_point(1e-6);
  for (size_t i = 0; i < views.size(); ++i) {
    sky.Add(half_results[i].sky_radiance, float_results[i].sky_radiance, Describe(views[i]));
    to_point.Add(half_results[i].radiance_to_point, float_results[i].radiance_to_point,
                 Describe(views[i]));
  }
  std::printf("half vs float32 tables: sky %s\nradiance to a point: %s\n", sky.Summary().c_str(),
              to_point.Summary().c_str());
  // 36 views x 3 channels = 108 samples, of which 69 and 60 are above the floor (twilight's are
  // mostly below it). At least 60 and 54: a read that went to zero for a whole sun angle (36
  // samples) fails.
  EXPECT_TRUE(ComparedAtLeast(sky, 60));
  EXPECT_TRUE(ComparedAtLeast(to_point, 54));
  // Rounded to the nearest (round_to_half.comp), a texel is within 2^-12 = 0.024% of its float32
  // value, and a sky read blends texels with weights that sum to one; the corrections taken from
  // them subtract marched values where the two nearly cancel, which can raise that a few times:
  // 0.1%. Measured: 0.035%. Rounded toward zero, as lavapipe's blit does without that pass, every
  // texel loses up to 0.05% in the same direction: measured 0.198%, which fails here. The radiance
  // to a point integrates J_ms, whose texels are rounded the same way: the same bound (measured:
  // 0.012%). Unscaled, J_ms underflowed in half floats and the radiance to a point was 100% off.
  EXPECT_LT(sky.value(), 1e-3) << sky.Summary();
  EXPECT_LT(to_point.value(), 1e-3) << to_point.Summary();
}

}  // namespace
}  // namespace aerial::testing
