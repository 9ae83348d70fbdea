// The default tables against the physical sky: the CPU reference with all scattering orders and
// the sun's whole disc (src/aerial/reference), by sun band, camera altitude and wavelength, for sky
// radiance, radiance to a point 10 km along the ray and sky irradiance (src/aerial/bench/
// sky_accuracy.h), over the quick grid. The reference samples take ~15 minutes to compute, so they
// are stored in tests/data/sky_reference_quick.json, made by
//   build/tools/aerial_bench_sky --grid quick --reference-file tests/data/sky_reference_quick.json
// and StoredReferenceIsTodaysReference recomputes some of them, so a stale file is noticed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "aerial/bench/sky_accuracy.h"
#include "aerial/reference/reference.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

using bench::SkyQuantity;

const char* kReferenceFile = AERIAL_SOURCE_DIR "/tests/data/sky_reference_quick.json";
constexpr double kNone = std::numeric_limits<double>::infinity();
const char* kDay = "day (sun zenith 0-60)";
const char* kAfternoon = "afternoon (60-85)";
const char* kLowSun = "low sun (85-95)";
const char* kTwilight = "twilight (95-108)";

// Bounds of one region on its largest relative error (any channel) and on its median (the largest
// of the channels' medians), each an interval [lower, upper], and the number of values it compares
// (fixed by the stored reference: those above the floor of 1e-4 of the noon sky).
//
// Issue 12's targets: daylight (sun zenith <= 60) at most 1% on the ground and 1.5% at 10 and 50
// km, median at most 0.4%; sun zenith 85-95 at most 3%; 95-108 at most 8%. Where a region meets
// its target the upper bound is the target and the lower bound 0. Where it does not (the comment
// says MISSED and gives both), the upper bound is the measured error plus 10%, rounded up, so that
// a regression fails, and the lower bound half the measured error, so that an improvement fails
// too and is written down here and in the README. The afternoon (60-85) has no target and is
// pinned the same way. Measured with the default tables of this commit (MU_S 40 on the
// arctangent mapping, 4 orders + the series' tail).
struct RegionBound {
  SkyQuantity quantity;
  const char* band;
  int altitude_km;
  int samples;
  double max_upper, max_lower, median_upper, median_lower;
};

const RegionBound kBounds[] = {
    {SkyQuantity::kSkyIrradiance, kDay, 0, 9, 0.01, 0, 0.0076, 0.00345},  // max 0.85%, median 0.69%: target; median MISSED, target 0.4%
    {SkyQuantity::kSkyRadiance, kDay, 0, 54, 0.012, 0.00545, 0.004, 0},  // max 1.09%, median 0.31%: MISSED, target 1%; median: target
    {SkyQuantity::kRadianceToPoint, kDay, 0, 54, 0.013, 0.00555, 0.004, 0},  // max 1.11%, median 0.20%: MISSED, target 1%; median: target
    {SkyQuantity::kSkyIrradiance, kDay, 10, 9, 0.015, 0, 0.0052, 0.00235},  // max 0.58%, median 0.47%: target; median MISSED, target 0.4%
    {SkyQuantity::kSkyRadiance, kDay, 10, 90, 0.028, 0.01245, 0.0095, 0.0043},  // max 2.49%, median 0.86%: MISSED, target 1.5%; median MISSED, target 0.4%
    {SkyQuantity::kRadianceToPoint, kDay, 10, 90, 0.023, 0.01045, 0.013, 0.00585},  // max 2.09%, median 1.17%: MISSED, target 1.5%; median MISSED, target 0.4%
    {SkyQuantity::kSkyIrradiance, kDay, 50, 9, 0.035, 0.01575, 0.034, 0.0154},  // max 3.15%, median 3.08%: MISSED, target 1.5%; median MISSED, target 0.4%
    {SkyQuantity::kSkyRadiance, kDay, 50, 90, 0.031, 0.01375, 0.017, 0.0074},  // max 2.75%, median 1.48%: MISSED, target 1.5%; median MISSED, target 0.4%
    {SkyQuantity::kRadianceToPoint, kDay, 50, 72, 0.53, 0.2402, 0.062, 0.02795},  // max 48.04%, median 5.59%: MISSED, target 1.5%; median MISSED, target 0.4%
    {SkyQuantity::kSkyIrradiance, kAfternoon, 0, 3, 0.0049, 0.0022, kNone, 0},  // max 0.44%, median 0.44%: no target, pinned
    {SkyQuantity::kSkyRadiance, kAfternoon, 0, 18, 0.0097, 0.0044, kNone, 0},  // max 0.88%, median 0.87%: no target, pinned
    {SkyQuantity::kRadianceToPoint, kAfternoon, 0, 18, 0.013, 0.0058, kNone, 0},  // max 1.16%, median 0.88%: no target, pinned
    {SkyQuantity::kSkyIrradiance, kAfternoon, 10, 3, 0.016, 0.00685, kNone, 0},  // max 1.37%, median 1.37%: no target, pinned
    {SkyQuantity::kSkyRadiance, kAfternoon, 10, 30, 0.027, 0.0121, kNone, 0},  // max 2.42%, median 1.29%: no target, pinned
    {SkyQuantity::kRadianceToPoint, kAfternoon, 10, 30, 0.02, 0.00905, kNone, 0},  // max 1.81%, median 1.51%: no target, pinned
    {SkyQuantity::kSkyIrradiance, kAfternoon, 50, 3, 0.016, 0.00725, kNone, 0},  // max 1.45%, median 1.45%: no target, pinned
    {SkyQuantity::kSkyRadiance, kAfternoon, 50, 30, 0.038, 0.0169, kNone, 0},  // max 3.38%, median 1.69%: no target, pinned
    {SkyQuantity::kRadianceToPoint, kAfternoon, 50, 24, 0.37, 0.1677, kNone, 0},  // max 33.55%, median 5.81%: no target, pinned
    {SkyQuantity::kSkyIrradiance, kLowSun, 0, 15, 0.069, 0.03105, kNone, 0},  // max 6.21%, median 1.45%: MISSED, target 3%
    {SkyQuantity::kSkyRadiance, kLowSun, 0, 90, 0.17, 0.0759, kNone, 0},  // max 15.18%, median 1.22%: MISSED, target 3%
    {SkyQuantity::kRadianceToPoint, kLowSun, 0, 90, 0.37, 0.1672, kNone, 0},  // max 33.44%, median 1.98%: MISSED, target 3%
    {SkyQuantity::kSkyIrradiance, kLowSun, 10, 15, 0.079, 0.0355, kNone, 0},  // max 7.10%, median 1.16%: MISSED, target 3%
    {SkyQuantity::kSkyRadiance, kLowSun, 10, 150, 0.36, 0.1618, kNone, 0},  // max 32.36%, median 1.12%: MISSED, target 3%
    {SkyQuantity::kRadianceToPoint, kLowSun, 10, 140, 8.4, 3.786, kNone, 0},  // max 757.27%, median 1.68%: MISSED, target 3%
    {SkyQuantity::kSkyIrradiance, kLowSun, 50, 15, 0.038, 0.01695, kNone, 0},  // max 3.39%, median 2.09%: MISSED, target 3%
    {SkyQuantity::kSkyRadiance, kLowSun, 50, 150, 0.14, 0.06335, kNone, 0},  // max 12.67%, median 1.21%: MISSED, target 3%
    {SkyQuantity::kRadianceToPoint, kLowSun, 50, 120, 1.1, 0.4565, kNone, 0},  // max 91.30%, median 3.12%: MISSED, target 3%
    {SkyQuantity::kSkyIrradiance, kTwilight, 0, 3, 0.19, 0.08315, kNone, 0},  // max 16.63%, median 16.63%: MISSED, target 8%
    {SkyQuantity::kSkyRadiance, kTwilight, 0, 13, 0.21, 0.09415, kNone, 0},  // max 18.83%, median 16.44%: MISSED, target 8%
    {SkyQuantity::kRadianceToPoint, kTwilight, 0, 1, 0.29, 0.1315, kNone, 0},  // max 26.30%, median 26.30%: MISSED, target 8%
    {SkyQuantity::kSkyIrradiance, kTwilight, 10, 3, 0.36, 0.1614, kNone, 0},  // max 32.28%, median 32.28%: MISSED, target 8%
    {SkyQuantity::kSkyRadiance, kTwilight, 10, 23, 0.38, 0.169, kNone, 0},  // max 33.80%, median 14.62%: MISSED, target 8%
    {SkyQuantity::kRadianceToPoint, kTwilight, 10, 0, kNone, 0, kNone, 0},  // no value above the floor
    {SkyQuantity::kSkyIrradiance, kTwilight, 50, 1, 0.08, 0, kNone, 0},  // max 2.51%, median 2.51%: target
    {SkyQuantity::kSkyRadiance, kTwilight, 50, 13, 0.4, 0.1809, kNone, 0},  // max 36.19%, median 2.46%: MISSED, target 8%
    {SkyQuantity::kRadianceToPoint, kTwilight, 50, 0, kNone, 0, kNone, 0},  // no value above the floor
};

const RegionBound* FindBound(const bench::RegionAccuracy& region) {
  for (const RegionBound& b : kBounds)
    if (b.quantity == region.quantity && region.band == b.band && region.altitude_m == b.altitude_km * 1000.0)
      return &b;
  return nullptr;
}

class PhysicalSky : public GpuTest {};

TEST_F(PhysicalSky, DefaultTablesAgainstTheTargets) {
  bench::SkyReference reference = bench::ReadSkyReference(kReferenceFile);
  ASSERT_EQ(reference.orders, reference::kAllOrders);
  ASSERT_EQ(PrecomputeOptions::Default().RepresentedOrders(), reference::kAllOrders);
  std::vector<bench::RegionAccuracy> regions = bench::CompareSkyWithTables(FullTables(), reference);
  std::printf("%s\n%s", bench::FormatSkyAccuracy(regions).c_str(), bench::FormatWorstSamples(regions).c_str());
  ASSERT_EQ(regions.size(), std::size(kBounds));  // 3 quantities x 4 bands x 3 altitudes
  for (const bench::RegionAccuracy& region : regions) {
    std::string name = bench::ToString(region.quantity) + ", " + region.band + ", camera at " +
                       std::to_string(int(region.altitude_m / 1000.0)) + " km";
    const RegionBound* bound = FindBound(region);
    ASSERT_NE(bound, nullptr) << name;
    int samples = region.channels[0].samples + region.channels[1].samples + region.channels[2].samples;
    EXPECT_EQ(samples, bound->samples) << name;
    if (samples == 0) continue;
    EXPECT_LE(region.Max(), bound->max_upper) << name;
    EXPECT_GE(region.Max(), bound->max_lower) << name << ": better than recorded, update the bound and README";
    if (bound->median_upper != kNone) {
      EXPECT_LE(region.Median(), bound->median_upper) << name << " (median)";
      EXPECT_GE(region.Median(), bound->median_lower) << name << " (median): better than recorded";
    }
  }
}

// The stored samples are today's reference: every 37th is recomputed with its own path count and
// seed, which reproduces it to rounding (the reference is deterministic for a seed and a path
// count, whatever the thread count), unless the reference code changed since the file was made.
TEST(PhysicalSkyReference, StoredReferenceIsTodaysReference) {
  bench::SkyReference reference = bench::ReadSkyReference(kReferenceFile);
  ASSERT_EQ(reference.samples.size(), 741u);
  int checked = 0;
  for (size_t i = 0; i < reference.samples.size(); i += 37) {
    const bench::SkySample& sample = reference.samples[i];
    reference::Estimate again = bench::RecomputeSkySample(AtmosphereParameters::Earth(), reference, sample);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(again.value[c], sample.value[c], 1e-9 * std::abs(sample.value[c]) + 1e-300) << i << " " << c;
    ++checked;
  }
  EXPECT_EQ(checked, 21);
}

}  // namespace
}  // namespace aerial::testing
