#pragma once
// Colour from a few samples of sky light: the XYZ of a spectrum as a linear map of its values at N
// wavelengths, fitted by least squares to the CIE 1931 integral over the spectra sky light takes.
//
// The midpoint rule at 12 wavelengths over 360-830 nm (39 nm bins) put the sky's chromaticity u'v'
// 0.001-0.003 off the integral, a near-constant shift: the solar spectrum has structure finer than
// the bins, and the colour-matching functions' lobes are 40-100 nm wide. But sky light is the solar
// spectrum E times a smooth factor: each light path scales it by its scattering coefficients (a
// power of lambda) and its transmittance, the exponential of Rayleigh's, the aerosols' and the
// ozone's optical depths. Over a family of such spectra, the best linear map from N values to XYZ
// is found by least squares against the integral (1 nm, trapezoid, the data read linearly between
// their tabulated wavelengths): per channel, min sum_s (w . L_s - XYZ_s)^2 / Y_s^2, each spectrum
// weighted by its own luminance so that all count alike in chromaticity.
//
// The family (SkyLightPaths), for each combination of:
//  - scattering: (lambda / 550 nm)^(-4a), a = 0, 1, 2 (the sun's direct light, light scattered once
//    and twice by the air);
//  - Rayleigh optical depth at 550 nm 0, 0.1, 0.3, 0.8, 2, 4 (Earth: 0.1 at the zenith, 4 along the
//    horizon) as (lambda / 550)^-4;
//  - ozone optical depth at 600 nm 0, 0.1, 0.4, 1, 2 (Earth: 0.04 at the zenith, 1-2 through the
//    ozone layer along the horizon, which sets the blue hour's colour) as the cross-section;
//  - aerosols: none, or optical depth 0.5 with an Angstrom exponent 1 or 2;
//  - a reflectance linear in lambda, 1 + s (lambda - 560) / 240, s = -0.5, 0, 0.5 (a ground albedo).
// 810 spectra. They are not any atmosphere's: a linear map fitted over them holds for any mixture
// of them (its error in XYZ is the mixture of theirs), which is what multiple scattering makes.
#include <functional>
#include <vector>

#include "aerial/atmosphere.h"

namespace aerial::spectrum {

// One spectrum of the family, as its factor on the solar spectrum.
struct SkyLightPath {
  double scattering_power = 0.0;  // a above
  double rayleigh_depth = 0.0, ozone_depth = 0.0, aerosol_depth = 0.0, aerosol_exponent = 0.0;
  double reflectance_slope = 0.0;  // s above

  double Factor(double nm) const;
  // E(lambda) times Factor(lambda), E the solar spectrum (spectral_data.h).
  double Radiance(double nm) const;
};

std::vector<SkyLightPath> SkyLightPaths();

// The XYZ (colour.h's units) of a spectrum over 360-830 nm, by the trapezoidal rule every 1 nm.
Spectrum CieIntegral(const std::function<double(double)>& spectrum);

// Per wavelength, its values' XYZ weights: XYZ = sum_j weights[j] * value_j.
std::vector<Spectrum> FitSkyLightConversion(const std::vector<double>& wavelengths_nm);

}  // namespace aerial::spectrum
