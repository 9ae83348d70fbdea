// aerial probe: the sky seen by one camera along one view ray, as JSON, from the tables or from
// the CPU reference. Other tools script against the option and key names: keep them stable.
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "aerial/cli/commands.h"
#include "aerial/cli/common_options.h"
#include "aerial/cli/memory_uses.h"
#include "aerial/core/toml_reader.h"
#include "aerial/error.h"
#include "aerial/probe.h"
#include "aerial/probe/spectral_reference.h"
#include "aerial/probe/spectral_table_probe.h"
#include "aerial/spectrum/colour.h"
#include "aerial/spectrum/spectral_sampling.h"

namespace aerial::cli {
namespace {

struct ProbeOptions {
  TableOptions tables;
  ViewAngles view;
  std::optional<double> distance_m;
  bool reference = false;
};

nlohmann::json ToJson(const Spectrum& s) { return nlohmann::json::array({s[0], s[1], s[2]}); }

// A radiance's (or irradiance's) three channels read as linear sRGB, in XYZ, with its luminance in
// cd/m^2 (or illuminance in lux): exact for spectral tables; for rgb ones, the three wavelengths
// taken as sRGB primaries, as the renderer shows them.
nlohmann::json ColourJson(const Spectrum& linear_srgb, const char* luminance_key) {
  Spectrum xyz = spectrum::Multiply(spectrum::XyzFromLinearSrgb(), linear_srgb);
  std::array<double, 2> uv = spectrum::ChromaticityUv(xyz);
  return {{"linear_srgb", ToJson(linear_srgb)},
          {"xyz", ToJson(xyz)},
          {"u_v", nlohmann::json::array({uv[0], uv[1]})},
          {luminance_key, spectrum::LuminanceCdM2(xyz)}};
}

// The quantities every probe reports, each as its three channels.
void AddQuantities(nlohmann::json& json, const ProbeResult& result, bool to_point) {
  json["sky_radiance"] = ToJson(result.sky_radiance);
  json["transmittance"] = ToJson(result.transmittance);
  json["sun_irradiance"] = ToJson(result.sun_irradiance);
  json["sky_irradiance"] = ToJson(result.sky_irradiance);
  json["solar_radiance"] = ToJson(result.solar_radiance);
  if (!to_point) return;
  json["radiance_to_point"] = ToJson(result.radiance_to_point);
  json["transmittance_to_point"] = ToJson(result.transmittance_to_point);
}

// The reference's Monte Carlo standard errors (of the orders >= 2), per channel.
void AddStdErrors(nlohmann::json& json, const ProbeResult& result, bool to_point) {
  json["sky_radiance_std_error"] = ToJson(result.sky_radiance_std_error);
  json["sky_irradiance_std_error"] = ToJson(result.sky_irradiance_std_error);
  if (to_point) json["radiance_to_point_std_error"] = ToJson(result.radiance_to_point_std_error);
}

// Each quantity of `result`, with its standard errors for the reference.
nlohmann::json QuantitiesJson(const ProbeResult& result, bool to_point, bool reference) {
  nlohmann::json json;
  AddQuantities(json, result, to_point);
  if (reference) AddStdErrors(json, result, to_point);
  return json;
}

// The quantities of groups of three wavelengths, each as one list over all their wavelengths.
nlohmann::json SpectrumJson(const std::vector<ProbeResult>& groups, bool to_point, bool reference) {
  nlohmann::json spectrum;
  for (const ProbeResult& group : groups) {
    const nlohmann::json channels = QuantitiesJson(group, to_point, reference);
    for (const auto& [key, values] : channels.items())
      for (const auto& value : values) spectrum[key].push_back(value);
  }
  return spectrum;
}

void RunProbe(const ProbeOptions& options) {
  AtmosphereParameters atmosphere = options.tables.LoadAtmosphere();
  ValidateViewAngles(options.view, atmosphere);
  // The shaders take the distance as a float; a ray ends at the atmosphere's boundary long before
  // 1e9 m (the longest, grazing Earth's, is under 2e6 m), so larger values are refused.
  if (options.distance_m && !(*options.distance_m >= 0.0 && *options.distance_m <= 1e9))
    throw aerial::Error("--distance-m", aerial::TomlFloat(*options.distance_m), "a distance in [0, 1e9] meters");
  PrecomputeOptions precompute = options.tables.MakePrecomputeOptions();
  RayParameters ray = ToRayParameters(options.view, atmosphere);
  const bool to_point = options.distance_m.has_value();
  const bool spectral = precompute.colour == ColourMode::kSpectral;
  const spectrum::SpectralSampling sampling = spectrum::SpectralSampling::ForTables(precompute.spectral_wavelengths);

  ProbeResult result;                       // rgb: at the atmosphere's wavelengths; spectral: linear sRGB
  std::vector<ProbeResult> at_wavelengths;  // spectral: at the sampling's wavelengths, group by group
  if (options.reference) {
    const ReferenceOptions reference{.orders = precompute.RepresentedOrders()};
    result = spectral ? ProbeReferenceSpectral(atmosphere, ray, options.distance_m, sampling, reference, &at_wavelengths)
                      : ProbeReference(atmosphere, ray, options.distance_m, reference);
  } else {
    Device device(options.tables.MakeDeviceOptions());
    // For spectral tables this counts their groups' tables and scratch, which the probe's groups
    // (ProbeSpectralTablesAtWavelengths) use one at a time.
    options.tables.MakeMemoryBudget(device.largest_heap_bytes()).Check(TableMemoryUses(precompute));
    const TableLoadOptions load = options.tables.MakeLoadOptions();
    Tables tables = Tables::LoadOrPrecompute(device, atmosphere, precompute, load);
    const ProbeQuery query{ray, options.distance_m.value_or(0.0)};
    result = Probe(tables, std::span(&query, 1)).front();
    if (spectral) at_wavelengths = ProbeSpectralTablesAtWavelengths(device, atmosphere, precompute, load, query);
  }

  nlohmann::json json;
  json["source"] = options.reference ? "reference" : "tables";
  json["lut"] = options.tables.lut;
  json["atmosphere"] = atmosphere.name;
  json["colour"] = options.tables.colour;
  // The quantities are given at wavelengths: the atmosphere's three (rgb), or the spectral
  // sampling's, where the spectral tables' own channels, linear sRGB, are under "linear_srgb".
  json["channels"] = "wavelengths_nm";
  json["altitude_m"] = options.view.altitude_m;
  json["view_zenith_deg"] = options.view.view_zenith_deg;
  json["sun_zenith_deg"] = options.view.sun_zenith_deg;
  json["azimuth_deg"] = options.view.azimuth_deg;
  if (to_point) json["distance_m"] = *options.distance_m;
  if (spectral) {
    json["wavelengths_nm"] = sampling.wavelengths_nm();
    json.update(SpectrumJson(at_wavelengths, to_point, options.reference));
    json["linear_srgb"] = QuantitiesJson(result, to_point, options.reference);
  } else {
    json["wavelengths_nm"] = ToJson(atmosphere.wavelengths_nm);
    json.update(QuantitiesJson(result, to_point, options.reference));
  }
  json["sky_radiance_colour"] = ColourJson(result.sky_radiance, "luminance_cd_m2");
  json["sun_irradiance_colour"] = ColourJson(result.sun_irradiance, "illuminance_lux");
  json["sky_irradiance_colour"] = ColourJson(result.sky_irradiance, "illuminance_lux");
  if (to_point) json["radiance_to_point_colour"] = ColourJson(result.radiance_to_point, "luminance_cd_m2");
  std::printf("%s\n", json.dump(2).c_str());
}

}  // namespace

void AddProbeCommand(CLI::App& app) {
  auto options = std::make_shared<ProbeOptions>();
  CLI::App* command = app.add_subcommand("probe", "Print the sky seen by one camera along one ray, as JSON");
  command->add_option("--altitude-m", options->view.altitude_m, "Camera altitude above the ground (m)")
      ->required();
  command->add_option("--view-zenith-deg", options->view.view_zenith_deg, "View zenith angle (deg)")
      ->required();
  command->add_option("--sun-zenith-deg", options->view.sun_zenith_deg, "Sun zenith angle (deg)")
      ->required();
  command->add_option("--azimuth-deg", options->view.azimuth_deg,
                      "Angle between the horizontal parts of view and sun (deg); 0: toward the sun")
      ->required();
  command->add_option("--distance-m", options->distance_m,
                      "Also report radiance_to_point and transmittance_to_point for this distance (m)");
  command->add_flag("--reference", options->reference,
                    "Compute with the CPU double-precision reference instead of the tables");
  options->tables.AddTo(*command);
  command->callback([options] { RunProbe(*options); });
}

}  // namespace aerial::cli
