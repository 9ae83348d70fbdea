#include "aerial/spectrum/higher_orders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace aerial::spectrum {
namespace {

// Through as many points as functions, the fit interpolates: any combination of the functions is
// read back exactly. Checked with 1, x and x^2 through 3 points, read between and beyond them.
TEST(LeastSquaresWeights, InterpolateTheBasisFunctions) {
  const std::vector<double> xs = {0.0, 1.0, 3.0};
  auto functions = [](double x) { return std::vector<double>{1.0, x, x * x}; };
  std::vector<std::vector<double>> basis;
  for (double x : xs) basis.push_back(functions(x));
  for (double at : {0.5, 2.0, 4.0}) {
    std::vector<double> weights = LeastSquaresWeights(basis, functions(at));
    double value = 0.0;
    for (size_t j = 0; j < xs.size(); ++j) value += weights[j] * (2.0 - 0.5 * xs[j] + 0.25 * xs[j] * xs[j]);
    EXPECT_NEAR(value, 2.0 - 0.5 * at + 0.25 * at * at, 1e-12) << "at " << at;
  }
}

// With more points than functions, a line fitted through 4 points that do not lie on one: the
// least-squares line of (0, 0), (1, 1), (2, 1), (3, 3) is y = 0.9 x - 0.1 (normal equations by
// hand: sum x = 6, sum x^2 = 14, sum y = 5, sum xy = 12).
TEST(LeastSquaresWeights, FitALineThroughFourPoints) {
  const std::vector<double> xs = {0.0, 1.0, 2.0, 3.0}, ys = {0.0, 1.0, 1.0, 3.0};
  std::vector<std::vector<double>> basis;
  for (double x : xs) basis.push_back({1.0, x});
  std::vector<double> weights = LeastSquaresWeights(basis, {1.0, 1.5});
  double value = 0.0;
  for (size_t j = 0; j < xs.size(); ++j) value += weights[j] * ys[j];
  EXPECT_NEAR(value, 0.9 * 1.5 - 0.1, 1e-12);
}

// Every other wavelength has all orders; the others read theirs from those alone.
TEST(HigherOrderStencils, ReadOnlyWavelengthsWithAllOrders) {
  SpectralAtmosphere earth(AtmosphereParameters::Earth());
  std::vector<HigherOrderStencil> stencils = HigherOrderStencils(SpectralSampling::ForTables(12), earth);
  ASSERT_EQ(stencils.size(), 12u);
  for (int w = 0; w < 12; ++w) {
    if (HasAllOrders(w)) {
      EXPECT_EQ(stencils[w].from, std::vector<int>{w});
      continue;
    }
    EXPECT_FALSE(stencils[w].from.empty()) << w;
    for (int k : stencils[w].from) EXPECT_TRUE(HasAllOrders(k)) << w << " from " << k;
    EXPECT_EQ(stencils[w].from.size(), stencils[w].weights.size());
  }
}

// A light path's response per unit of sunlight, a lambda^b exp(-c ozone(lambda)) (a power law for
// the scattering, Beer-Lambert for the ozone on the path), lies in the fit's basis: every
// wavelength between two with all orders reads it back to rounding, for a zenith path (c small)
// and a twilight one through 30 times more ozone. The last wavelength (810 nm) has neighbours on
// one side only and fits a line in log(lambda): it is not exact, and is not checked.
TEST(HigherOrderStencils, ReadBackAPowerLawThroughOzone) {
  SpectralAtmosphere earth(AtmosphereParameters::Earth());
  const SpectralSampling sampling = SpectralSampling::ForTables(12);
  std::vector<HigherOrderStencil> stencils = HigherOrderStencils(sampling, earth);
  const std::vector<double>& nm = sampling.wavelengths_nm();
  for (double ozone_depth : {0.03, 1.0}) {
    auto log_response = [&](double lambda) {
      return std::log(3e-3) - 4.2 * std::log(lambda / 550.0) -
             ozone_depth * earth.AbsorptionExtinction(lambda) / earth.AbsorptionExtinction(600.0);
    };
    for (int w = 0; w + 1 < 12; ++w) {
      if (HasAllOrders(w)) continue;
      double fitted = 0.0;
      for (size_t j = 0; j < stencils[w].from.size(); ++j) fitted += stencils[w].weights[j] * log_response(nm[stencils[w].from[j]]);
      EXPECT_NEAR(fitted, log_response(nm[w]), 1e-9) << nm[w] << " nm, ozone depth " << ozone_depth;
    }
  }
}

// Light of the orders >= 2 in the Earth's shadow has crossed long columns of air: its log response
// also falls as Rayleigh's coefficient times the column. Where a wavelength has four neighbours
// with all orders (at 12 wavelengths: 3, 5 and 7), the fit reads that back to rounding, from a thin
// column to twilight's (an optical depth of 20 at 550 nm), on top of the power law and the ozone.
TEST(HigherOrderStencils, ReadBackRayleighsColumnWhereFourNeighboursHaveIt) {
  SpectralAtmosphere earth(AtmosphereParameters::Earth());
  const SpectralSampling sampling = SpectralSampling::ForTables(12);
  std::vector<HigherOrderStencil> stencils = HigherOrderStencils(sampling, earth);
  const std::vector<double>& nm = sampling.wavelengths_nm();
  int checked = 0;
  for (double rayleigh_depth : {0.1, 20.0}) {
    auto log_response = [&](double lambda) {
      return std::log(3e-3) - 4.2 * std::log(lambda / 550.0) -
             0.5 * earth.AbsorptionExtinction(lambda) / earth.AbsorptionExtinction(600.0) -
             rayleigh_depth * earth.RayleighScattering(lambda) / earth.RayleighScattering(550.0);
    };
    for (int w = 0; w < 12; ++w) {
      if (stencils[w].from.size() != 4) continue;
      ++checked;
      double fitted = 0.0;
      for (size_t j = 0; j < 4; ++j) fitted += stencils[w].weights[j] * log_response(nm[stencils[w].from[j]]);
      EXPECT_NEAR(fitted, log_response(nm[w]), 1e-9) << nm[w] << " nm, Rayleigh depth " << rayleigh_depth;
    }
  }
  EXPECT_EQ(checked, 6);
}

// From 12 wavelengths up no stencil passes on more than 4 times its neighbours' errors (sum of
// |weights|; the three-function fits reach 3.9 at 48 wavelengths). Without the check on the
// four-function fit, that fit's weights reached 42 at 24 wavelengths. At 6 wavelengths, 78 nm
// apart, the three-function fit alone already passes on 11 times: that count is for quick looks.
TEST(HigherOrderStencils, KeepTheirNoiseGainBounded) {
  SpectralAtmosphere earth(AtmosphereParameters::Earth());
  for (int count : {12, 18, 24, 36, 48}) {
    double most = 0.0;
    for (const HigherOrderStencil& stencil : HigherOrderStencils(SpectralSampling::ForTables(count), earth)) {
      double gain = 0.0;
      for (double w : stencil.weights) gain += std::abs(w);
      most = std::max(most, gain);
    }
    std::printf("%d wavelengths: noise gain %.2f at most\n", count, most);
    EXPECT_LE(most, 4.0) << count << " wavelengths";
  }
}

}  // namespace
}  // namespace aerial::spectrum
