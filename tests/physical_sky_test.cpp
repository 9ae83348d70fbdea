// The default tables against the physical sky: the CPU reference with all scattering orders and
// the sun's whole disc (src/aerial/reference), by sun band, camera altitude and wavelength, for sky
// radiance, radiance to a point 10 km along the ray and sky irradiance (src/aerial/bench/
// sky_accuracy.h), over the quick grid. The reference samples take ~41 minutes to compute, so they
// are stored in tests/data/sky_reference_quick.json, made by
//   build/tools/aerial_bench_sky --grid quick --paths 65536
//       --reference-file tests/data/sky_reference_quick.json
// and StoredReferenceIsTodaysReference recomputes some of them, so a stale file is noticed.
#include <gtest/gtest.h>

#include <algorithm>
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
// km, median at most 0.4%; sun zenith 85-95 at most 3%; 95-108 at most 8%. Where a region meets its
// target the upper bound is the target and the lower bound 0. Where it does not (the comment says
// MISSED and gives both), the upper bound is the measured error plus 10%, rounded up, so that a
// regression fails, and the lower bound half the measured error, so that an improvement fails too
// and is written down here and in docs/accuracy.md. The afternoon (60-85) has no target and is pinned the
// same way. Measured with the default tables of this commit (MU_S 36 on the arctangent mapping, 4
// orders + the series' tail, the density grid's zenith cells quadratic toward the horizon above and
// below it, the ground irradiance of order 1 corrected by single scattering integrated along an 8x8
// grid, the irradiance read exponentially in r), radiance to a point marched with the multiple
// density table R32 MU56 MU_S36 NU9 (the density tables' r texels), every density read linearly
// in mu_s between daylight texels (GetDensityTextureUvwz), the density tables' fourth axis the
// view-sun azimuth (GetUnitRangeFromViewSunAzimuth), 9 nu slices (one on nu = 0) in 16-bit floats
// rounded to the nearest (round_to_half.comp), the sky's single scattering corrected where the sun is low and its
// multiple scattering blended exponentially in mu_s and nu (GetSkyInscatterCorrection,
// sky_lookup.glsl), single scattering marched with steps that follow a sun on the horizon
// (GetStepSpacingExponent, scattering.glsl), the scattering density tables' mu axis on the view
// zenith angle (MU_AXIS_VIEW_ZENITH, mappings.glsl) and their r axis warped (WarpR, the irradiance
// table's too), J_ms blended exponentially in mu_s in the Earth's shadow, the mu_s mapping's width
// 1/7 (MU_S_SPREAD), the sky's multiple scattering blended in nu as radiance, the density grid's
// node at each cell's mean path length (CellNodeZenith), the irradiance read linearly in mu_s in
// daylight and integrated over zenith nodes by Fejer's rule, the sky's multiple scattering blended
// in daylight quadratically in mu_s over three texels and at the nus its slices hold
// (GetMultipleScatteringBlendCorrection),
// the r axis warped by R_WARP 0.5. Against the stored reference of 65,536 paths per sample (up to
// 64 times more where noisy, and for every irradiance above the floor), in the sun's vertical plane
// and across it (azimuth 90).
struct RegionBound {
  SkyQuantity quantity;
  const char* band;
  int altitude_km;
  int samples;
  double max_upper, max_lower, median_upper, median_lower;
};

const RegionBound kBounds[] = {
    {SkyQuantity::kSkyIrradiance, kDay, 0, 9, 0.01, 0, 0.004, 0},  // max 0.686%: target 1%; median 0.39%: target
    {SkyQuantity::kSkyRadiance, kDay, 0, 81, 0.01, 0, 0.004, 0},  // max 0.460%: target 1%; median 0.26%: target
    {SkyQuantity::kRadianceToPoint, kDay, 0, 81, 0.01, 0, 0.004, 0},  // max 0.676%: target 1%; median 0.40%: target
    {SkyQuantity::kSkyIrradiance, kDay, 10, 9, 0.015, 0, 0.004, 0},  // max 0.441%: target 1.5%; median 0.09%: target
    {SkyQuantity::kSkyRadiance, kDay, 10, 135, 0.015, 0, 0.004, 0},  // max 0.679%: target 1.5%; median 0.23%: target
    {SkyQuantity::kRadianceToPoint, kDay, 10, 135, 0.015, 0, 0.004, 0},  // max 0.835%: target 1.5%; median 0.17%: target
    {SkyQuantity::kSkyIrradiance, kDay, 50, 9, 0.015, 0, 0.004, 0},  // max 0.377%: target 1.5%; median 0.21%: target
    {SkyQuantity::kSkyRadiance, kDay, 50, 135, 0.015, 0, 0.004, 0},  // max 0.640%: target 1.5%; median 0.23%: target
    {SkyQuantity::kRadianceToPoint, kDay, 50, 108, 0.015, 0, 0.004, 0},  // max 0.665%: target 1.5%; median 0.20%: target
    {SkyQuantity::kSkyIrradiance, kAfternoon, 0, 3, 0.0032, 0.001427, kNone, 0},  // max 0.285%, median 0.29%: no target, pinned
    {SkyQuantity::kSkyRadiance, kAfternoon, 0, 27, 0.0045, 0.002, kNone, 0},  // max 0.400%, median 0.25%: no target, pinned
    {SkyQuantity::kRadianceToPoint, kAfternoon, 0, 27, 0.0055, 0.002485, kNone, 0},  // max 0.497%, median 0.29%: no target, pinned
    {SkyQuantity::kSkyIrradiance, kAfternoon, 10, 3, 0.00093, 0.0004201, kNone, 0},  // max 0.084%, median 0.08%: no target, pinned
    {SkyQuantity::kSkyRadiance, kAfternoon, 10, 45, 0.0058, 0.002602, kNone, 0},  // max 0.520%, median 0.15%: no target, pinned
    {SkyQuantity::kRadianceToPoint, kAfternoon, 10, 45, 0.0031, 0.001392, kNone, 0},  // max 0.278%, median 0.11%: no target, pinned
    {SkyQuantity::kSkyIrradiance, kAfternoon, 50, 3, 0.0068, 0.003054, kNone, 0},  // max 0.611%, median 0.61%: no target, pinned
    {SkyQuantity::kSkyRadiance, kAfternoon, 50, 45, 0.0063, 0.00285, kNone, 0},  // max 0.570%, median 0.23%: no target, pinned
    {SkyQuantity::kRadianceToPoint, kAfternoon, 50, 36, 0.004, 0.001799, kNone, 0},  // max 0.360%, median 0.12%: no target, pinned
    {SkyQuantity::kSkyIrradiance, kLowSun, 0, 15, 0.03, 0, kNone, 0},  // max 2.313%: target 3%
    {SkyQuantity::kSkyRadiance, kLowSun, 0, 135, 0.03, 0, kNone, 0},  // max 2.881%: target 3%
    {SkyQuantity::kRadianceToPoint, kLowSun, 0, 135, 0.03, 0, kNone, 0},  // max 2.446%: target 3%
    {SkyQuantity::kSkyIrradiance, kLowSun, 10, 15, 0.03, 0, kNone, 0},  // max 0.819%: target 3%
    {SkyQuantity::kSkyRadiance, kLowSun, 10, 225, 0.03, 0, kNone, 0},  // max 2.345%: target 3%
    {SkyQuantity::kRadianceToPoint, kLowSun, 10, 206, 0.03, 0, kNone, 0},  // max 1.813%: target 3%
    {SkyQuantity::kSkyIrradiance, kLowSun, 50, 15, 0.03, 0, kNone, 0},  // max 0.966%: target 3%
    {SkyQuantity::kSkyRadiance, kLowSun, 50, 225, 0.03, 0, kNone, 0},  // max 2.674%: target 3%
    {SkyQuantity::kRadianceToPoint, kLowSun, 50, 180, 0.03, 0, kNone, 0},  // max 0.269%: target 3%
    {SkyQuantity::kSkyIrradiance, kTwilight, 0, 3, 0.08, 0, kNone, 0},  // max 5.784%: target 8%
    {SkyQuantity::kSkyRadiance, kTwilight, 0, 18, 0.08, 0, kNone, 0},  // max 7.355%: target 8%
    {SkyQuantity::kRadianceToPoint, kTwilight, 0, 1, 0.08, 0, kNone, 0},  // max 4.560%: target 8%
    {SkyQuantity::kSkyIrradiance, kTwilight, 10, 3, 0.08, 0, kNone, 0},  // max 4.014%: target 8%
    {SkyQuantity::kSkyRadiance, kTwilight, 10, 29, 0.08, 0, kNone, 0},  // max 3.779%: target 8%
    {SkyQuantity::kRadianceToPoint, kTwilight, 10, 0, kNone, 0, kNone, 0},  // no value above the floor
    {SkyQuantity::kSkyIrradiance, kTwilight, 50, 1, 0.08, 0, kNone, 0},  // max 0.094%: target 8%
    {SkyQuantity::kSkyRadiance, kTwilight, 50, 19, 0.08, 0, kNone, 0},  // max 3.654%: target 8%
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
  // Through the public API, from the test cache that FullTables() fills.
  FullTables();
  Device device;
  Tables tables =
      Tables::LoadOrPrecompute(device, AtmosphereParameters::Earth(), PrecomputeOptions::Default());
  ASSERT_TRUE(tables.from_cache());
  std::vector<bench::RegionAccuracy> regions = bench::CompareSkyWithTables(tables, reference);
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
    EXPECT_GE(region.Max(), bound->max_lower) << name << ": better than recorded, update the bound and docs/accuracy.md";
    if (bound->median_upper != kNone) {
      EXPECT_LE(region.Median(), bound->median_upper) << name << " (median)";
      EXPECT_GE(region.Median(), bound->median_lower) << name << " (median): better than recorded";
    }
  }
}

// The stored samples are today's reference: every 52nd is recomputed with its own path count and
// seed, which reproduces it to rounding (the reference is deterministic for a seed and a path
// count, whatever the thread count), unless the reference code changed since the file was made.
TEST(PhysicalSkyReference, StoredReferenceIsTodaysReference) {
  bench::SkyReference reference = bench::ReadSkyReference(kReferenceFile);
  ASSERT_EQ(reference.samples.size(), 1092u);
  int checked = 0;
  for (size_t i = 0; i < reference.samples.size(); i += 52) {
    const bench::SkySample& sample = reference.samples[i];
    reference::Estimate again = bench::RecomputeSkySample(AtmosphereParameters::Earth(), reference, sample);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(again.value[c], sample.value[c], 1e-9 * std::abs(sample.value[c]) + 1e-300) << i << " " << c;
    ++checked;
  }
  EXPECT_EQ(checked, 21);
}

// Every stored sample met its noise goal (bench::NoiseGoal: a quarter of the target for daylight
// and low-sun radiances, of the 0.4% median target for every irradiance), or took the most paths the reference
// allows: each compared value (those above the floor) counts.
TEST(PhysicalSkyReference, StoredSamplesMeetTheirBandsNoiseGoal) {
  bench::SkyReference reference = bench::ReadSkyReference(kReferenceFile);
  const int max_paths = bench::kMaxReferencePathsFactor * reference.paths_per_query;
  int checked = 0;
  int at_most_paths = 0;
  for (const bench::SunBand& band : bench::SkyGrid::Quick().bands) {
    for (const bench::SkySample& sample : reference.samples) {
      if (sample.band != band.name) continue;
      ++checked;
      double noise = 0.0;
      for (int c = 0; c < 3; ++c)
        if (sample.value[c] >= reference.floors[size_t(sample.quantity)][c])
          noise = std::max(noise, sample.std_error[c] / sample.value[c]);
      if (sample.paths == max_paths) {
        ++at_most_paths;
        continue;
      }
      EXPECT_LE(noise, bench::NoiseGoal(band, sample.quantity))
          << band.name << ", " << bench::ToString(sample.quantity) << " sample with " << sample.paths << " paths";
    }
  }
  EXPECT_EQ(checked, 1092);
  // 24 low-sun radiances (which meet the low sun's 0.75% there: at most 0.74%), 14 twilight ones,
  // and 6 low-sun and twilight irradiances, at most 0.78% against their 0.1% (kIrradianceNoiseGoal);
  // docs/accuracy.md, "Accuracy against the physical sky".
  EXPECT_EQ(at_most_paths, 44);
}

// aerial_bench_sky --samples-csv: a header, then one row per sample and channel ending with the
// signed relative error tables / reference - 1 (here +10%, 0 and -25%, exact in binary to %.6g).
TEST(SkySamplesCsv, OneRowPerSampleAndChannelWithTheSignedError) {
  bench::SkyReference reference;
  reference.samples.push_back(
      {SkyQuantity::kSkyRadiance, "day", {0.0, 60.0, 30.0, 90.0}, {2.0, 4.0, 8.0}, {0.1, 0.1, 0.1}, 1024});
  std::string csv = bench::FormatSampleErrorsCsv(reference, {{2.2, 4.0, 6.0}});
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);
  EXPECT_EQ(csv.rfind("quantity,band,", 0), 0u) << csv;
  EXPECT_NE(csv.find("sky radiance,day,0,60,30,90,680,2,0.1,2.2,0.1\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",550,4,0.1,4,0\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",440,8,0.1,6,-0.25\n"), std::string::npos) << csv;
}

}  // namespace
}  // namespace aerial::testing
