#pragma once
// An atmosphere at any visible wavelength, extended from the three wavelengths its parameters
// give, each constituent by the spectral law it follows:
//  - Rayleigh scattering by lambda^-4 (Bruneton 2017's fit; Bucholtz 1995 adds a small
//    dispersion term that the three-wavelength Earth does not carry), its factor fitted in log;
//  - Mie scattering and extinction by the Angstrom law beta * lambda^-alpha, fitted in log-log
//    (alpha = 0 for Bruneton's Earth);
//  - ozone absorption as the measured cross-section (spectral_data.h) times a number density
//    fitted by least squares (5.374e18 m^-3 at the peak for Earth's 300 DU);
//  - the solar irradiance as the ASTM G-173 spectrum times a least-squares factor (1 for Earth,
//    1 / d^2 for a planet d AU from the Sun);
//  - the ground albedo linearly between the given wavelengths, constant beyond them.
// For the built-in Earth this reproduces Bruneton 2017's spectral demo at every wavelength.
#include <array>
#include <vector>

#include "aerial/atmosphere.h"
#include "aerial/spectrum/spectral_sampling.h"

namespace aerial::spectrum {

class SpectralAtmosphere {
 public:
  explicit SpectralAtmosphere(const AtmosphereParameters& three_wavelengths);

  // The atmosphere at three other wavelengths (one precompute group).
  AtmosphereParameters At(const std::array<double, 3>& wavelengths_nm) const;
  // At every group of a sampling's wavelengths.
  std::vector<AtmosphereParameters> AtGroups(const SpectralSampling& sampling) const;

  double SolarIrradiance(double nm) const;
  double RayleighScattering(double nm) const;
  double MieScattering(double nm) const;
  double MieExtinction(double nm) const;
  double AbsorptionExtinction(double nm) const;
  double GroundAlbedo(double nm) const;
  // A reflectance given at the atmosphere's three wavelengths (a ground or surface albedo), as a
  // spectrum: linear between them, constant beyond.
  double ReflectanceAt(const Spectrum& at_three_wavelengths, double nm) const;
  // The reflectance spectrum of that form (its values at the three wavelengths) that does to the
  // sun's light what a linear sRGB albedo does to its colour: LinearSrgb(E rho) = albedo *
  // LinearSrgb(E), channel by channel, E the solar irradiance over `sampling`. A renderer that
  // multiplies linear sRGB light by an albedo treats the albedo so, exactly under sunlight.
  Spectrum ReflectanceForSunlight(const Spectrum& linear_srgb_albedo, const SpectralSampling& sampling) const;

 private:
  struct PowerLaw {
    double factor = 0.0, exponent = 0.0;  // factor * (lambda / 1 um)^exponent
    double At(double nm) const;
  };
  static PowerLaw FitPowerLaw(const Spectrum& wavelengths_nm, const Spectrum& values, bool fixed_rayleigh);

  AtmosphereParameters base_;
  PowerLaw rayleigh_, mie_scattering_, mie_extinction_;
  double ozone_density_ = 0.0, solar_scale_ = 0.0;
};

// The three channels the render-time shaders work in when the tables are spectral: linear sRGB.
// The sun's irradiance is the solar spectrum's colour; each coefficient is the sunlight-weighted
// mean of its spectrum per channel, LinearSrgb(E * sigma) / LinearSrgb(E), which the optically
// thin limit of single scattering makes exact; the transmittance table is computed from them too
// (spectral_precompute.h says why and docs/colour.md what it costs).
AtmosphereParameters LinearSrgbAtmosphere(const SpectralAtmosphere& atmosphere,
                                          const AtmosphereParameters& base,
                                          const SpectralSampling& sampling);

}  // namespace aerial::spectrum
