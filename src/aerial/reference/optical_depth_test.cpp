#include "aerial/reference/optical_depth.h"

#include <gtest/gtest.h>

#include "aerial/reference/test_atmospheres.h"

namespace aerial::reference {
namespace {

// Zenith optical depth of an exponential layer: int_0^(Rt-R) beta exp(-h/H) dh
// = beta H (1 - exp(-(Rt - R)/H)). The Gauss-Legendre remainder is ~1e-18 (medium.h), so 1e-9
// (the brief's bound) leaves room for the summation's rounding only.
TEST(Transmittance, ZenithExponentialLayerMatchesClosedForm) {
  for (double scale_height : {8000.0, 1200.0}) {
    AtmosphereParameters a = testing::ExponentialRayleigh(scale_height);
    Medium medium(a);
    double thickness = a.top_radius_m - a.bottom_radius_m;
    Spectrum t = ComputeTransmittance(medium, Accuracy::kReference, a.bottom_radius_m, 1.0, thickness);
    for (int c = 0; c < 3; ++c) {
      double expected =
          std::exp(-a.rayleigh_scattering[c] * scale_height * -std::expm1(-thickness / scale_height));
      EXPECT_NEAR(t[c] / expected, 1.0, 1e-9) << scale_height << " " << c;
    }
  }
}

// A uniform layer along a horizontal ray from 500 m up: T = exp(-beta L) with the chord
// L = sqrt(Rt^2 - r^2). Constant densities integrate exactly; 1e-12 is rounding.
TEST(Transmittance, HorizontalUniformLayerMatchesChord) {
  const Spectrum beta = {1e-6, 2e-6, 5e-6};
  AtmosphereParameters a = testing::UniformRayleigh(beta, 10e3);
  Medium medium(a);
  double r = a.bottom_radius_m + 500.0;
  double chord = std::sqrt(a.top_radius_m * a.top_radius_m - r * r);
  Spectrum t = ComputeTransmittance(medium, Accuracy::kReference, r, 0.0, chord);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(t[c] / std::exp(-beta[c] * chord), 1.0, 1e-12) << c;
}

// The ozone tent (0 at 10 km, 1 at 25 km, 0 at 40 km) has a zenith column of 15 km (the
// triangle's area). Its kinks are levels, so the piecewise-linear integrand is exact: 1e-12.
TEST(Transmittance, OzoneTentZenithColumnIsFifteenKilometers) {
  AtmosphereParameters a = testing::Empty();
  AtmosphereParameters earth = AtmosphereParameters::Earth();
  a.absorption_density = earth.absorption_density;
  a.absorption_extinction = earth.absorption_extinction;
  Medium medium(a);
  for (Accuracy accuracy : {Accuracy::kReference, Accuracy::kMonteCarlo}) {
    Column column = ComputeColumn(medium, accuracy, a.bottom_radius_m, 1.0, 60e3);
    EXPECT_NEAR(column.absorption / 15e3, 1.0, 1e-12);
    Spectrum t = ComputeTransmittance(medium, accuracy, a.bottom_radius_m, 1.0, 60e3);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(t[c] / std::exp(-a.absorption_extinction[c] * 15e3), 1.0, 1e-12);
  }
}

// Monte Carlo accuracy is ~1e-4 of the optical depth (medium.h); check grazing rays, the worst
// case, against the reference: rays that just miss the ground, and horizontal ones, which stay
// above their start, from within the Mie layer and from above where its levels stop.
TEST(Transmittance, MonteCarloAccuracyIsWithin1e4OfReference) {
  Medium medium(AtmosphereParameters::Earth());
  for (double altitude : {5e3, 19e3, 22e3, 30e3}) {
    double r = medium.bottom_radius() + altitude;
    for (double mu : {CosHorizon(r, medium.bottom_radius()) + 0.002, 0.0}) {
      double length = DistanceToOuterSphere(r, mu, medium.top_radius());
      Spectrum a = medium.OpticalDepth(ComputeColumn(medium, Accuracy::kReference, r, mu, length));
      Spectrum b = medium.OpticalDepth(ComputeColumn(medium, Accuracy::kMonteCarlo, r, mu, length));
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(b[c] / a[c], 1.0, 1e-4) << altitude << " m, mu " << mu << ", channel " << c;
    }
  }
}

// Optical depth is additive along a ray: [0, s] + [s, L] = [0, L] (RayColumns::ColumnTo against
// ComputeColumn over the same ray, including the downward, tangent and upward parts). 1e-12.
TEST(RayColumns, ColumnToIsAdditive) {
  Medium medium(AtmosphereParameters::Earth());
  double r = medium.bottom_radius() + 3000.0, mu = -0.02;
  double length = DistanceToOuterSphere(r, mu, medium.top_radius());
  RayColumns columns;
  columns.Build(medium, Accuracy::kReference, r, mu, length);
  EXPECT_DOUBLE_EQ(columns.length(), length);
  for (double s : {0.0, 1234.5, -r * mu, 250e3, length}) {
    Column direct = ComputeColumn(medium, Accuracy::kReference, r, mu, s);
    Column cut = columns.ColumnTo(s);
    EXPECT_NEAR(cut.rayleigh, direct.rayleigh, 1e-12 * columns.cumulative().back().rayleigh) << s;
    EXPECT_NEAR(cut.mie, direct.mie, 1e-12 * columns.cumulative().back().mie) << s;
  }
}

}  // namespace
}  // namespace aerial::reference
