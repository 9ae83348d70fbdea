#include "aerial/spectrum/spectral_sunlight.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aerial::spectrum {
namespace {

// Column densities along a path (m of air at density 1): Rayleigh, Mie, ozone.
struct Columns {
  double rayleigh, mie, ozone;
};

// A path's channel optical depths in the render-time atmosphere, as its transmittance table
// holds them: each channel's coefficients times the columns.
Spectrum ChannelOpticalDepth(const AtmosphereParameters& srgb, const Columns& n) {
  Spectrum tau{};
  for (int c = 0; c < 3; ++c)
    tau[c] = srgb.rayleigh_scattering[c] * n.rayleigh + srgb.mie_extinction[c] * n.mie +
             srgb.absorption_extinction[c] * n.ozone;
  return tau;
}

// The light after the path, wavelength by wavelength, in each channel's units of LinearSrgb(E beta):
// what the CPU reference computes, from the spectral atmosphere directly.
Spectrum ExpectedSunlight(const SpectralAtmosphere& atmosphere, const SpectralSampling& sampling,
                          double (SpectralAtmosphere::*beta)(double) const, const Columns& n) {
  auto coefficient = [&](double nm) { return beta ? (atmosphere.*beta)(nm) : 1.0; };
  std::vector<double> attenuated = sampling.Sample([&](double nm) {
    double tau = atmosphere.RayleighScattering(nm) * n.rayleigh + atmosphere.MieExtinction(nm) * n.mie +
                 atmosphere.AbsorptionExtinction(nm) * n.ozone;
    return atmosphere.SolarIrradiance(nm) * coefficient(nm) * std::exp(-tau);
  });
  std::vector<double> unattenuated =
      sampling.Sample([&](double nm) { return atmosphere.SolarIrradiance(nm) * coefficient(nm); });
  Spectrum light = sampling.LinearSrgb(attenuated), unit = sampling.LinearSrgb(unattenuated);
  for (int c = 0; c < 3; ++c) light[c] /= unit[c];
  return light;
}

// Paths from the zenith (8 km of Rayleigh's scale height, 1.2 km of Mie's, 15 km of the ozone
// layer's thickness) to 40 air masses (the sun on the horizon), and 10 km along the ground.
const Columns kPaths[] = {{8000.0, 1200.0, 15000.0}, {40 * 8000.0, 40 * 1200.0, 40 * 15000.0},
                          {10000.0, 10000.0, 0.0}, {3 * 8000.0, 5 * 1200.0, 2 * 15000.0}};

void ExpectReadsBackEveryWavelength(const AtmosphereParameters& base) {
  SpectralAtmosphere atmosphere(base);
  const SpectralSampling sampling = SpectralSampling::ForTables(12);
  AtmosphereParameters srgb = LinearSrgbAtmosphere(atmosphere, base, sampling);
  SpectralSunlight sunlight = MakeSpectralSunlight(atmosphere, srgb, sampling);
  ASSERT_EQ(sunlight.exponents.size(), 12u);
  for (const Columns& n : kPaths) {
    Spectrum tau = ChannelOpticalDepth(srgb, n);
    Spectrum rayleigh = PathSunlight(sunlight, sunlight.rayleigh_shares, tau);
    Spectrum mie = PathSunlight(sunlight, sunlight.mie_shares, tau);
    Spectrum direct = PathSunlight(sunlight, sunlight.direct_shares, tau);
    Spectrum expected_rayleigh = ExpectedSunlight(atmosphere, sampling, &SpectralAtmosphere::RayleighScattering, n);
    Spectrum expected_mie = ExpectedSunlight(atmosphere, sampling, &SpectralAtmosphere::MieScattering, n);
    Spectrum expected_direct = ExpectedSunlight(atmosphere, sampling, nullptr, n);
    // Algebra in double: the fit is exact, and 1e-9 leaves room for its conditioning (A's
    // condition number is a few hundred, squared by the normal equations).
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(rayleigh[c], expected_rayleigh[c], 1e-9 * std::abs(expected_rayleigh[c]) + 1e-15) << c;
      EXPECT_NEAR(mie[c], expected_mie[c], 1e-9 * std::abs(expected_mie[c]) + 1e-15) << c;
      EXPECT_NEAR(direct[c], expected_direct[c], 1e-9 * std::abs(expected_direct[c]) + 1e-15) << c;
    }
  }
}

// Every wavelength's transmittance recovered from the three channels' optical depths: the light
// after each path is the spectral sum the reference makes.
TEST(SpectralSunlight, ReadsBackEveryWavelengthsTransmittance) {
  ExpectReadsBackEveryWavelength(AtmosphereParameters::Earth());
}

// Without ozone two constituents are left, and their column densities are still determined.
TEST(SpectralSunlight, ReadsBackWithoutOzone) {
  AtmosphereParameters no_ozone = AtmosphereParameters::Earth();
  no_ozone.absorption_extinction = {0.0, 0.0, 0.0};
  ExpectReadsBackEveryWavelength(no_ozone);
}

// What the three-channel product misses along the low sun's path (40 air masses), which the sum
// corrects: more than 1% in every channel of the light Rayleigh scatters, so the sum is not the
// product under another name.
TEST(SpectralSunlight, DiffersFromTheChannelsTransmittanceAtTheLowSun) {
  AtmosphereParameters base = AtmosphereParameters::Earth();
  SpectralAtmosphere atmosphere(base);
  const SpectralSampling sampling = SpectralSampling::ForTables(12);
  AtmosphereParameters srgb = LinearSrgbAtmosphere(atmosphere, base, sampling);
  Spectrum tau = ChannelOpticalDepth(srgb, kPaths[1]);
  Spectrum expected = ExpectedSunlight(atmosphere, sampling, &SpectralAtmosphere::RayleighScattering, kPaths[1]);
  for (int c = 0; c < 3; ++c) EXPECT_GT(std::abs(std::exp(-tau[c]) / expected[c] - 1.0), 0.01) << c;
}

// Two constituents with one spectrum (Mie following lambda^-4 as Rayleigh does) leave their
// column densities undetermined: no terms, and the channels' transmittance is used as it is.
TEST(SpectralSunlight, NoTermsWhereTheColumnsAreNotDetermined) {
  AtmosphereParameters base = AtmosphereParameters::Earth();
  for (int c = 0; c < 3; ++c) {
    base.mie_scattering[c] = 0.5 * base.rayleigh_scattering[c];
    base.mie_extinction[c] = 0.5 * base.rayleigh_scattering[c];
  }
  SpectralAtmosphere atmosphere(base);
  const SpectralSampling sampling = SpectralSampling::ForTables(12);
  EXPECT_TRUE(MakeSpectralSunlight(atmosphere, LinearSrgbAtmosphere(atmosphere, base, sampling), sampling)
                  .exponents.empty());
}

}  // namespace
}  // namespace aerial::spectrum
