#pragma once
// The physical description of an atmosphere, in SI units (meters, m^-1, W/m^2/nm), following the
// model of Bruneton 2017 (model.h): Rayleigh and Mie scattering plus an absorbing layer (ozone),
// each with a density profile of up to two layers. Three wavelengths are rendered ("radiance mode").
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>

namespace aerial {

using Spectrum = std::array<double, 3>;

// density(h) = clamp(exp_term * exp(exp_scale_per_m * h) + linear_term_per_m * h + constant_term,
//                    0, 1), h = altitude in meters (Bruneton 2017, DensityProfileLayer).
struct DensityProfileLayer {
  double width_m = 0.0;
  double exp_term = 0.0;
  double exp_scale_per_m = 0.0;
  double linear_term_per_m = 0.0;
  double constant_term = 0.0;

  double Density(double altitude_m) const;
};

// layers[0] applies below layers[0].width_m, layers[1] above it (width 0: layers[1] everywhere).
struct DensityProfile {
  std::array<DensityProfileLayer, 2> layers;

  double Density(double altitude_m) const;
};

struct AtmosphereParameters {
  std::string name = "earth";
  Spectrum wavelengths_nm{};
  Spectrum solar_irradiance{};       // W/m^2/nm at the top of the atmosphere.
  double sun_angular_radius_rad = 0.0;
  double bottom_radius_m = 0.0;      // planet radius.
  double top_radius_m = 0.0;         // atmosphere top.
  DensityProfile rayleigh_density;
  Spectrum rayleigh_scattering{};    // m^-1 at density 1; Rayleigh does not absorb.
  DensityProfile mie_density;
  Spectrum mie_scattering{};         // m^-1 at density 1.
  Spectrum mie_extinction{};         // m^-1 at density 1, >= mie_scattering.
  double mie_phase_g = 0.0;          // Cornette-Shanks asymmetry, in (-1, 1).
  DensityProfile absorption_density;  // ozone.
  Spectrum absorption_extinction{};  // m^-1 at density 1.
  Spectrum ground_albedo{};          // Lambertian, in [0, 1].
  double mu_s_min = 0.0;             // cosine of the largest sun zenith angle the tables cover.

  // The "earth" atmosphere of Bruneton 2017's demo (docs/design.md, "Conventions").
  static AtmosphereParameters Earth();

  // Stable FNV-1a hash of every physical field (not the name): the cache key.
  uint64_t Hash() const;
};

// Atmosphere files (TOML, examples/atmospheres/*.toml; the keys: atmosphere/config.h).
// Reads and validates a file. A missing or unreadable file throws an Error naming the path.
AtmosphereParameters LoadAtmosphereFile(const std::filesystem::path& path);

// Checks physical ranges, on each value as the shaders receive it (rounded to float): bottom
// radius in [1000, 100000] km and thickness top - bottom in [1, 1000] km; wavelengths in
// [360, 830] nm, where the spectral data (solar spectrum, ozone, CIE observer) are tabulated;
// solar irradiance in [0, 1000] W/m^2/nm, not 0 at all three; sun angular radius in [1e-4, 0.1] rad;
// scattering, extinction and absorption in [0, 0.1] m^-1, with Mie extinction >= Mie scattering;
// Mie g in (-1, 1); albedo in [0, 1]; mu_s_min in [-1, 0] (max_sun_zenith_deg in [90, 180]);
// density layers with width >= 0 and each term within +-1e6 at every altitude. Why each range:
// config.cpp, next to the constants. Errors name fields by their TOML keys. where is copied into
// the Error.
void Validate(const AtmosphereParameters& atmosphere, const std::string& where = "");

}  // namespace aerial
