#include "aerial/reference/solar_disc.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "aerial/reference/geometry.h"
#include "aerial/reference/optical_depth.h"
#include "aerial/reference/wavelength_groups.h"

namespace aerial::reference {
namespace {

constexpr double kPi = std::numbers::pi;

// The disc integrated the long way: a fine polar grid over the disc in exact spherical geometry
// (direction at angular distance rho alpha from the centre, at position angle phi; solid angle
// sin(rho alpha) alpha^2 drho dphi), each cell's centre visible or not, divided by the disc's
// solid angle 2 pi (1 - cos alpha). Midpoint rule: 600 x 600 cells, error ~1e-4 where the horizon
// cuts the disc (a cell row straddles it), ~1e-8 elsewhere.
Spectrum BruteForceDiscAverage(const Medium& medium, double r, double mu_s, bool cosine) {
  const double alpha = medium.atmosphere().sun_angular_radius_rad;
  const double theta_s = std::acos(mu_s), mu_horizon = CosHorizon(r, medium.bottom_radius());
  const int n = 600;
  Spectrum sum{};
  double solid_angle = 0.0;
  for (int i = 0; i < n; ++i) {
    double rho = alpha * (i + 0.5) / n;
    double cell = std::sin(rho) * (alpha / n) * (2.0 * kPi / n);
    for (int j = 0; j < n; ++j) {
      double phi = 2.0 * kPi * (j + 0.5) / n;
      // Zenith cosine of the direction at angle rho from the centre, position angle phi (phi = 0
      // towards the zenith): spherical law of cosines.
      double mu = std::cos(theta_s) * std::cos(rho) + std::sin(theta_s) * std::sin(rho) * std::cos(phi);
      solid_angle += cell;
      if (!(mu > mu_horizon)) continue;
      Spectrum t = ComputeTransmittance(medium, Accuracy::kMonteCarlo, r, mu,
                                        DistanceToOuterSphere(r, mu, medium.top_radius()));
      for (int c = 0; c < 3; ++c) sum[c] += cell * t[c] * (cosine ? std::max(mu, 0.0) : 1.0);
    }
  }
  for (double& s : sum) s /= solid_angle;
  return sum;
}

// The chord-quadrature disc average against the brute-force one, on the ground and at 10 km, with
// the disc high, low, cut by the horizon and just hidden. Tolerance 2e-4 relative: the flat-disc
// chord density (O(alpha^2) = 2e-5), the brute force's horizon row (~1e-5) and the Monte Carlo
// accuracy of the transmittance (1e-4, medium.h) of the brute force; plus 1e-9 absolute (of
// averages that are ~0.1-1 for a high sun) for slivers of the disc that the brute force's grid
// resolves coarsely, such as the 1e-8 left above the horizontal plane at 10 km.
TEST(SolarDisc, AveragesMatchABruteForceIntegralOverTheDisc) {
  AtmosphereParameters a = AtmosphereParameters::Earth();
  Medium medium(a);
  const double alpha = a.sun_angular_radius_rad;
  for (double altitude : {0.0, 10e3}) {
    double r = a.bottom_radius_m + altitude;
    double mu_horizon = CosHorizon(r, a.bottom_radius_m);
    double theta_h = std::acos(mu_horizon);
    for (double offset_in_radii : {200.0, 76.0, 20.0, 11.0, 1.5, 0.5, 0.0, -0.5}) {
      double mu_s = std::cos(theta_h - offset_in_radii * alpha);
      for (bool cosine : {false, true}) {
        Spectrum expected = BruteForceDiscAverage(medium, r, mu_s, cosine);
        Spectrum actual = cosine ? SunDiscHorizontalIrradianceFactor(medium, Accuracy::kReference, r, mu_s)
                                 : SunDiscTransmittance(medium, Accuracy::kReference, r, mu_s);
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(actual[c], expected[c], 2e-4 * expected[c] + 1e-9)
              << "altitude " << altitude << ", disc centre " << offset_in_radii
              << " radii above the horizon, cosine " << cosine << ", channel " << c;
      }
    }
    EXPECT_EQ(SunDiscTransmittance(medium, Accuracy::kReference, r, std::cos(theta_h + 1.01 * alpha))[2], 0.0);
  }
}

// The path tracer's one-point estimate averages to the brute-force integral: 40,000 draws within 4 of their standard errors plus the brute force's 2e-4 (above), with the disc
// cut by the horizon and low, on the ground
// and at 10 km. A density of the disc's points other than its area's (an arcsine law in y, tried)
// puts the low and cut discs' means 1-7% off and fails. A disc more than 20 degrees up draws
// nothing: its centre is its value.
TEST(SolarDisc, OnePointEstimateAveragesToTheDisc) {
  AtmosphereParameters a = AtmosphereParameters::Earth();
  Medium medium(a);
  const WavelengthGroups groups(a);
  const double alpha = a.sun_angular_radius_rad;
  Rng rng(7, 0);
  for (double altitude : {0.0, 10e3}) {
    const double r = a.bottom_radius_m + altitude;
    const double theta_h = std::acos(CosHorizon(r, a.bottom_radius_m));
    for (double offset_in_radii : {11.0, 1.5, 0.5, 0.0, -0.5}) {
      const double mu_s = std::cos(theta_h - offset_in_radii * alpha);
      for (bool cosine : {false, true}) {
        const Spectrum expected = BruteForceDiscAverage(medium, r, mu_s, cosine);
        const int draws = 40000;
        Spectrum sum{}, sum_sq{};
        for (int i = 0; i < draws; ++i) {
          Channels t = cosine ? SampleSunDiscHorizontalIrradianceFactor(groups, r, mu_s, rng)
                              : SampleSunDiscTransmittance(groups, r, mu_s, rng);
          for (int c = 0; c < 3; ++c) {
            sum[c] += t[c];
            sum_sq[c] += t[c] * t[c];
          }
        }
        for (int c = 0; c < 3; ++c) {
          const double mean = sum[c] / draws, variance = std::max(sum_sq[c] / draws - mean * mean, 0.0);
          EXPECT_NEAR(mean, expected[c], 4.0 * std::sqrt(variance / draws) + 2e-4 * expected[c] + 1e-9)
              << "altitude " << altitude << ", disc centre " << offset_in_radii << " radii above the horizon, cosine "
              << cosine << ", channel " << c;
        }
      }
    }
  }
  Rng untouched(7, 1), compared(7, 1);
  const double high = std::cos(0.5);
  const Channels centre = SampleSunDiscTransmittance(groups, a.bottom_radius_m, high, untouched);
  EXPECT_EQ(untouched.Next(), compared.Next()) << "a high sun draws nothing";
  EXPECT_NEAR(centre[1], SunDiscTransmittance(medium, Accuracy::kMonteCarlo, a.bottom_radius_m, high)[1], 1e-15);
}

// With no atmosphere the averages are geometric: the visible fraction of the disc, which for the
// centre on the horizon is 1/2, and on the ground the disc's mean of max(mu, 0), which for the
// centre on the horizon is the mean height of the upper half-disc, 4 alpha / (3 pi) (to O(alpha^3)),
// times 1/2.
TEST(SolarDisc, EmptyAtmosphereGivesTheDiscGeometry) {
  AtmosphereParameters a = AtmosphereParameters::Earth();
  a.rayleigh_scattering = a.mie_scattering = a.mie_extinction = a.absorption_extinction = {};
  Medium medium(a);
  const double R = a.bottom_radius_m, alpha = a.sun_angular_radius_rad;
  EXPECT_NEAR(SunDiscTransmittance(medium, Accuracy::kReference, R, 0.0)[0], 0.5, 1e-12);
  EXPECT_NEAR(SunDiscTransmittance(medium, Accuracy::kReference, R, 1.0)[0], 1.0, 1e-12);
  EXPECT_NEAR(SunDiscHorizontalIrradianceFactor(medium, Accuracy::kReference, R, 0.0)[0],
              0.5 * 4.0 * alpha / (3.0 * kPi), 1e-6 * alpha);
  // High sun: over a spherical cap the mean zenith cosine is cos(theta_s) (1 + cos alpha) / 2;
  // the flat chord density gets it to O(alpha^2) = 2e-5.
  double mu_s = std::cos(0.5);
  EXPECT_NEAR(SunDiscHorizontalIrradianceFactor(medium, Accuracy::kReference, R, mu_s)[0],
              mu_s * (1.0 + std::cos(alpha)) / 2.0, 2e-5 * mu_s);
}

}  // namespace
}  // namespace aerial::reference
