#include "aerial/atmosphere/config.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <numbers>
#include <vector>

#include "aerial/core/error.h"

namespace aerial {
namespace {

using Layer = DensityProfileLayer;

// The members of a density layer, in file order, with their TOML keys.
constexpr std::pair<const char*, double Layer::*> kLayerFields[] = {
    {"width_m", &Layer::width_m},
    {"exp_term", &Layer::exp_term},
    {"exp_scale_per_m", &Layer::exp_scale_per_m},
    {"linear_term_per_m", &Layer::linear_term_per_m},
    {"constant_term", &Layer::constant_term}};

// Shortest text that reads back as the same double (std::to_chars), as a TOML float. Fixed
// notation for ordinary magnitudes ("6360000.0", not "6.36e+06"); TOML reads "6360000" as an
// integer, so a ".0" is added to integral values.
std::string FormatDouble(double value) {
  char buffer[512];
  double magnitude = std::fabs(value);
  auto format = (magnitude == 0.0 || (magnitude >= 1e-3 && magnitude < 1e16))
                    ? std::chars_format::fixed
                    : std::chars_format::general;
  std::string text(buffer, std::to_chars(buffer, buffer + sizeof buffer, value, format).ptr);
  if (text.find_first_of(".ein") == std::string::npos) text += ".0";
  return text;
}

std::string FormatSpectrum(const Spectrum& s) {
  std::string text = "[";
  for (size_t i = 0; i < s.size(); ++i) text += (i ? ", " : "") + FormatDouble(s[i]);
  return text + "]";
}

// A TOML basic string: quotes, backslashes and control characters escaped.
std::string Quote(std::string_view text) {
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += c;
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", c);
      quoted += escape;
    } else {
      quoted += c;
    }
  }
  return quoted + "\"";
}

// The offending value as the user wrote it, for messages.
std::string NodeText(const toml::node& node) {
  if (auto* v = node.as_string()) return Quote(v->get());
  if (auto* v = node.as_integer()) return std::to_string(v->get());
  if (auto* v = node.as_floating_point()) return FormatDouble(v->get());
  if (auto* v = node.as_boolean()) return v->get() ? "true" : "false";
  if (auto* array = node.as_array()) {
    std::string text = "[";
    for (size_t i = 0; i < array->size(); ++i) text += (i ? ", " : "") + NodeText(*array->get(i));
    return text + "]";
  }
  if (node.is_table()) return "(a table)";
  return "(a date or time)";
}

// Reads typed values out of the parsed document, remembering where each key was written so
// that a range error found later by Validate() can still point at its line.
class Reader {
 public:
  explicit Reader(std::string where) : where_(std::move(where)) {}

  [[noreturn]] void Fail(const toml::node& node, const std::string& field,
                         const std::string& allowed) const {
    throw Error(field, NodeText(node), allowed, At(node.source().begin));
  }

  // "file:line:column" of a key read from the document, or just "file" for defaulted keys.
  std::string WhereOf(const std::string& field) const {
    auto it = positions_.find(field);
    return it == positions_.end() ? where_ : At(it->second);
  }

  void RejectUnknownKeys(const toml::table& table, const std::string& prefix,
                         std::initializer_list<std::string_view> known) const {
    for (auto&& [key, node] : table) {
      if (std::find(known.begin(), known.end(), key.str()) != known.end()) continue;
      std::string allowed = "a known key; ";
      allowed += prefix.empty() ? "top-level keys are" : "keys in " + prefix + " are";
      for (size_t i = 0; i < known.size(); ++i)
        allowed += (i ? ", " : " ") + std::string(known.begin()[i]);
      throw Error(Join(prefix, key.str()), NodeText(node), allowed, At(key.source().begin));
    }
  }

  const toml::table& Table(const toml::node& node, const std::string& field,
                           const std::string& allowed) {
    Remember(node, field);
    if (!node.is_table()) Fail(node, field, allowed);
    return *node.as_table();
  }

  std::string String(const toml::node& node, const std::string& field) {
    Remember(node, field);
    if (!node.is_string()) Fail(node, field, "a string");
    return node.as_string()->get();
  }

  // Integers are accepted too: "bottom_radius_m = 6360000" means 6360000.0.
  double Number(const toml::node& node, const std::string& field, const std::string& unit) {
    Remember(node, field);
    if (auto* v = node.as_floating_point()) return v->get();
    if (auto* v = node.as_integer()) return static_cast<double>(v->get());
    Fail(node, field, "a number" + (unit.empty() ? "" : " (" + unit + ")"));
  }

  Spectrum ReadSpectrum(const toml::node& node, const std::string& field, const std::string& unit) {
    Remember(node, field);
    const toml::array* array = node.as_array();
    if (!array) Fail(node, field, "an array of 3 numbers (" + unit + "), one per wavelength");
    if (array->size() != 3)
      Fail(node, field, "3 values, one per wavelength; it has " + std::to_string(array->size()));
    Spectrum s;
    for (size_t i = 0; i < 3; ++i) s[i] = Number(*array->get(i), Index(field, i), unit);
    return s;
  }

  DensityProfile ReadDensity(const toml::node& node, const std::string& field) {
    Remember(node, field);
    const toml::array* array = node.as_array();
    if (!array || array->empty() || array->size() > 2) {
      std::string got = array ? "; it has " + std::to_string(array->size()) : "";
      Fail(node, field, "an array of 1 or 2 layer tables {width_m, exp_term, ...}" + got);
    }
    DensityProfile profile;
    // One layer applies everywhere: it goes to layers[1], below a zero-width layers[0].
    size_t first = array->size() == 1 ? 1 : 0;
    for (size_t i = 0; i < array->size(); ++i) {
      std::string layer_field = Index(field, i);
      const toml::table& table =
          Table(*array->get(i), layer_field, "a layer table {width_m = ..., exp_term = ...}");
      RejectUnknownKeys(
          table, layer_field,
          {"width_m", "exp_term", "exp_scale_per_m", "linear_term_per_m", "constant_term"});
      Layer& layer = profile.layers[first + i];
      for (auto [key, member] : kLayerFields) {
        if (const toml::node* value = table.get(key))
          layer.*member = Number(*value, Join(layer_field, key), "");
      }
    }
    return profile;
  }

  static std::string Join(const std::string& prefix, std::string_view key) {
    return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
  }
  static std::string Index(const std::string& field, size_t i) {
    return field + "[" + std::to_string(i) + "]";
  }

 private:
  void Remember(const toml::node& node, const std::string& field) {
    positions_[field] = node.source().begin;
  }
  std::string At(const toml::source_position& position) const {
    return where_ + ":" + std::to_string(position.line) + ":" + std::to_string(position.column);
  }

  std::string where_;
  std::map<std::string, toml::source_position> positions_;
};

// Applies one optional key: calls read(node) if the key is present.
template <typename F>
void IfPresent(const toml::table& table, std::string_view key, F read) {
  if (const toml::node* node = table.get(key)) read(*node);
}

void Check(bool ok, const std::string& field, double value, const std::string& allowed,
           const std::string& where) {
  if (!ok) throw Error(field, FormatDouble(value), allowed, where);
}

void CheckSpectrum(const Spectrum& s, const std::string& field, double low, double high,
                   const std::string& allowed, const std::string& where) {
  for (size_t i = 0; i < 3; ++i) {
    bool ok = s[i] >= low && s[i] <= high && std::isfinite(s[i]);
    Check(ok, Reader::Index(field, i), s[i], allowed, where);
  }
}

bool IsZero(const Layer& layer) {
  for (auto [key, member] : kLayerFields)
    if (layer.*member != 0.0) return false;
  return true;
}

// The layers as the file lists them: only layers[1] when layers[0] is the zero placeholder.
std::vector<const Layer*> FileLayers(const DensityProfile& profile) {
  if (IsZero(profile.layers[0])) return {&profile.layers[1]};
  return {&profile.layers[0], &profile.layers[1]};
}

void CheckDensity(const DensityProfile& profile, const std::string& field,
                  const std::string& where) {
  std::vector<const Layer*> layers = FileLayers(profile);
  for (size_t i = 0; i < layers.size(); ++i) {
    std::string layer_field = Reader::Index(field, i);
    for (auto [key, member] : kLayerFields) {
      double value = layers[i]->*member;
      Check(std::isfinite(value), Reader::Join(layer_field, key), value, "a finite number", where);
    }
    Check(layers[i]->width_m >= 0.0, Reader::Join(layer_field, "width_m"), layers[i]->width_m,
          ">= 0 m", where);
  }
}

std::string DensityToToml(const DensityProfile& profile) {
  std::string text = "density = [\n";
  for (const Layer* layer : FileLayers(profile)) {
    text += "  {";
    const char* separator = " ";
    for (auto [key, member] : kLayerFields) {
      text += separator + std::string(key) + " = " + FormatDouble(layer->*member);
      separator = ", ";
    }
    text += " },\n";
  }
  return text + "]\n";
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
    if (!best_exact || FormatDouble(candidate).size() < FormatDouble(best).size()) best = candidate;
    best_exact = true;
  }
  return best;
}

AtmosphereParameters ParseAtmosphereToml(std::string_view text, const std::string& where) {
  toml::table root;
  try {
    root = toml::parse(text, where);
  } catch (const toml::parse_error& e) {
    const auto& begin = e.source().begin;
    throw Error("TOML syntax", std::string(e.description()), "TOML v1.0 (https://toml.io)",
                where + ":" + std::to_string(begin.line) + ":" + std::to_string(begin.column));
  }
  Reader r(where);
  AtmosphereParameters a = AtmosphereParameters::Earth();
  r.RejectUnknownKeys(
      root, "",
      {"name", "wavelengths_nm", "solar_irradiance", "sun_angular_radius_rad", "bottom_radius_m",
       "top_radius_m", "ground_albedo", "max_sun_zenith_deg", "rayleigh", "mie", "ozone"});
  IfPresent(root, "name", [&](auto& n) { a.name = r.String(n, "name"); });
  IfPresent(root, "wavelengths_nm",
            [&](auto& n) { a.wavelengths_nm = r.ReadSpectrum(n, "wavelengths_nm", "nm"); });
  IfPresent(root, "solar_irradiance", [&](auto& n) {
    a.solar_irradiance = r.ReadSpectrum(n, "solar_irradiance", "W/m^2/nm");
  });
  IfPresent(root, "sun_angular_radius_rad", [&](auto& n) {
    a.sun_angular_radius_rad = r.Number(n, "sun_angular_radius_rad", "rad");
  });
  IfPresent(root, "bottom_radius_m",
            [&](auto& n) { a.bottom_radius_m = r.Number(n, "bottom_radius_m", "m"); });
  IfPresent(root, "top_radius_m",
            [&](auto& n) { a.top_radius_m = r.Number(n, "top_radius_m", "m"); });
  IfPresent(root, "ground_albedo",
            [&](auto& n) { a.ground_albedo = r.ReadSpectrum(n, "ground_albedo", "in [0, 1]"); });
  IfPresent(root, "max_sun_zenith_deg", [&](auto& n) {
    // Checked here, in degrees as written; Validate() only sees the cosine.
    double degrees = r.Number(n, "max_sun_zenith_deg", "degrees");
    if (!(degrees >= 90.0 && degrees <= 180.0))
      r.Fail(n, "max_sun_zenith_deg", "[90, 180] degrees");
    a.mu_s_min = MuSMinFromMaxSunZenithDeg(degrees);
  });
  IfPresent(root, "rayleigh", [&](auto& n) {
    const toml::table& t = r.Table(n, "rayleigh", "a table ([rayleigh])");
    r.RejectUnknownKeys(t, "rayleigh", {"scattering", "density"});
    IfPresent(t, "scattering", [&](auto& m) {
      a.rayleigh_scattering = r.ReadSpectrum(m, "rayleigh.scattering", "m^-1");
    });
    IfPresent(t, "density",
              [&](auto& m) { a.rayleigh_density = r.ReadDensity(m, "rayleigh.density"); });
  });
  IfPresent(root, "mie", [&](auto& n) {
    const toml::table& t = r.Table(n, "mie", "a table ([mie])");
    r.RejectUnknownKeys(t, "mie", {"scattering", "extinction", "phase_g", "density"});
    IfPresent(t, "scattering",
              [&](auto& m) { a.mie_scattering = r.ReadSpectrum(m, "mie.scattering", "m^-1"); });
    IfPresent(t, "extinction",
              [&](auto& m) { a.mie_extinction = r.ReadSpectrum(m, "mie.extinction", "m^-1"); });
    IfPresent(t, "phase_g", [&](auto& m) { a.mie_phase_g = r.Number(m, "mie.phase_g", ""); });
    IfPresent(t, "density", [&](auto& m) { a.mie_density = r.ReadDensity(m, "mie.density"); });
  });
  IfPresent(root, "ozone", [&](auto& n) {
    const toml::table& t = r.Table(n, "ozone", "a table ([ozone])");
    r.RejectUnknownKeys(t, "ozone", {"absorption", "density"});
    IfPresent(t, "absorption", [&](auto& m) {
      a.absorption_extinction = r.ReadSpectrum(m, "ozone.absorption", "m^-1");
    });
    IfPresent(t, "density",
              [&](auto& m) { a.absorption_density = r.ReadDensity(m, "ozone.density"); });
  });
  try {
    Validate(a);
  } catch (const Error& e) {
    throw Error(e.field(), e.value(), e.allowed(), r.WhereOf(e.field()));
  }
  return a;
}

AtmosphereParameters LoadAtmosphereFile(const std::filesystem::path& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                       &std::fclose);
  if (!file) {
    throw Error("atmosphere file", path.string(),
                std::string("a readable TOML file (") + std::strerror(errno) + ")");
  }
  std::string text;
  char chunk[4096];
  size_t got;
  while ((got = std::fread(chunk, 1, sizeof chunk, file.get())) > 0) text.append(chunk, got);
  // Reading a directory opens fine and fails here (EISDIR).
  if (std::ferror(file.get())) {
    throw Error("atmosphere file", path.string(),
                std::string("a readable TOML file (") + std::strerror(errno) + ")");
  }
  return ParseAtmosphereToml(text, path.string());
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
        "in (bottom_radius_m, bottom_radius_m + 1000 km] = (" + FormatDouble(a.bottom_radius_m) +
            ", " + FormatDouble(a.bottom_radius_m + 1e6) + "] m",
        where);
  CheckSpectrum(a.ground_albedo, "ground_albedo", 0.0, 1.0, "[0, 1]", where);
  if (!(a.mu_s_min >= -1.0 && a.mu_s_min <= 0.0)) {
    throw Error("max_sun_zenith_deg",
                FormatDouble(std::acos(a.mu_s_min) * 180.0 / std::numbers::pi) +
                    " (mu_s_min = " + FormatDouble(a.mu_s_min) + ")",
                "[90, 180] degrees (mu_s_min in [-1, 0])", where);
  }
  CheckSpectrum(a.rayleigh_scattering, "rayleigh.scattering", 0.0, HUGE_VAL, non_negative, where);
  CheckDensity(a.rayleigh_density, "rayleigh.density", where);
  CheckSpectrum(a.mie_scattering, "mie.scattering", 0.0, HUGE_VAL, non_negative, where);
  CheckSpectrum(a.mie_extinction, "mie.extinction", 0.0, HUGE_VAL, non_negative, where);
  // Extinction = scattering + absorption, and absorption cannot be negative.
  for (size_t i = 0; i < 3; ++i) {
    Check(a.mie_extinction[i] >= a.mie_scattering[i], Reader::Index("mie.extinction", i),
          a.mie_extinction[i],
          ">= mie.scattering[" + std::to_string(i) + "] = " + FormatDouble(a.mie_scattering[i]) +
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

std::string ToToml(const AtmosphereParameters& a) {
  std::string text = "# aerial atmosphere (SI units; format in src/aerial/atmosphere/config.h)\n";
  text += "name = " + Quote(a.name) + "\n";
  text += "wavelengths_nm = " + FormatSpectrum(a.wavelengths_nm) + "\n";
  text += "solar_irradiance = " + FormatSpectrum(a.solar_irradiance) + "  # W/m^2/nm\n";
  text += "sun_angular_radius_rad = " + FormatDouble(a.sun_angular_radius_rad) + "\n";
  text += "bottom_radius_m = " + FormatDouble(a.bottom_radius_m) + "\n";
  text += "top_radius_m = " + FormatDouble(a.top_radius_m) + "\n";
  text += "ground_albedo = " + FormatSpectrum(a.ground_albedo) + "\n";
  text += "max_sun_zenith_deg = " + FormatDouble(MaxSunZenithDegFromMuSMin(a.mu_s_min)) + "\n";
  text += "\n[rayleigh]\nscattering = " + FormatSpectrum(a.rayleigh_scattering) + "  # m^-1\n";
  text += DensityToToml(a.rayleigh_density);
  text += "\n[mie]\nscattering = " + FormatSpectrum(a.mie_scattering) + "  # m^-1\n";
  text += "extinction = " + FormatSpectrum(a.mie_extinction) + "  # m^-1\n";
  text += "phase_g = " + FormatDouble(a.mie_phase_g) + "\n";
  text += DensityToToml(a.mie_density);
  text += "\n[ozone]\nabsorption = " + FormatSpectrum(a.absorption_extinction) + "  # m^-1\n";
  text += DensityToToml(a.absorption_density);
  return text;
}

}  // namespace aerial
