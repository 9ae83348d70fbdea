// The default tables against the physical sky: the CPU reference with all scattering orders and
// the sun's whole disc (src/aerial/reference), by sun band, camera altitude and wavelength, for sky
// radiance, radiance to a point 10 km along the ray and sky irradiance (src/aerial/bench/
// sky_accuracy.h; issue 12's targets). The reference samples take ~20 minutes to compute, so they
// are stored in tests/data/sky_reference_quick.json, made by
//   build/tools/aerial_bench_sky --grid quick --reference-file tests/data/sky_reference_quick.json
// and StoredReferenceIsTodaysReference recomputes some of them, so a stale file is noticed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "aerial/bench/sky_accuracy.h"
#include "aerial/reference/reference.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

const char* kReferenceFile = AERIAL_SOURCE_DIR "/tests/data/sky_reference_quick.json";

// Bounds on the largest relative error of a region, and on its median (all channels).
struct Bound {
  double max, median;
};

class PhysicalSky : public GpuTest {};

Bound BoundFor(const bench::RegionAccuracy& region) {
  return {0.0, 0.0};
}

TEST_F(PhysicalSky, DefaultTablesMeetTheTargets) {
  bench::SkyReference reference = bench::ReadSkyReference(kReferenceFile);
  ASSERT_EQ(reference.orders, reference::kAllOrders);
  ASSERT_EQ(PrecomputeOptions::Default().RepresentedOrders(), reference::kAllOrders);
  std::vector<bench::RegionAccuracy> regions = bench::CompareSkyWithTables(FullTables(), reference);
  std::printf("%s\n%s", bench::FormatSkyAccuracy(regions).c_str(), bench::FormatWorstSamples(regions).c_str());
  ASSERT_EQ(regions.size(), 36u);  // 3 quantities x 4 bands x 3 altitudes
  for (const bench::RegionAccuracy& region : regions) {
    std::string name = bench::ToString(region.quantity) + ", " + region.band + ", camera at " +
                       std::to_string(int(region.altitude_m / 1000.0)) + " km";
    Bound bound = BoundFor(region);
    EXPECT_LE(region.Max(), bound.max) << name;
    EXPECT_LE(region.Median(), bound.median) << name;
  }
}

}  // namespace
}  // namespace aerial::testing
