#pragma once
// The measured spectra the spectral precompute needs, from src/aerial/spectrum/data/ (each file
// names its source and units):
//  - the CIE 1931 2-degree colour-matching functions, 360-830 nm every 5 nm;
//  - the extraterrestrial solar irradiance (ASTM G-173 ETR), W m^-2 nm^-1, 10 nm bins;
//  - the ozone absorption cross-section at 233 K (Serdyuchenko et al. 2014), m^2, 10 nm bins.
#include <array>

#include "aerial/spectrum/tabulated_spectrum.h"

namespace aerial::spectrum {

// x-bar, y-bar, z-bar.
const std::array<TabulatedSpectrum, 3>& Cie1931ColourMatching();
const TabulatedSpectrum& SolarIrradiance();
const TabulatedSpectrum& OzoneCrossSection();

// The integral of y-bar over 360-830 nm, in nm (106.857 with the 5 nm table): luminance is
// 683 lm/W times the integral of y-bar times the spectral radiance.
double YBarIntegralNm();

// Dobson unit, molecules m^-2 (WMO); Bruneton 2017's Earth has 300 DU spread over its 15 km tent.
inline constexpr double kDobsonUnit = 2.687e20;
// Maximum luminous efficacy of radiation, lm/W at 555 nm (CIE; the SI definition of the candela).
inline constexpr double kMaxLuminousEfficacy = 683.0;

}  // namespace aerial::spectrum
