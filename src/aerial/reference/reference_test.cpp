#include "aerial/reference/reference.h"

#include <gtest/gtest.h>

#include "aerial/error.h"

namespace aerial::reference {
namespace {

const AtmosphereParameters kEarth = AtmosphereParameters::Earth();

// Out-of-range inputs name the offending field; rounding-sized excursions are accepted.
TEST(Reference, RejectsInvalidInputs) {
  Reference ref(kEarth);
  const double R = kEarth.bottom_radius_m, Rt = kEarth.top_radius_m;
  EXPECT_THROW(ref.DistanceToBoundary(R - 1.0, 0.5), Error);
  EXPECT_THROW(ref.DistanceToBoundary(Rt + 1.0, 0.5), Error);
  EXPECT_THROW(ref.DistanceToBoundary(NAN, 0.5), Error);
  EXPECT_THROW(ref.DistanceToBoundary(R, 1.01), Error);
  EXPECT_THROW(ref.Transmittance(R, 0.5, -1.0), Error);
  EXPECT_THROW(ref.ComputeSingleScattering(R, 0.5, -1.5, 0.0), Error);
  EXPECT_THROW(ref.ComputeSingleScattering(R, 0.5, 0.5, NAN), Error);
  EXPECT_THROW(ref.ComputeRadiance(R, 0.5, 0.5, 0.5, 0), Error);
  EXPECT_THROW(ref.ComputeSkyIrradiance(R, 0.5, 0), Error);
  EXPECT_THROW(ref.ComputeSkyIrradiance(R, 0.5, 2, {0, 1, 0}), Error);
  EXPECT_THROW(ref.ComputeTiltedSkyIrradiance(R, 0.5, -1.5, 0.5, 2), Error);
  EXPECT_THROW(Reference::RayleighPhase(2.0), Error);
  try {
    ref.ComputeDirectIrradiance(R, 1.5);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "mu_s");
  }
  EXPECT_NO_THROW(ref.DistanceToBoundary(R - 1e-4, 1.0 + 1e-13));
  AtmosphereParameters bad = kEarth;
  bad.top_radius_m = bad.bottom_radius_m;
  EXPECT_THROW(Reference{bad}, Error);
}

// Boundary distances: the ground from above along the nadir, the top along the zenith; the
// transmittance over a distance is clamped to the boundary.
TEST(Reference, BoundariesAndTransmittance) {
  Reference ref(kEarth);
  const double R = kEarth.bottom_radius_m, Rt = kEarth.top_radius_m;
  EXPECT_TRUE(ref.RayIntersectsGround(R + 1000.0, -1.0));
  EXPECT_NEAR(ref.DistanceToBoundary(R + 1000.0, -1.0), 1000.0, 1e-6);
  EXPECT_FALSE(ref.RayIntersectsGround(R + 1000.0, 0.0));
  EXPECT_NEAR(ref.DistanceToBoundary(R, 1.0), Rt - R, 1e-6);
  Spectrum far = ref.Transmittance(R, 1.0, 1e9), boundary = ref.TransmittanceToBoundary(R, 1.0);
  Spectrum near = ref.Transmittance(R, 1.0, 1000.0);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(far[c], boundary[c]);
    EXPECT_GT(near[c], boundary[c]);
    EXPECT_LT(boundary[c], 1.0);
  }
}

// ComputeRadiance with one order is the deterministic single scattering times the phase
// functions, without Monte Carlo error; more orders add positive radiance with an error.
TEST(Reference, RadianceOrderOneIsSingleScatteringWithPhase) {
  Reference ref(kEarth);
  const double R = kEarth.bottom_radius_m, mu = 0.5, mu_s = 0.8, nu = 0.3;
  SingleScattering s = ref.ComputeSingleScattering(R, mu, mu_s, nu);
  Estimate one = ref.ComputeRadiance(R, mu, mu_s, nu, 1);
  Estimate two = ref.ComputeRadiance(R, mu, mu_s, nu, 2, INFINITY, {2048, 1, 0});
  for (int c = 0; c < 3; ++c) {
    EXPECT_DOUBLE_EQ(one.value[c], s.rayleigh[c] * Reference::RayleighPhase(nu) + s.mie[c] * ref.MiePhase(nu));
    EXPECT_EQ(one.std_error[c], 0.0);
    EXPECT_GT(two.value[c], one.value[c] + 4.0 * two.std_error[c]);
  }
}

// An infeasible nu (farther from mu mu_s than sqrt((1 - mu^2)(1 - mu_s^2))) is clamped to the
// nearest feasible value: looking at the zenith, nu must equal mu_s.
TEST(Reference, ClampsNuToTheFeasibleRange) {
  Reference ref(kEarth);
  const double R = kEarth.bottom_radius_m;
  SingleScattering a = ref.ComputeSingleScattering(R, 1.0, 0.6, 0.9);
  SingleScattering b = ref.ComputeSingleScattering(R, 1.0, 0.6, 0.6);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(a.rayleigh[c], b.rayleigh[c]);
}

// The default sample count meets the brief's accuracy: a standard error <= 0.2% of the radiance
// of orders 1..4 for a camera on the ground, view zenith 60, sun zenith 30 degrees (measured
// ~0.1%; ~0.7 s on 2 cores).
TEST(Reference, DefaultSamplesGiveTwoPerMilleAtDaylight) {
  Reference ref(kEarth);
  const double mu = 0.5, mu_s = std::sqrt(3.0) / 2.0;
  const double nu = mu * mu_s - std::sqrt((1.0 - mu * mu) * (1.0 - mu_s * mu_s));  // sun behind.
  Estimate e = ref.ComputeRadiance(kEarth.bottom_radius_m, mu, mu_s, nu, 4);
  for (int c = 0; c < 3; ++c) EXPECT_LT(e.std_error[c], 2e-3 * e.value[c]) << c;
}

}  // namespace
}  // namespace aerial::reference
