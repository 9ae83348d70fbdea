#include "aerial/reference/irradiance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "aerial/reference/geometry.h"
#include "aerial/reference/optical_depth.h"
#include "aerial/reference/phase_functions.h"
#include "aerial/reference/quadrature.h"
#include "aerial/reference/single_scattering.h"
#include "aerial/reference/test_atmospheres.h"

namespace aerial::reference {
namespace {

// Direct irradiance at the ground under an exponential layer: with the sun at the zenith,
// E_sun exp(-beta H (1 - exp(-(Rt - R)/H))) (closed form, 1e-9 as for transmittance); with the
// whole disc below the horizon, 0. (The disc cut by the horizon: solar_disc_test.)
TEST(DirectIrradiance, MatchesClosedFormsAndDiscAverageCosine) {
  AtmosphereParameters a = testing::ExponentialRayleigh();
  Medium medium(a);
  const double R = a.bottom_radius_m, H = 8000.0, alpha = a.sun_angular_radius_rad;
  Spectrum zenith = ComputeDirectIrradiance(medium, Accuracy::kReference, R, 1.0);
  Spectrum below = ComputeDirectIrradiance(medium, Accuracy::kReference, R, -1.01 * alpha);
  for (int c = 0; c < 3; ++c) {
    double tau = a.rayleigh_scattering[c] * H * -std::expm1(-(a.top_radius_m - R) / H);
    EXPECT_NEAR(zenith[c] / (a.solar_irradiance[c] * std::exp(-tau)), 1.0, 1e-9);
    EXPECT_EQ(below[c], 0.0);
  }
}

// Order 1 of the path-traced sky irradiance must equal the hemisphere integral of the
// deterministic single scattering, E_1 = int_0^2pi int_0^1 L_1(mu, phi) mu dmu dphi with
// L_1 = S_R P_R(nu). Rayleigh only, so L_1 is smooth: adaptive Gauss-Kronrod in mu (1e-5) times a
// 12-point trapezoid in phi over [0, pi] (symmetric, periodic: spectrally accurate, < 1e-6).
// Tolerance: 4 standard errors plus 1e-4 (the Monte Carlo transmittance, medium.h).
TEST(SkyIrradiance, OrderOneMatchesHemisphereIntegralOfSingleScattering) {
  AtmosphereParameters a = testing::ExponentialRayleigh();
  Medium medium(a);
  const double r = a.bottom_radius_m + 500.0, mu_s = 0.6;
  const int azimuths = 12;
  auto radiance_times_mu = [&](double mu) {
    Values<3> out{};
    for (int j = 0; j <= azimuths; ++j) {
      double phi = M_PI * j / azimuths, weight = (j == 0 || j == azimuths ? 0.5 : 1.0) * 2.0 * M_PI / azimuths;
      double nu = mu * mu_s + std::sqrt((1.0 - mu * mu) * (1.0 - mu_s * mu_s)) * std::cos(phi);
      SingleScattering s = ComputeSingleScattering(medium, r, mu, mu_s, nu,
                                                   DistanceToOuterSphere(r, mu, a.top_radius_m), 1e-6);
      for (int c = 0; c < 3; ++c) out[c] += weight * mu * s.rayleigh[c] * RayleighPhaseFunction(nu);
    }
    return out;
  };
  Values<3> expected = IntegrateAdaptive<3>(radiance_times_mu, {0.0, 0.1, 1.0}, 1e-5);
  OrderEstimates e = EstimateSkyIrradianceOrders(medium, r, mu_s, 1.0, mu_s, 1, {32768, 1, 0});
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(e.orders[1].value[c], expected[c], 4.0 * e.orders[1].std_error[c] + 1e-4 * expected[c]) << c;
    EXPECT_LT(e.orders[1].std_error[c], 3e-3 * expected[c]);
  }
}

// The same on a surface tilted 60 degrees, facing 120 degrees of azimuth away from the sun: order 1
// must be the integral over the hemisphere about the normal n of the single scattering along each
// direction w, to the top of the atmosphere or, below the horizon, to the (black) ground:
// E_1(n) = int_{n.w > 0} L_1(w) (n . w) dw. In the world frame w = (mu, phi): adaptive Gauss-Kronrod
// in mu (1e-5), with breakpoints at the horizon (where L_1 jumps) and where the arc of n.w > 0
// becomes a whole circle or none, times 4 x 8-point Gauss-Legendre in phi over that arc (smooth
// there). This checks where the estimator puts the sun and the ground relative to the normal.
TEST(SkyIrradiance, TiltedOrderOneMatchesHemisphereIntegralOfSingleScattering) {
  AtmosphereParameters a = testing::ExponentialRayleigh();
  Medium medium(a);
  const double R = a.bottom_radius_m, r = R + 500.0, mu_s = 0.6, sin_s = 0.8;
  const double mu_n = 0.5, sin_n = std::sqrt(0.75), phi_n = 2.0 * M_PI / 3.0;
  const double nu_n = sin_n * std::cos(phi_n) * sin_s + mu_n * mu_s;  // the sun at phi = 0
  auto radiance_times_cosine = [&](double mu) {
    Values<3> out{};
    double sin_w = std::sqrt(std::max(1.0 - mu * mu, 0.0));
    // n . w = mu_n mu + sin_n sin_w cos(phi - phi_n) > 0 on phi_n -+ half_arc.
    double c = sin_w > 0.0 ? -mu_n * mu / (sin_n * sin_w) : (mu_n * mu > 0.0 ? -2.0 : 2.0);
    if (c >= 1.0) return out;
    double half_arc = c <= -1.0 ? M_PI : std::acos(c);
    bool ground = RayIntersectsInnerSphere(r, mu, R);
    double length = ground ? DistanceToInnerSphere(r, mu, R) : DistanceToOuterSphere(r, mu, a.top_radius_m);
    const int pieces = 4;
    for (int p = 0; p < pieces; ++p) {
      double from = phi_n - half_arc + 2.0 * half_arc * p / pieces, to = from + 2.0 * half_arc / pieces;
      ForEachGaussLegendreNode(kGaussLegendre8X, kGaussLegendre8W, from, to, [&](double phi, double weight) {
        double nu = sin_w * std::cos(phi) * sin_s + mu * mu_s;
        double cosine = mu_n * mu + sin_n * sin_w * std::cos(phi - phi_n);
        SingleScattering s = ComputeSingleScattering(medium, r, mu, mu_s, nu, length, 1e-6);
        for (int c = 0; c < 3; ++c) out[c] += weight * cosine * s.rayleigh[c] * RayleighPhaseFunction(nu);
      });
    }
    return out;
  };
  Values<3> expected = IntegrateAdaptive<3>(
      radiance_times_cosine, {-1.0, -sin_n, CosHorizon(r, R), sin_n, 1.0}, 1e-4);
  OrderEstimates e = EstimateSkyIrradianceOrders(medium, r, mu_s, mu_n, nu_n, 1, {32768, 1, 0});
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(e.orders[1].value[c], expected[c], 4.0 * e.orders[1].std_error[c] + 2e-4 * expected[c]) << c;
    EXPECT_LT(e.orders[1].std_error[c], 1e-2 * expected[c]);
  }
}

// Sky irradiance orders are positive and, in Earth's atmosphere, each smaller than the
// previous beyond 4 standard errors (as for radiance, multiple_scattering_test.cpp).
TEST(SkyIrradiance, OrdersArePositiveAndDecrease) {
  Medium medium(AtmosphereParameters::Earth());
  OrderEstimates e = EstimateSkyIrradianceOrders(medium, medium.bottom_radius(), 0.7, 1.0, 0.7, 3, {4096, 1, 0});
  for (int c = 0; c < 3; ++c) {
    for (int k = 1; k <= 3; ++k) EXPECT_GT(e.orders[k].value[c], 0.0);
    for (int k = 2; k <= 3; ++k) {
      EXPECT_LT(e.orders[k].value[c] + 4.0 * e.orders[k].std_error[c],
                e.orders[k - 1].value[c] - 4.0 * e.orders[k - 1].std_error[c]);
    }
  }
}

// A surface on the ground facing straight down sees only the ground beside it, through no air:
// a Lambertian ground of albedo a lit by E_0 + E_sky has radiance a / pi (E_0 + E_sky), so the
// downward irradiance is a (E_0 + E_sky), one order up: order 1 is a E_0, order k + 1 is a times
// order k of the upward sky irradiance. Tolerance: 4 standard errors of both plus 1e-4 (the Monte
// Carlo direct irradiance at the ground vertex, medium.h).
TEST(SkyIrradiance, FacingDownOnTheGroundSeesTheLitGround) {
  Medium medium(AtmosphereParameters::Earth());
  const double R = medium.bottom_radius(), mu_s = 0.6;
  const Spectrum& albedo = medium.atmosphere().ground_albedo;
  OrderEstimates down = EstimateSkyIrradianceOrders(medium, R, mu_s, -1.0, -mu_s, 3, {8192, 1, 0});
  OrderEstimates up = EstimateSkyIrradianceOrders(medium, R, mu_s, 1.0, mu_s, 2, {8192, 2, 0});
  Spectrum direct = ComputeDirectIrradiance(medium, Accuracy::kReference, R, mu_s);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(down.orders[1].value[c], albedo[c] * direct[c],
                4.0 * down.orders[1].std_error[c] + 1e-4 * albedo[c] * direct[c]) << c;
    for (int k = 1; k <= 2; ++k) {
      double expected = albedo[c] * up.orders[k].value[c];
      EXPECT_NEAR(down.orders[k + 1].value[c], expected,
                  4.0 * std::hypot(down.orders[k + 1].std_error[c], albedo[c] * up.orders[k].std_error[c]) +
                      1e-4 * expected)
          << "order " << k + 1 << ", channel " << c;
    }
  }
}

}  // namespace
}  // namespace aerial::reference
