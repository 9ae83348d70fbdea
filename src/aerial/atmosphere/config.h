#pragma once
// Atmosphere parameters from TOML text, and back to it. LoadAtmosphereFile and Validate, the
// public calls, are declared in aerial/atmosphere.h.
//
// Every key is optional: values start from AtmosphereParameters::Earth() and the file overrides
// them. Keys carry their SI unit in their name (bottom_radius_m, exp_scale_per_m). Spectra are
// arrays of 3 values, one per entry of wavelengths_nm. A density profile is an array of 1 or 2
// layers {width_m, exp_term, exp_scale_per_m, linear_term_per_m, constant_term}; a missing layer
// key is 0, and one layer applies at every altitude (it becomes layers[1], layers[0] stays zero,
// DensityProfile's "width 0" convention). A given density replaces the whole default profile.
// max_sun_zenith_deg is stored as mu_s_min = cos(max_sun_zenith_deg).
//
// Nothing is silently ignored: an unknown key (a typo), a wrong type or a wrong array length
// throws aerial::Error naming the dotted key ("mie.density[0].exp_term"), the value and what is
// allowed, with "file:line:column" as where.
#include <filesystem>
#include <string>
#include <string_view>

#include "aerial/atmosphere.h"

namespace aerial {

// Parses and validates TOML text; where names the source in messages (usually the path).
AtmosphereParameters ParseAtmosphereToml(std::string_view text, const std::string& where);

// Writes every field in the format above. Doubles are printed in their shortest form that reads
// back to the same double, so ParseAtmosphereToml(ToToml(p)) == p field by field. One caveat:
// mu_s_min is written as an angle, and a mu_s_min that no double angle maps to (only possible
// when set in code, never from a file) reads back within a few ulps.
std::string ToToml(const AtmosphereParameters& atmosphere);

// cos(degrees) for degrees in [90, 180], exact at 90, 120 and 180 (so "120.0" gives exactly the
// -0.5 of Earth()), and the inverse; ToToml and the parser share them.
double MuSMinFromMaxSunZenithDeg(double degrees);
double MaxSunZenithDegFromMuSMin(double mu_s_min);

// The wavelengths an atmosphere may be given at: where every spectrum the spectral precompute
// reads (spectrum/spectral_data.h) is tabulated. Outside it the solar spectrum reads 0, and the
// spectral sun would be black.
inline constexpr double kMinWavelengthNm = 360.0, kMaxWavelengthNm = 830.0;

}  // namespace aerial
