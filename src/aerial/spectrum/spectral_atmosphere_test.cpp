#include "aerial/spectrum/spectral_atmosphere.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aerial::spectrum {
namespace {

void ExpectRelativelyNear(const Spectrum& a, const Spectrum& b, double tolerance, const char* what) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tolerance * std::abs(b[i])) << what << " " << i;
}

// Extended from Earth's three wavelengths and read back at them, the atmosphere is Earth again:
// Rayleigh's lambda^-4 and Mie's flat law exactly, ozone and the sun to the 4 digits Earth keeps.
TEST(SpectralAtmosphere, ReproducesItsThreeWavelengths) {
  AtmosphereParameters earth = AtmosphereParameters::Earth();
  AtmosphereParameters again = SpectralAtmosphere(earth).At(earth.wavelengths_nm);
  ExpectRelativelyNear(again.rayleigh_scattering, earth.rayleigh_scattering, 1e-12, "rayleigh");
  ExpectRelativelyNear(again.mie_scattering, earth.mie_scattering, 1e-12, "mie scattering");
  ExpectRelativelyNear(again.mie_extinction, earth.mie_extinction, 1e-12, "mie extinction");
  ExpectRelativelyNear(again.absorption_extinction, earth.absorption_extinction, 1e-3, "ozone");
  ExpectRelativelyNear(again.solar_irradiance, earth.solar_irradiance, 1e-3, "sun");
  ExpectRelativelyNear(again.ground_albedo, earth.ground_albedo, 1e-12, "albedo");
}

// Bruneton 2017's Rayleigh fit at 400 nm: 1.24062e-6 / 0.4^4 m^-1.
TEST(SpectralAtmosphere, ExtendsRayleighAsLambdaToTheMinusFour) {
  SpectralAtmosphere earth(AtmosphereParameters::Earth());
  EXPECT_NEAR(earth.RayleighScattering(400.0) / (1.24062e-6 / std::pow(0.4, 4.0)), 1.0, 1e-9);
}

// In linear sRGB, each coefficient times the sun's colour is the colour of the sunlight the
// coefficient weights: single scattering in thin air is then exact in every channel.
TEST(SpectralAtmosphere, LinearSrgbCoefficientsWeightTheSunlight) {
  AtmosphereParameters earth = AtmosphereParameters::Earth();
  SpectralAtmosphere spectral(earth);
  const SpectralSampling sampling = SpectralSampling::ForTables(12);
  AtmosphereParameters srgb = LinearSrgbAtmosphere(spectral, earth, sampling);
  std::vector<double> sunlit_rayleigh = sampling.Sample(
      [&](double nm) { return spectral.SolarIrradiance(nm) * spectral.RayleighScattering(nm); });
  Spectrum expected = sampling.LinearSrgb(sunlit_rayleigh);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(srgb.rayleigh_scattering[c] * srgb.solar_irradiance[c], expected[c], 1e-12 * expected[c]);
  // Blue scatters most, and the sun is near white (each channel within 20% of green).
  EXPECT_GT(srgb.rayleigh_scattering[2], srgb.rayleigh_scattering[1]);
  EXPECT_GT(srgb.rayleigh_scattering[1], srgb.rayleigh_scattering[0]);
  for (double c : srgb.solar_irradiance) EXPECT_NEAR(c / srgb.solar_irradiance[1], 1.0, 0.2);
}

// A surface's three-channel albedo as a spectrum: its own values at 680, 550 and 440 nm, the mean
// of two neighbours half-way between them, and the end values beyond them.
TEST(SpectralAtmosphere, ReflectanceIsLinearBetweenTheThreeWavelengths) {
  SpectralAtmosphere earth(AtmosphereParameters::Earth());
  const Spectrum albedo = {0.3, 0.5, 0.1};  // at 680, 550, 440 nm
  EXPECT_DOUBLE_EQ(earth.ReflectanceAt(albedo, 680.0), 0.3);
  EXPECT_DOUBLE_EQ(earth.ReflectanceAt(albedo, 550.0), 0.5);
  EXPECT_DOUBLE_EQ(earth.ReflectanceAt(albedo, 440.0), 0.1);
  EXPECT_NEAR(earth.ReflectanceAt(albedo, 615.0), 0.4, 1e-12);
  EXPECT_NEAR(earth.ReflectanceAt(albedo, 495.0), 0.3, 1e-12);
  EXPECT_DOUBLE_EQ(earth.ReflectanceAt(albedo, 380.0), 0.1);
  EXPECT_DOUBLE_EQ(earth.ReflectanceAt(albedo, 800.0), 0.3);
}

// The reflectance for sunlight does to the sun's light what the albedo does to its colour,
// channel by channel (the definition, checked from the spectra: to rounding), for a green albedo
// as saturated as a lawn's; a grey albedo is a flat spectrum of the same value.
TEST(SpectralAtmosphere, ReflectanceForSunlightReflectsItAsTheAlbedoDoes) {
  SpectralAtmosphere earth(AtmosphereParameters::Earth());
  const SpectralSampling sampling = SpectralSampling::ForTables(12);
  std::vector<double> sun = sampling.Sample([&](double nm) { return earth.SolarIrradiance(nm); });
  const Spectrum green = {0.08, 0.25, 0.04};
  Spectrum rho = earth.ReflectanceForSunlight(green, sampling);
  std::vector<double> reflected = sun;
  for (size_t i = 0; i < sun.size(); ++i) reflected[i] *= earth.ReflectanceAt(rho, sampling.wavelengths_nm()[i]);
  Spectrum colour = sampling.LinearSrgb(reflected), white = sampling.LinearSrgb(sun);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(colour[c], green[c] * white[c], 1e-12 * white[c]) << c;
  // Not the albedo's own values at the three wavelengths: the sRGB channels overlap in wavelength.
  EXPECT_GT(std::abs(rho[1] / green[1] - 1.0), 0.05);
  Spectrum grey = earth.ReflectanceForSunlight({0.3, 0.3, 0.3}, sampling);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(grey[k], 0.3, 1e-12) << k;
}

}  // namespace
}  // namespace aerial::spectrum
