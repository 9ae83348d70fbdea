#include "aerial/atmosphere/config.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "aerial/atmosphere/config_layers.h"
#include "aerial/core/toml_reader.h"
#include "aerial/error.h"

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

// The physical ranges of Validate(), in one place. Each is checked on the value as the shaders
// receive it, rounded to float (AtmosphereUniforms): a double such as 1e300 is finite but becomes
// inf there, and 1e-50 becomes 0.
// Planet radius: below 1000 km no body keeps an atmosphere (Pluto, 1188 km, is the smallest
// known); above 100,000 km (Jupiter: 71,492 km) float, in which the shaders work with r,
// resolves altitude to worse than 8 m.
constexpr double kMinBottomRadiusM = 1e6, kMaxBottomRadiusM = 1e8;
// Atmosphere thickness: at least 1 km, so that the tables' r axis spans some 2000 float steps of
// r at Earth's radius (0.5 m each); at most 1000 km, beyond which exponential profiles and
// thin-shell sampling do not describe an atmosphere well.
constexpr double kMinThicknessM = 1e3, kMaxThicknessM = 1e6;
// Solar spectral irradiance at the top of the atmosphere: the Sun gives about 2 W/m^2/nm at its
// peak at 1 AU; 1000 is 500 times that (a planet 0.045 AU from a Sun-like star).
constexpr double kMaxSolarIrradiance = 1e3;
// Sun's angular radius: 1e-4 rad is the Sun seen from 47 AU (beyond Pluto); 0.1 rad a sun 20
// times as wide as ours. With the irradiance above, the sun disc's radiance E / (pi r^2) stays
// below 3.2e10, far inside float.
constexpr double kMinSunRadiusRad = 1e-4, kMaxSunRadiusRad = 0.1;
// Scattering, extinction and absorption coefficients: 0.1 m^-1 is a visibility (3.9 / beta) of
// 39 m, thick fog; Earth's clear air is about 1e-5 m^-1.
constexpr double kMaxCoefficientPerM = 0.1;
// Density layer terms: the density is clamped to [0, 1], and float (7 significant digits) could
// not resolve it from terms larger than 1e6, nor exp() past float's largest (e^88); so each term
// must stay within +-1e6 at every altitude of the atmosphere.
constexpr double kMaxDensityTerm = 1e6;

// value as the shaders receive it. Beyond float's range it is +-inf (the conversion itself would
// be undefined behavior), below its smallest denormal 0.
double AsFloat(double value) {
  if (std::fabs(value) > std::numeric_limits<float>::max() && std::isfinite(value))
    return std::copysign(HUGE_VAL, value);
  return static_cast<float>(value);
}

void Check(bool ok, const std::string& field, double value, const std::string& allowed,
           const std::string& where) {
  if (!ok) throw Error(field, TomlFloat(value), allowed, where);
}

// A value in [low, high] once value and bounds are rounded to float, so that a bound itself is in
// range as the message says ("0.1" is 0.100000001 as float); NaN fails every comparison.
void CheckRange(double value, const std::string& field, double low, double high,
                const std::string& unit, const std::string& where) {
  double f = AsFloat(value);
  Check(f >= AsFloat(low) && f <= AsFloat(high), field, value,
        "in [" + TomlFloat(low) + ", " + TomlFloat(high) + "]" + unit + " (as float)", where);
}

void CheckSpectrum(const Spectrum& s, const std::string& field, double low, double high,
                   const std::string& unit, const std::string& where) {
  for (size_t i = 0; i < 3; ++i) CheckRange(s[i], TomlReader::Index(field, i), low, high, unit, where);
}

// Each term of density(h) = exp_term * exp(exp_scale_per_m * h) + linear_term_per_m * h +
// constant_term within kMaxDensityTerm over h in [0, thickness], in float.
void CheckDensity(const DensityProfile& profile, const std::string& field, double thickness_m,
                  const std::string& where) {
  std::vector<const DensityProfileLayer*> layers = config_layers::FileLayers(profile);
  const std::string within = " (each term of the density within +-" + TomlFloat(kMaxDensityTerm) +
                             " up to the top, " + TomlFloat(thickness_m) + " m)";
  for (size_t i = 0; i < layers.size(); ++i) {
    std::string layer_field = TomlReader::Index(field, i);
    auto key = [&](const char* name) { return TomlReader::Join(layer_field, name); };
    for (auto [name, member] : kFields) {
      double value = layers[i]->*member;
      Check(std::isfinite(AsFloat(value)), key(name), value, "a finite number (as float)", where);
    }
    const DensityProfileLayer& l = *layers[i];
    Check(l.width_m >= 0.0, key("width_m"), l.width_m, ">= 0 m", where);
    Check(std::fabs(l.exp_term) <= kMaxDensityTerm, key("exp_term"), l.exp_term,
          "at most " + TomlFloat(kMaxDensityTerm) + " in magnitude", where);
    // The exponential is largest at one end of [0, thickness]. exp() itself must stay within the
    // bound even when exp_term is 0, or 0 * inf gives NaN in the shaders. Compared as logarithms,
    // so that exp() cannot overflow here either.
    double growth = std::max(0.0, l.exp_scale_per_m * thickness_m);
    Check(std::log(std::max(std::fabs(l.exp_term), 1.0)) + growth <= std::log(kMaxDensityTerm),
          key("exp_scale_per_m"), l.exp_scale_per_m, "a scale that keeps exp_term * exp(scale * h)" + within,
          where);
    Check(std::fabs(l.linear_term_per_m) * thickness_m <= kMaxDensityTerm, key("linear_term_per_m"),
          l.linear_term_per_m, "a slope that keeps linear_term_per_m * h" + within, where);
    Check(std::fabs(l.constant_term) <= kMaxDensityTerm, key("constant_term"), l.constant_term,
          "at most " + TomlFloat(kMaxDensityTerm) + " in magnitude", where);
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
  return ParseAtmosphereToml(ReadTomlFile(path, "atmosphere file"), path.string());
}

void Validate(const AtmosphereParameters& a, const std::string& where) {
  const std::string per_m = " m^-1";
  CheckSpectrum(a.wavelengths_nm, "wavelengths_nm", kMinWavelengthNm, kMaxWavelengthNm,
                " nm (where the spectral data are tabulated)", where);
  CheckSpectrum(a.solar_irradiance, "solar_irradiance", 0.0, kMaxSolarIrradiance, " W/m^2/nm", where);
  // A channel may be dark, but a sun without light leaves nothing to see, and the exposure and the
  // white balance, which divide by it, undefined.
  if (!std::any_of(a.solar_irradiance.begin(), a.solar_irradiance.end(), [](double e) { return AsFloat(e) > 0.0; })) {
    throw Error("solar_irradiance",
                "[" + TomlFloat(a.solar_irradiance[0]) + ", " + TomlFloat(a.solar_irradiance[1]) + ", " +
                    TomlFloat(a.solar_irradiance[2]) + "]",
                "at least one value > 0 W/m^2/nm (a sun that gives light)", where);
  }
  CheckRange(a.sun_angular_radius_rad, "sun_angular_radius_rad", kMinSunRadiusRad, kMaxSunRadiusRad,
             " rad", where);
  CheckRange(a.bottom_radius_m, "bottom_radius_m", kMinBottomRadiusM, kMaxBottomRadiusM, " m", where);
  // The tables parameterize altitude over [bottom, top], as floats.
  double thickness_m = AsFloat(a.top_radius_m) - AsFloat(a.bottom_radius_m);
  Check(thickness_m >= kMinThicknessM && thickness_m <= kMaxThicknessM, "top_radius_m", a.top_radius_m,
        "in [bottom_radius_m + " + TomlFloat(kMinThicknessM / 1e3) + " km, bottom_radius_m + " +
            TomlFloat(kMaxThicknessM / 1e3) + " km] = [" + TomlFloat(a.bottom_radius_m + kMinThicknessM) +
            ", " + TomlFloat(a.bottom_radius_m + kMaxThicknessM) + "] m",
        where);
  CheckSpectrum(a.ground_albedo, "ground_albedo", 0.0, 1.0, "", where);
  if (!(AsFloat(a.mu_s_min) >= -1.0 && AsFloat(a.mu_s_min) <= 0.0)) {
    throw Error("max_sun_zenith_deg",
                TomlFloat(std::acos(a.mu_s_min) * 180.0 / std::numbers::pi) +
                    " (mu_s_min = " + TomlFloat(a.mu_s_min) + ")",
                "[90, 180] degrees (mu_s_min in [-1, 0])", where);
  }
  CheckSpectrum(a.rayleigh_scattering, "rayleigh.scattering", 0.0, kMaxCoefficientPerM, per_m, where);
  CheckDensity(a.rayleigh_density, "rayleigh.density", thickness_m, where);
  CheckSpectrum(a.mie_scattering, "mie.scattering", 0.0, kMaxCoefficientPerM, per_m, where);
  CheckSpectrum(a.mie_extinction, "mie.extinction", 0.0, kMaxCoefficientPerM, per_m, where);
  // Extinction = scattering + absorption, and absorption cannot be negative.
  for (size_t i = 0; i < 3; ++i) {
    Check(AsFloat(a.mie_extinction[i]) >= AsFloat(a.mie_scattering[i]),
          TomlReader::Index("mie.extinction", i), a.mie_extinction[i],
          ">= mie.scattering[" + std::to_string(i) + "] = " + TomlFloat(a.mie_scattering[i]) +
              " (extinction includes scattering)",
          where);
  }
  // g = +-1 makes the Cornette-Shanks phase function a delta peak (division by zero at theta 0);
  // a g that rounds to +-1 in float does the same in the shaders.
  Check(AsFloat(a.mie_phase_g) > -1.0 && AsFloat(a.mie_phase_g) < 1.0, "mie.phase_g", a.mie_phase_g,
        "in (-1, 1), open (as float)", where);
  CheckDensity(a.mie_density, "mie.density", thickness_m, where);
  CheckSpectrum(a.absorption_extinction, "ozone.absorption", 0.0, kMaxCoefficientPerM, per_m, where);
  CheckDensity(a.absorption_density, "ozone.density", thickness_m, where);
}

}  // namespace aerial
