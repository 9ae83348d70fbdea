#pragma once
// Atmosphere parameters from TOML files (examples/atmospheres/*.toml), and back.
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

#include "aerial/atmosphere/parameters.h"

namespace aerial {

// Reads and validates a file. A missing or unreadable file throws an Error naming the path.
AtmosphereParameters LoadAtmosphereFile(const std::filesystem::path& path);

// Parses and validates TOML text; where names the source in messages (usually the path).
AtmosphereParameters ParseAtmosphereToml(std::string_view text, const std::string& where);

// Checks physical ranges, on each value as the shaders receive it (rounded to float): bottom
// radius in [1000, 100000] km and thickness top - bottom in [1, 1000] km; wavelengths in
// [300, 1000] nm; solar irradiance in [0, 1000] W/m^2/nm; sun angular radius in [1e-4, 0.1] rad;
// scattering, extinction and absorption in [0, 0.1] m^-1, with Mie extinction >= Mie scattering;
// Mie g in (-1, 1); albedo in [0, 1]; mu_s_min in [-1, 0] (max_sun_zenith_deg in [90, 180]);
// density layers with width >= 0 and each term within +-1e6 at every altitude. Why each range:
// config.cpp, next to the constants. Errors name fields by their TOML keys. where is copied into
// the Error.
void Validate(const AtmosphereParameters& atmosphere, const std::string& where = "");

// Writes every field in the format above. Doubles are printed in their shortest form that reads
// back to the same double, so ParseAtmosphereToml(ToToml(p)) == p field by field. One caveat:
// mu_s_min is written as an angle, and a mu_s_min that no double angle maps to (only possible
// when set in code, never from a file) reads back within a few ulps.
std::string ToToml(const AtmosphereParameters& atmosphere);

// cos(degrees) for degrees in [90, 180], exact at 90, 120 and 180 (so "120.0" gives exactly the
// -0.5 of Earth()), and the inverse; ToToml and the parser share them.
double MuSMinFromMaxSunZenithDeg(double degrees);
double MaxSunZenithDegFromMuSMin(double mu_s_min);

}  // namespace aerial
