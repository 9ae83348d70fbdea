#include "aerial/reference/single_scattering.h"

#include <gtest/gtest.h>

#include "aerial/reference/geometry.h"
#include "aerial/reference/optical_depth.h"
#include "aerial/reference/solar_disc.h"
#include "aerial/reference/test_atmospheres.h"

namespace aerial::reference {
namespace {

// A 1 km uniform layer seen at the zenith from the ground with the sun at mu_s = 0.5: in the
// plane-parallel approximation S = beta E int_0^Z exp(-beta s - beta (Z - s) / mu_s) ds
// = beta E exp(-beta Z / mu_s) (1 - exp(-a Z)) / a, a = beta (1 - 1 / mu_s). Sphericity lengthens
// the sun path by ~(Z / 2R) tan^2(theta_s) ~ 2e-4 relatively, i.e. ~1e-6 of S for tau_sun <= 6e-3:
// tolerance 1e-5.
TEST(SingleScattering, ThinUniformLayerMatchesFirstOrderClosedForm) {
  const Spectrum beta = {1e-6, 2e-6, 3e-6};
  const double height = 1000.0, mu_s = 0.5;
  AtmosphereParameters a = testing::UniformRayleigh(beta, height);
  Medium medium(a);
  SingleScattering s = ComputeSingleScattering(medium, a.bottom_radius_m, 1.0, mu_s, mu_s, height);
  for (int c = 0; c < 3; ++c) {
    double k = beta[c] * (1.0 - 1.0 / mu_s);
    double expected = beta[c] * a.solar_irradiance[c] * std::exp(-beta[c] * height / mu_s) *
                      -std::expm1(-k * height) / k;
    EXPECT_NEAR(s.rayleigh[c] / expected, 1.0, 1e-5) << c;
    EXPECT_EQ(s.mie[c], 0.0);
  }
}

// Seen from the ground with the sun 11.5 degrees below the horizon, the whole zenith ray (whose
// horizon dips by at most 7.9 degrees at 60 km) is in the Earth's shadow: exactly zero.
TEST(SingleScattering, ZeroInTheEarthsShadow) {
  Medium medium(AtmosphereParameters::Earth());
  SingleScattering s = ComputeSingleScattering(medium, medium.bottom_radius(), 1.0, -0.2, -0.2,
                                               medium.top_radius() - medium.bottom_radius());
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(s.rayleigh[c], 0.0);
    EXPECT_EQ(s.mie[c], 0.0);
  }
}

// At twilight (sun 2.9 degrees below the horizon) a ray towards the sun leaves the Earth's shadow
// and penumbra partway. The adaptive result must match a brute-force 10000-step midpoint rule,
// whose error (h = 100 m, integrand C1 at the penumbra's edges) is below 1e-5, to the brief's
// 1e-4.
TEST(SingleScattering, TwilightMatchesBruteForceMidpointRule) {
  AtmosphereParameters a = AtmosphereParameters::Earth();
  Medium medium(a);
  const double r = a.bottom_radius_m + 100.0, mu = 0.1, mu_s = -0.05;
  const double nu = mu * mu_s + std::sqrt((1 - mu * mu) * (1 - mu_s * mu_s));
  const double length = DistanceToOuterSphere(r, mu, a.top_radius_m);
  SingleScattering s = ComputeSingleScattering(medium, r, mu, mu_s, nu, length);
  const int steps = 10000;
  const double h = length / steps;
  Spectrum rayleigh{}, mie{};
  RayColumns view;
  view.Build(medium, Accuracy::kReference, r, mu, length);
  for (int i = 0; i < steps; ++i) {
    double d = (i + 0.5) * h, r_d = RadiusAt(r, mu, d), mu_s_d = (r * mu_s + d * nu) / r_d;
    Spectrum t_sun = SunDiscTransmittance(medium, Accuracy::kReference, r_d, mu_s_d);
    if (t_sun == Spectrum{}) continue;
    Spectrum t = medium.Transmittance(view.ColumnTo(d));
    Densities rho = medium.At(r_d - a.bottom_radius_m);
    for (int c = 0; c < 3; ++c) {
      double light = h * t[c] * t_sun[c] * a.solar_irradiance[c];
      rayleigh[c] += light * a.rayleigh_scattering[c] * rho.rayleigh;
      mie[c] += light * a.mie_scattering[c] * rho.mie;
    }
  }
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(s.rayleigh[c], 0.0);
    EXPECT_NEAR(s.rayleigh[c] / rayleigh[c], 1.0, 1e-4) << c;
    EXPECT_NEAR(s.mie[c] / mie[c], 1.0, 1e-4) << c;
  }
}

}  // namespace
}  // namespace aerial::reference
