#include "aerial/atmosphere/config.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "aerial/atmosphere/config_layers.h"
#include "aerial/core/error.h"
#include "aerial/core/toml_reader.h"

namespace aerial {
namespace {

using config_layers::kFields;

Spectrum ReadSpectrum(TomlReader& r, const toml::node& node, const std::string& field,
                      const std::string& unit) {
  const toml::array* array = node.as_array();
  if (!array) r.Fail(node, field, "an array of 3 numbers (" + unit + "), one per wavelength");
  if (array->size() != 3)
    r.Fail(node, field, "3 values, one per wavelength; it has " + std::to_string(array->size()));
  std::vector<double> values = r.Numbers(node, field, 3, 3, unit);
  return {values[0], values[1], values[2]};
}

DensityProfile ReadDensity(TomlReader& r, const toml::node& node, const std::string& field) {
  const toml::array* array = node.as_array();
  if (!array || array->empty() || array->size() > 2) {
    std::string got = array ? "; it has " + std::to_string(array->size()) : "";
    r.Fail(node, field, "an array of 1 or 2 layer tables {width_m, exp_term, ...}" + got);
  }
  DensityProfile profile;
  // One layer applies everywhere: it goes to layers[1], below a zero-width layers[0].
  size_t first = array->size() == 1 ? 1 : 0;
  for (size_t i = 0; i < array->size(); ++i) {
    std::string layer_field = TomlReader::Index(field, i);
    const toml::table& table =
        r.Table(*array->get(i), layer_field, "a layer table {width_m = ..., exp_term = ...}");
    r.RejectUnknownKeys(
        table, layer_field,
        {"width_m", "exp_term", "exp_scale_per_m", "linear_term_per_m", "constant_term"});
    DensityProfileLayer& layer = profile.layers[first + i];
    for (auto [key, member] : kFields) {
      if (const toml::node* value = table.get(key))
        layer.*member = r.Number(*value, TomlReader::Join(layer_field, key), "");
    }
  }
  return profile;
}

void Check(bool ok, const std::string& field, double value, const std::string& allowed,
           const std::string& where) {
  if (!ok) throw Error(field, TomlFloat(value), allowed, where);
}

void CheckSpectrum(const Spectrum& s, const std::string& field, double low, double high,
                   const std::string& allowed, const std::string& where) {
  for (size_t i = 0; i < 3; ++i) {
    bool ok = s[i] >= low && s[i] <= high && std::isfinite(s[i]);
    Check(ok, TomlReader::Index(field, i), s[i], allowed, where);
  }
}

void CheckDensity(const DensityProfile& profile, const std::string& field,
                  const std::string& where) {
  std::vector<const DensityProfileLayer*> layers = config_layers::FileLayers(profile);
  for (size_t i = 0; i < layers.size(); ++i) {
    std::string layer_field = TomlReader::Index(field, i);
    for (auto [key, member] : kFields) {
      double value = layers[i]->*member;
      Check(std::isfinite(value), TomlReader::Join(layer_field, key), value, "a finite number",
            where);
    }
    Check(layers[i]->width_m >= 0.0, TomlReader::Join(layer_field, "width_m"), layers[i]->width_m,
          ">= 0 m", where);
  }
}

}  // namespace

double MuSMinFromMaxSunZenithDeg(double degrees) {
  // cos(d) = -sin(d - 90): d - 90 is exact for d in [90, 180] (Sterbenz), sin(0) = 0 exactly,
  // and long double (64-bit mantissa on x86-64, 113 on AArch64 Linux) keeps the error of pi/6
  // and pi/2 far below half a double ulp, so 120 and 180 round to exactly -0.5 and -1.
  constexpr long double kPi = 3.141592653589793238462643383279502884L;
  long double s = std::sin((static_cast<long double>(degrees) - 90.0L) * kPi / 180.0L);
  return 0.0 - static_cast<double>(s);
}

double MaxSunZenithDegFromMuSMin(double mu_s_min) {
  constexpr long double kPi = 3.141592653589793238462643383279502884L;
  long double degrees = 90.0L + std::asin(-static_cast<long double>(mu_s_min)) * 180.0L / kPi;
  // Among the doubles next to the exact angle, prefer one that maps back to mu_s_min exactly,
  // then the one with the shortest text ("120.0", not "120.00000000000001").
  double best = static_cast<double>(degrees);
  double candidate = best;
  for (int i = 0; i < 8; ++i) candidate = std::nextafter(candidate, -INFINITY);
  bool best_exact = false;
  for (int i = 0; i < 17; ++i, candidate = std::nextafter(candidate, INFINITY)) {
    if (MuSMinFromMaxSunZenithDeg(candidate) != mu_s_min) continue;
    if (!best_exact || TomlFloat(candidate).size() < TomlFloat(best).size()) best = candidate;
    best_exact = true;
  }
  return best;
}

AtmosphereParameters ParseAtmosphereToml(std::string_view text, const std::string& where) {
  TomlReader r(where);
  toml::table root = r.Parse(text);
  AtmosphereParameters a = AtmosphereParameters::Earth();
  // Each reads one optional key of table t, whose dotted name is prefix ("" at the top level).
  auto number = [&](const toml::table& t, const std::string& prefix, std::string_view key,
                    double& out, const std::string& unit) {
    IfPresent(t, key, [&](auto& n) { out = r.Number(n, TomlReader::Join(prefix, key), unit); });
  };
  auto spectrum = [&](const toml::table& t, const std::string& prefix, std::string_view key,
                      Spectrum& out, const std::string& unit) {
    IfPresent(t, key,
              [&](auto& n) { out = ReadSpectrum(r, n, TomlReader::Join(prefix, key), unit); });
  };
  auto density = [&](const toml::table& t, const std::string& prefix, DensityProfile& out) {
    IfPresent(t, "density", [&](auto& n) { out = ReadDensity(r, n, prefix + ".density"); });
  };
  // A section ([mie]): read(table) if present, after checking its keys.
  auto section = [&](const std::string& key, std::initializer_list<std::string_view> known,
                     auto read) {
    IfPresent(root, key, [&](auto& n) {
      const toml::table& t = r.Table(n, key);
      r.RejectUnknownKeys(t, key, known);
      read(t);
    });
  };

  r.RejectUnknownKeys(
      root, "",
      {"name", "wavelengths_nm", "solar_irradiance", "sun_angular_radius_rad", "bottom_radius_m",
       "top_radius_m", "ground_albedo", "max_sun_zenith_deg", "rayleigh", "mie", "ozone"});
  IfPresent(root, "name", [&](auto& n) { a.name = r.String(n, "name"); });
  spectrum(root, "", "wavelengths_nm", a.wavelengths_nm, "nm");
  spectrum(root, "", "solar_irradiance", a.solar_irradiance, "W/m^2/nm");
  number(root, "", "sun_angular_radius_rad", a.sun_angular_radius_rad, "rad");
  number(root, "", "bottom_radius_m", a.bottom_radius_m, "m");
  number(root, "", "top_radius_m", a.top_radius_m, "m");
  spectrum(root, "", "ground_albedo", a.ground_albedo, "in [0, 1]");
  IfPresent(root, "max_sun_zenith_deg", [&](auto& n) {
    // Checked here, in degrees as written; Validate() only sees the cosine.
    double degrees = r.Number(n, "max_sun_zenith_deg", "degrees");
    if (!(degrees >= 90.0 && degrees <= 180.0))
      r.Fail(n, "max_sun_zenith_deg", "[90, 180] degrees");
    a.mu_s_min = MuSMinFromMaxSunZenithDeg(degrees);
  });
  section("rayleigh", {"scattering", "density"}, [&](const toml::table& t) {
    spectrum(t, "rayleigh", "scattering", a.rayleigh_scattering, "m^-1");
    density(t, "rayleigh", a.rayleigh_density);
  });
  section("mie", {"scattering", "extinction", "phase_g", "density"}, [&](const toml::table& t) {
    spectrum(t, "mie", "scattering", a.mie_scattering, "m^-1");
    spectrum(t, "mie", "extinction", a.mie_extinction, "m^-1");
    number(t, "mie", "phase_g", a.mie_phase_g, "");
    density(t, "mie", a.mie_density);
  });
  section("ozone", {"absorption", "density"}, [&](const toml::table& t) {
    spectrum(t, "ozone", "absorption", a.absorption_extinction, "m^-1");
    density(t, "ozone", a.absorption_density);
  });
  try {
    Validate(a);
  } catch (const Error& e) {
    throw Error(e.field(), e.value(), e.allowed(), r.WhereOf(e.field()));
  }
  return a;
}

AtmosphereParameters LoadAtmosphereFile(const std::filesystem::path& path) {
  return ParseAtmosphereToml(ReadTomlFile(path, "--atmosphere"), path.string());
}

void Validate(const AtmosphereParameters& a, const std::string& where) {
  const std::string non_negative = ">= 0 and finite";
  CheckSpectrum(a.wavelengths_nm, "wavelengths_nm", 300.0, 1000.0, "[300, 1000] nm", where);
  CheckSpectrum(a.solar_irradiance, "solar_irradiance", 0.0, HUGE_VAL, non_negative, where);
  Check(a.sun_angular_radius_rad > 0.0 && a.sun_angular_radius_rad <= 0.1, "sun_angular_radius_rad",
        a.sun_angular_radius_rad, "(0, 0.1] rad", where);
  Check(a.bottom_radius_m > 0.0 && std::isfinite(a.bottom_radius_m), "bottom_radius_m",
        a.bottom_radius_m, "> 0 m and finite", where);
  // The tables parameterize altitude over [bottom, top]; a shell thicker than 1000 km is not an
  // atmosphere this model (exponential profiles, thin-shell sampling) describes well.
  Check(a.top_radius_m > a.bottom_radius_m && a.top_radius_m - a.bottom_radius_m <= 1e6,
        "top_radius_m", a.top_radius_m,
        "in (bottom_radius_m, bottom_radius_m + 1000 km] = (" + TomlFloat(a.bottom_radius_m) +
            ", " + TomlFloat(a.bottom_radius_m + 1e6) + "] m",
        where);
  CheckSpectrum(a.ground_albedo, "ground_albedo", 0.0, 1.0, "[0, 1]", where);
  if (!(a.mu_s_min >= -1.0 && a.mu_s_min <= 0.0)) {
    throw Error("max_sun_zenith_deg",
                TomlFloat(std::acos(a.mu_s_min) * 180.0 / std::numbers::pi) +
                    " (mu_s_min = " + TomlFloat(a.mu_s_min) + ")",
                "[90, 180] degrees (mu_s_min in [-1, 0])", where);
  }
  CheckSpectrum(a.rayleigh_scattering, "rayleigh.scattering", 0.0, HUGE_VAL, non_negative, where);
  CheckDensity(a.rayleigh_density, "rayleigh.density", where);
  CheckSpectrum(a.mie_scattering, "mie.scattering", 0.0, HUGE_VAL, non_negative, where);
  CheckSpectrum(a.mie_extinction, "mie.extinction", 0.0, HUGE_VAL, non_negative, where);
  // Extinction = scattering + absorption, and absorption cannot be negative.
  for (size_t i = 0; i < 3; ++i) {
    Check(a.mie_extinction[i] >= a.mie_scattering[i], TomlReader::Index("mie.extinction", i),
          a.mie_extinction[i],
          ">= mie.scattering[" + std::to_string(i) + "] = " + TomlFloat(a.mie_scattering[i]) +
              " (extinction includes scattering)",
          where);
  }
  // g = +-1 makes the Cornette-Shanks phase function a delta peak (division by zero at theta 0).
  Check(a.mie_phase_g > -1.0 && a.mie_phase_g < 1.0, "mie.phase_g", a.mie_phase_g,
        "in (-1, 1), open", where);
  CheckDensity(a.mie_density, "mie.density", where);
  CheckSpectrum(a.absorption_extinction, "ozone.absorption", 0.0, HUGE_VAL, non_negative, where);
  CheckDensity(a.absorption_density, "ozone.density", where);
}

}  // namespace aerial
