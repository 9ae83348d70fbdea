#include "aerial/reference/phase_functions.h"

#include <gtest/gtest.h>

#include "aerial/reference/quadrature.h"

namespace aerial::reference {
namespace {

// int_S2 P dw = 2 pi int_-1^1 P(nu) dnu = 1 within 1e-6 (the brief's bound; adaptive quadrature to
// 1e-10 makes the integration error negligible, including Mie's forward peak at g = 0.8, 0.99).
TEST(PhaseFunctions, NormalizedOverTheSphere) {
  for (double g : {0.0, 0.5, 0.8, 0.99, -0.7}) {
    Values<3> v = IntegrateAdaptive<3>(
        [g](double nu) {
          return Values<3>{RayleighPhaseFunction(nu), CornetteShanksPhaseFunction(g, nu),
                           HenyeyGreensteinPhaseFunction(g, nu)};
        },
        {-1.0, 0.0, 0.9, 0.99, 1.0}, 1e-10);
    for (double integral : v) EXPECT_NEAR(2.0 * std::numbers::pi * integral, 1.0, 1e-6) << g;
  }
}

// The samplers invert their CDFs: CDF(Sample(u)) = u, with the closed forms
// Rayleigh (3/8)(nu + nu^3/3 + 4/3) and HG (1 - g^2)/(2g) ((1 + g^2 - 2g nu)^-1/2 - 1/(1 + g)).
// 1e-12: the cube root and square roots' rounding.
TEST(PhaseFunctions, SamplersInvertTheirCdf) {
  for (double u = 0.0; u <= 1.0; u += 0.0625) {
    double nu = SampleRayleighCosine(u);
    EXPECT_NEAR(0.375 * (nu + nu * nu * nu / 3.0 + 4.0 / 3.0), u, 1e-12);
    for (double g : {0.8, -0.3}) {
      double mu = SampleHenyeyGreensteinCosine(g, u);
      double cdf = (1.0 - g * g) / (2.0 * g) * (1.0 / std::sqrt(1.0 + g * g - 2.0 * g * mu) - 1.0 / (1.0 + g));
      EXPECT_NEAR(cdf, u, 1e-12) << g;
    }
  }
}

}  // namespace
}  // namespace aerial::reference
