#include "aerial/reference/wavelength_groups.h"

#include <gtest/gtest.h>

#include <cmath>

#include "aerial/error.h"
#include "aerial/reference/reference.h"

namespace aerial::reference {
namespace {

// Earth at `count` groups of made-up wavelengths: Rayleigh as lambda^-4 and ozone, sunlight and
// ground albedo varied, so that the groups' extinctions span more than the three wavelengths of
// any one group (1.9x to 0.33x Earth's Rayleigh), as a 360-830 nm spectral sampling does.
std::vector<AtmosphereParameters> Groups(int count) {
  std::vector<AtmosphereParameters> groups;
  const AtmosphereParameters earth = AtmosphereParameters::Earth();
  for (int g = 0; g < count; ++g) {
    AtmosphereParameters a = earth;
    const double stretch = 0.85 + 0.45 * g / std::max(count - 1, 1);  // wavelength scale
    for (int c = 0; c < 3; ++c) {
      a.wavelengths_nm[c] = earth.wavelengths_nm[c] * stretch;
      a.rayleigh_scattering[c] = earth.rayleigh_scattering[c] / std::pow(stretch, 4.0);
      a.absorption_extinction[c] = earth.absorption_extinction[c] * (1.5 - 0.4 * g / count);
      a.solar_irradiance[c] = earth.solar_irradiance[c] * (0.8 + 0.1 * g);
      a.ground_albedo[c] = 0.1 + 0.02 * g;
    }
    groups.push_back(a);
  }
  return groups;
}

// A low sun seen across the air toward it: long, reddened paths, where the groups' weights differ
// the most from their sampling medium's.
constexpr double kR = 6360e3 + 500.0, kMu = 0.05, kMuS = 0.1, kNu = 0.9;

// Paths sampled from the groups' spread-out sampling medium and weighted at each group must
// estimate what each group's own paths do: within 4 combined standard errors, every channel.
TEST(WavelengthGroups, SharedPathsAgreeWithEachGroupsOwn) {
  const std::vector<AtmosphereParameters> atmospheres = Groups(4);
  const ReferenceGroups shared(atmospheres);
  const MonteCarloOptions options{.paths_per_query = 8192, .seed = 3};
  const MonteCarloOptions own_options{.paths_per_query = 8192, .seed = 4};
  GroupEstimates radiance = shared.ComputeRadiance(kR, kMu, kMuS, kNu, kAllOrders, INFINITY, options);
  GroupEstimates irradiance = shared.ComputeTiltedSkyIrradiance(kR, kMuS, 0.3, 0.2, kAllOrders, options);
  for (int g = 0; g < 4; ++g) {
    const Reference own(atmospheres[size_t(g)]);
    Estimate own_radiance = own.ComputeRadiance(kR, kMu, kMuS, kNu, kAllOrders, INFINITY, own_options);
    Estimate own_irradiance = own.ComputeTiltedSkyIrradiance(kR, kMuS, 0.3, 0.2, kAllOrders, own_options);
    for (int c = 0; c < 3; ++c) {
      const Estimate& a = radiance.groups[size_t(g)];
      EXPECT_NEAR(a.value[c], own_radiance.value[c], 4.0 * std::hypot(a.std_error[c], own_radiance.std_error[c]))
          << "radiance, group " << g << ", channel " << c;
      const Estimate& e = irradiance.groups[size_t(g)];
      EXPECT_NEAR(e.value[c], own_irradiance.value[c], 4.0 * std::hypot(e.std_error[c], own_irradiance.std_error[c]))
          << "irradiance, group " << g << ", channel " << c;
    }
  }
}

// Shared paths make the groups' errors move together, so the error of a sum over groups is not the
// root sum of squares of theirs: GroupEstimates::StdError takes it from the chunks. Against the
// spread of that sum over 12 seeds: within [0.55, 1.6] of it (the spread of 12 samples has a
// relative standard deviation of about 21%). The root sum of squares of the groups' own errors,
// which treats them as independent, comes out below 0.6 of it here: the test tells them apart.
TEST(WavelengthGroups, ErrorOfASumOverGroupsMatchesItsSpreadOverSeeds) {
  const int count = 8, seeds = 12;
  const ReferenceGroups shared(Groups(count));
  Channels weights(3 * count, 1.0 / (3 * count));
  std::vector<double> sums;
  double predicted = 0.0, independent = 0.0;
  for (int seed = 1; seed <= seeds; ++seed) {
    GroupEstimates e = shared.ComputeRadiance(kR, kMu, kMuS, kNu, kAllOrders, INFINITY,
                                              {.paths_per_query = 2048, .seed = uint64_t(seed)});
    double sum = 0.0, variance = 0.0;
    for (int c = 0; c < 3 * count; ++c) {
      sum += weights[c] * e.groups[size_t(c / 3)].value[c % 3];
      variance += std::pow(weights[c] * e.groups[size_t(c / 3)].std_error[c % 3], 2.0);
    }
    sums.push_back(sum);
    predicted += e.StdError(weights) / seeds;
    independent += std::sqrt(variance) / seeds;
  }
  double mean = 0.0, spread = 0.0;
  for (double s : sums) mean += s / seeds;
  for (double s : sums) spread += std::pow(s - mean, 2.0) / (seeds - 1);
  spread = std::sqrt(spread);
  EXPECT_GT(predicted, 0.55 * spread);
  EXPECT_LT(predicted, 1.6 * spread);
  EXPECT_LT(independent, 0.6 * spread);
}

TEST(WavelengthGroups, GroupsMustShareTheirGeometry) {
  std::vector<AtmosphereParameters> groups = Groups(3);
  groups[2].top_radius_m += 1000.0;
  try {
    WavelengthGroups{groups};
    FAIL() << "groups of different atmospheres were accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "groups[2]");
  }
  try {
    WavelengthGroups{Groups(kMaxWavelengthGroups + 1)};
    FAIL() << "more groups than channels were accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "groups");
    EXPECT_EQ(e.value(), std::to_string(kMaxWavelengthGroups + 1));
  }
}

}  // namespace
}  // namespace aerial::reference
