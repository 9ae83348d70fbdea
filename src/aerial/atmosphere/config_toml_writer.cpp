// ToToml (config.h): atmosphere parameters back to the TOML that ParseAtmosphereToml reads.
#include <string>

#include "aerial/atmosphere/config.h"
#include "aerial/atmosphere/config_layers.h"
#include "aerial/core/toml_reader.h"

namespace aerial {
namespace {

std::string FormatSpectrum(const Spectrum& s) {
  std::string text = "[";
  for (size_t i = 0; i < s.size(); ++i) text += (i ? ", " : "") + TomlFloat(s[i]);
  return text + "]";
}

std::string DensityToToml(const DensityProfile& profile) {
  std::string text = "density = [\n";
  for (const DensityProfileLayer* layer : config_layers::FileLayers(profile)) {
    text += "  {";
    const char* separator = " ";
    for (auto [key, member] : config_layers::kFields) {
      text += separator + std::string(key) + " = " + TomlFloat(layer->*member);
      separator = ", ";
    }
    text += " },\n";
  }
  return text + "]\n";
}

}  // namespace

std::string ToToml(const AtmosphereParameters& a) {
  std::string text = "# aerial atmosphere (SI units; format in src/aerial/atmosphere/config.h)\n";
  text += "name = " + TomlString(a.name) + "\n";
  text += "wavelengths_nm = " + FormatSpectrum(a.wavelengths_nm) + "\n";
  text += "solar_irradiance = " + FormatSpectrum(a.solar_irradiance) + "  # W/m^2/nm\n";
  text += "sun_angular_radius_rad = " + TomlFloat(a.sun_angular_radius_rad) + "\n";
  text += "bottom_radius_m = " + TomlFloat(a.bottom_radius_m) + "\n";
  text += "top_radius_m = " + TomlFloat(a.top_radius_m) + "\n";
  text += "ground_albedo = " + FormatSpectrum(a.ground_albedo) + "\n";
  text += "max_sun_zenith_deg = " + TomlFloat(MaxSunZenithDegFromMuSMin(a.mu_s_min)) + "\n";
  text += "\n[rayleigh]\nscattering = " + FormatSpectrum(a.rayleigh_scattering) + "  # m^-1\n";
  text += DensityToToml(a.rayleigh_density);
  text += "\n[mie]\nscattering = " + FormatSpectrum(a.mie_scattering) + "  # m^-1\n";
  text += "extinction = " + FormatSpectrum(a.mie_extinction) + "  # m^-1\n";
  text += "phase_g = " + TomlFloat(a.mie_phase_g) + "\n";
  text += DensityToToml(a.mie_density);
  text += "\n[ozone]\nabsorption = " + FormatSpectrum(a.absorption_extinction) + "  # m^-1\n";
  text += DensityToToml(a.absorption_density);
  return text;
}

}  // namespace aerial
