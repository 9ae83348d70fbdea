#include "aerial/spectrum/spectral_atmosphere.h"

#include <algorithm>
#include <cmath>

#include "aerial/spectrum/colour.h"
#include "aerial/spectrum/spectral_data.h"

namespace aerial::spectrum {
namespace {

// The factor s minimizing sum (values - s * shape)^2 over the three wavelengths.
double FitScale(const Spectrum& wavelengths_nm, const Spectrum& values, const TabulatedSpectrum& shape) {
  double numerator = 0.0, denominator = 0.0;
  for (int i = 0; i < 3; ++i) {
    double s = shape.At(wavelengths_nm[i]);
    numerator += values[i] * s;
    denominator += s * s;
  }
  return denominator > 0.0 ? numerator / denominator : 0.0;
}

}  // namespace

double SpectralAtmosphere::PowerLaw::At(double nm) const {
  return factor == 0.0 ? 0.0 : factor * std::pow(nm * 1e-3, exponent);
}

// Least squares in log space; a constituent with a zero value anywhere is taken as absent.
SpectralAtmosphere::PowerLaw SpectralAtmosphere::FitPowerLaw(const Spectrum& wavelengths_nm,
                                                             const Spectrum& values, bool fixed_rayleigh) {
  if (std::any_of(values.begin(), values.end(), [](double v) { return v <= 0.0; })) return {};
  double mean_x = 0.0, mean_y = 0.0;
  for (int i = 0; i < 3; ++i) {
    mean_x += std::log(wavelengths_nm[i] * 1e-3) / 3.0;
    mean_y += std::log(values[i]) / 3.0;
  }
  double exponent = -4.0;
  if (!fixed_rayleigh) {
    double sxy = 0.0, sxx = 0.0;
    for (int i = 0; i < 3; ++i) {
      double dx = std::log(wavelengths_nm[i] * 1e-3) - mean_x;
      sxy += dx * (std::log(values[i]) - mean_y);
      sxx += dx * dx;
    }
    exponent = sxx > 0.0 ? sxy / sxx : 0.0;
  }
  return {std::exp(mean_y - exponent * mean_x), exponent};
}

SpectralAtmosphere::SpectralAtmosphere(const AtmosphereParameters& a)
    : base_(a),
      rayleigh_(FitPowerLaw(a.wavelengths_nm, a.rayleigh_scattering, true)),
      mie_scattering_(FitPowerLaw(a.wavelengths_nm, a.mie_scattering, false)),
      mie_extinction_(FitPowerLaw(a.wavelengths_nm, a.mie_extinction, false)),
      ozone_density_(FitScale(a.wavelengths_nm, a.absorption_extinction, OzoneCrossSection())),
      solar_scale_(FitScale(a.wavelengths_nm, a.solar_irradiance, spectrum::SolarIrradiance())) {}

double SpectralAtmosphere::SolarIrradiance(double nm) const {
  return solar_scale_ * spectrum::SolarIrradiance().At(nm);
}
double SpectralAtmosphere::RayleighScattering(double nm) const { return rayleigh_.At(nm); }
double SpectralAtmosphere::MieScattering(double nm) const { return mie_scattering_.At(nm); }
// Never below the scattering, as AtmosphereParameters requires.
double SpectralAtmosphere::MieExtinction(double nm) const {
  return std::max(mie_extinction_.At(nm), MieScattering(nm));
}
double SpectralAtmosphere::AbsorptionExtinction(double nm) const {
  return ozone_density_ * OzoneCrossSection().At(nm);
}

double SpectralAtmosphere::GroundAlbedo(double nm) const { return ReflectanceAt(base_.ground_albedo, nm); }

double SpectralAtmosphere::ReflectanceAt(const Spectrum& at_three_wavelengths, double nm) const {
  std::array<int, 3> order = {0, 1, 2};
  std::sort(order.begin(), order.end(),
            [&](int i, int j) { return base_.wavelengths_nm[i] < base_.wavelengths_nm[j]; });
  TabulatedSpectrum albedo;
  for (int i : order) {
    albedo.wavelengths_nm.push_back(base_.wavelengths_nm[i]);
    albedo.values.push_back(at_three_wavelengths[i]);
  }
  nm = std::clamp(nm, albedo.wavelengths_nm.front(), albedo.wavelengths_nm.back());
  return albedo.At(nm);
}

Spectrum SpectralAtmosphere::ReflectanceForSunlight(const Spectrum& linear_srgb_albedo,
                                                    const SpectralSampling& sampling) const {
  std::vector<double> sun = sampling.Sample([&](double nm) { return SolarIrradiance(nm); });
  // reflected[c][k]: channel c of the sunlight reflected by the spectrum that is 1 at wavelength
  // k of the three, 0 at the others (linear in those three values).
  Matrix3 reflected{};
  for (int k = 0; k < 3; ++k) {
    Spectrum unit{};
    unit[k] = 1.0;
    std::vector<double> light = sun;
    for (size_t i = 0; i < light.size(); ++i) light[i] *= ReflectanceAt(unit, sampling.wavelengths_nm()[i]);
    Spectrum colour = sampling.LinearSrgb(light);
    for (int c = 0; c < 3; ++c) reflected[c][k] = colour[c];
  }
  Spectrum wanted = sampling.LinearSrgb(sun);
  for (int c = 0; c < 3; ++c) wanted[c] *= linear_srgb_albedo[c];
  return Multiply(Inverse(reflected), wanted);
}

std::vector<AtmosphereParameters> SpectralAtmosphere::AtGroups(const SpectralSampling& sampling) const {
  std::vector<AtmosphereParameters> groups;
  for (int g = 0; g < sampling.groups(); ++g) groups.push_back(At(sampling.Group(g)));
  return groups;
}

AtmosphereParameters SpectralAtmosphere::At(const std::array<double, 3>& wavelengths_nm) const {
  AtmosphereParameters a = base_;
  for (int i = 0; i < 3; ++i) {
    double nm = wavelengths_nm[i];
    a.wavelengths_nm[i] = nm;
    a.solar_irradiance[i] = SolarIrradiance(nm);
    a.rayleigh_scattering[i] = RayleighScattering(nm);
    a.mie_scattering[i] = MieScattering(nm);
    a.mie_extinction[i] = MieExtinction(nm);
    a.absorption_extinction[i] = AbsorptionExtinction(nm);
    a.ground_albedo[i] = GroundAlbedo(nm);
  }
  return a;
}

AtmosphereParameters LinearSrgbAtmosphere(const SpectralAtmosphere& atmosphere,
                                          const AtmosphereParameters& base,
                                          const SpectralSampling& sampling) {
  std::vector<double> sun = sampling.Sample([&](double nm) { return atmosphere.SolarIrradiance(nm); });
  Spectrum sun_colour = sampling.LinearSrgb(sun);
  auto weighted = [&](double (SpectralAtmosphere::*coefficient)(double) const) {
    std::vector<double> values = sun;
    for (size_t i = 0; i < values.size(); ++i)
      values[i] *= (atmosphere.*coefficient)(sampling.wavelengths_nm()[i]);
    Spectrum colour = sampling.LinearSrgb(values);
    Spectrum mean{};
    for (int c = 0; c < 3; ++c) mean[c] = std::max(colour[c] / sun_colour[c], 0.0);
    return mean;
  };
  AtmosphereParameters a = base;
  a.solar_irradiance = sun_colour;
  a.rayleigh_scattering = weighted(&SpectralAtmosphere::RayleighScattering);
  a.mie_scattering = weighted(&SpectralAtmosphere::MieScattering);
  a.mie_extinction = weighted(&SpectralAtmosphere::MieExtinction);
  a.absorption_extinction = weighted(&SpectralAtmosphere::AbsorptionExtinction);
  a.ground_albedo = weighted(&SpectralAtmosphere::GroundAlbedo);
  return a;
}

}  // namespace aerial::spectrum
