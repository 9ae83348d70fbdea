// The 3D tables (nu dropped, Elek 2009): against the CPU reference where their one assumption (the
// sun keeps its zenith angle along the view ray) holds exactly, against the 4D tables in daylight,
// and at twilight, where they are known to lose the Earth's shadow.
#include <gtest/gtest.h>

#include <cstdio>

#include "aerial/probe/table_probe.h"
#include "aerial/reference/reference.h"
#include "comparison.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

std::vector<ProbeQuery> ToQueries(const std::vector<ViewAngles>& views) {
  std::vector<ProbeQuery> queries;
  for (const ViewAngles& v : views) queries.push_back({ToRayParameters(v, AtmosphereParameters::Earth()), 0.0});
  return queries;
}

class Lut3d : public GpuTest {};

// Along a vertical ray the sun's zenith angle does not change (mu_s_d = (r mu_s + d nu) / r_d with
// nu = mu_s when mu = 1), so single scattering in 3D is exact there, up to the same table
// interpolation as in 4D: the 4D single-scattering bounds apply.
TEST_F(Lut3d, SingleScatteringMatchesReferenceOnVerticalRays) {
  auto views = ViewGrid({0.0, 10e3}, {0.0}, {0.0, 30.0, 60.0, 80.0}, {0.0});
  auto results = ProbeTables(FullTables(/*orders=*/1, LutVariant::k3D), ToQueries(views));
  reference::Reference reference(AtmosphereParameters::Earth());
  WorstError rayleigh(1e-12), mie(1e-12);
  for (size_t i = 0; i < views.size(); ++i) {
    RayParameters ray = ToRayParameters(views[i], AtmosphereParameters::Earth());
    auto expected = reference.ComputeSingleScattering(ray.r, ray.mu, ray.mu_s, ray.nu);
    rayleigh.Add(results[i].rayleigh, expected.rayleigh, Describe(views[i]));
    mie.Add(results[i].mie, expected.mie, Describe(views[i]));
  }
  // Every view (2 altitudes x 4 suns) and channel: looking up in daylight, no value is near 1e-12.
  EXPECT_TRUE(ComparedExactly(rayleigh, 2 * 4 * 3));
  EXPECT_TRUE(ComparedExactly(mie, 2 * 4 * 3));
  std::printf("3d single rayleigh: %s\n3d single mie: %s\n", rayleigh.Summary().c_str(), mie.Summary().c_str());
  // 4D bounds for the same cameras: 0.5% on the ground; 2% at 10 km (r-slice spacing).
  EXPECT_LT(rayleigh.value(), 2e-2) << rayleigh.Summary();
  EXPECT_LT(mie.value(), 2e-2) << mie.Summary();
}

// A vertical view has no azimuth, so the azimuth-averaged density is exact too: the 4-order sky at
// the zenith is as close to the reference as the 4D tables are (4D bound on the ground: 2%).
TEST_F(Lut3d, FourOrderZenithSkyMatchesReference) {
  auto views = ViewGrid({0.0}, {0.0}, {0.0, 30.0, 60.0}, {0.0});
  auto results = ProbeTables(FullTables(4, LutVariant::k3D), ToQueries(views));
  reference::Reference reference(AtmosphereParameters::Earth());
  WorstError worst(1e-12);
  for (size_t i = 0; i < views.size(); ++i) {
    RayParameters ray = ToRayParameters(views[i], AtmosphereParameters::Earth());
    auto expected = reference.ComputeRadiance(ray.r, ray.mu, ray.mu_s, ray.nu, 4, INFINITY, {.paths_per_query = 16384});
    worst.Add(results[i].sky_radiance, expected.value, Describe(views[i]));
  }
  EXPECT_TRUE(ComparedExactly(worst, 3 * 3));  // every sun and channel: daylight, far above 1e-12
  std::printf("3d 4-order zenith sky: %s\n", worst.Summary().c_str());
  EXPECT_LT(worst.value(), 2e-2) << worst.Summary();
}

// Daylight (sun zenith <= 80 degrees), cameras from the ground to 30 km, views above the horizon:
// the 3D tables against the 4D ones. Measured: worst 3.9%, looking at the horizon toward a low sun
// (view zenith 89, sun zenith 80), where the sun's elevation changes most along the long path; the
// 3% aim holds elsewhere. Bound 5%.
TEST_F(Lut3d, DaylightSkyWithinMeasuredBoundOf4d) {
  auto views = ViewGrid({0.0, 2e3, 10e3, 30e3}, {0.0, 30.0, 60.0, 75.0, 85.0, 89.0},
                        {0.0, 20.0, 40.0, 60.0, 70.0, 80.0}, {0.0, 45.0, 90.0, 135.0, 180.0});
  auto queries = ToQueries(views);
  auto results_3d = ProbeTables(FullTables(4, LutVariant::k3D), queries);
  auto results_4d = ProbeTables(FullTables(4, LutVariant::k4D), queries);
  WorstError worst(1e-12);
  for (size_t i = 0; i < views.size(); ++i)
    worst.Add(results_3d[i].sky_radiance, results_4d[i].sky_radiance, Describe(views[i]));
  // Every view (4 x 6 x 6 x 5) and channel: daylight skies, far above 1e-12.
  EXPECT_TRUE(ComparedExactly(worst, 4 * 6 * 6 * 5 * 3));
  std::printf("3d vs 4d, daylight: %s\n", worst.Summary().c_str());
  EXPECT_LT(worst.value(), 0.05) << worst.Summary();
}

// Twilight: the sun 6 degrees below the horizon, looking away from it, where the sky is lit from
// above the Earth's shadow. The 3D tables, whose sun keeps the camera's elevation along every ray
// (also along the rays of the multiple-scattering orders, which dominate at twilight), measure
// 0.679 of the 4D blue radiance there. Against the reference with all orders (aerial probe
// --reference), 4D is 4.4% high and 3D 29% low. Before the 4D sky's single scattering correction
// (sky_lookup.glsl) the ratio was 0.581, with 4D 22% high; with Bruneton 2017's table sizes, 0.732. The
// ratio is pinned to [0.62, 0.75] so that the difference is neither hidden nor silently changed.
TEST_F(Lut3d, TwilightLosesTheEarthShadowByAPinnedAmount) {
  ViewAngles view{0.0, 30.0, 96.0, 180.0};
  std::vector<ProbeQuery> query = ToQueries({view});
  Spectrum sky_3d = ProbeTables(FullTables(4, LutVariant::k3D), query).front().sky_radiance;
  Spectrum sky_4d = ProbeTables(FullTables(4, LutVariant::k4D), query).front().sky_radiance;
  double blue_ratio = sky_3d[2] / sky_4d[2];
  std::printf("twilight (%s): 3d/4d blue = %.3f\n", Describe(view).c_str(), blue_ratio);
  EXPECT_GT(blue_ratio, 0.62);
  EXPECT_LT(blue_ratio, 0.75);
}

}  // namespace
}  // namespace aerial::testing
