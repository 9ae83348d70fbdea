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

void RunProbe(const ProbeOptions& options) {
  AtmosphereParameters atmosphere = options.tables.LoadAtmosphere();
  ValidateViewAngles(options.view, atmosphere);
  // The shaders take the distance as a float; a ray ends at the atmosphere's boundary long before
  // 1e9 m (the longest, grazing Earth's, is under 2e6 m), so larger values are refused.
  if (options.distance_m && !(*options.distance_m >= 0.0 && *options.distance_m <= 1e9))
    throw aerial::Error("--distance-m", aerial::TomlFloat(*options.distance_m), "a distance in [0, 1e9] meters");
  PrecomputeOptions precompute = options.tables.MakePrecomputeOptions();
  RayParameters ray = ToRayParameters(options.view, atmosphere);

  ProbeResult result;
  if (options.reference) {
    result = precompute.colour == ColourMode::kSpectral
                 ? ProbeReferenceSpectral(atmosphere, ray, options.distance_m, precompute.RepresentedOrders(),
                                          precompute.spectral_wavelengths)
                 : ProbeReference(atmosphere, ray, options.distance_m, precompute.RepresentedOrders());
  } else {
    Device device(options.tables.MakeDeviceOptions());
    options.tables.MakeMemoryBudget(device.largest_heap_bytes()).Check(TableMemoryUses(precompute));
    Tables tables = Tables::LoadOrPrecompute(device, atmosphere, precompute, options.tables.MakeLoadOptions());
    ProbeQuery query{ray, options.distance_m.value_or(0.0)};
    result = Probe(tables, std::span(&query, 1)).front();
  }

  nlohmann::json json;
  json["source"] = options.reference ? "reference" : "tables";
  json["lut"] = options.tables.lut;
  json["atmosphere"] = atmosphere.name;
  json["colour"] = options.tables.colour;
  if (precompute.colour == ColourMode::kSpectral)
    json["wavelengths_nm"] = spectrum::SpectralSampling(precompute.spectral_wavelengths).wavelengths_nm();
  else
    json["wavelengths_nm"] = ToJson(atmosphere.wavelengths_nm);
  json["altitude_m"] = options.view.altitude_m;
  json["view_zenith_deg"] = options.view.view_zenith_deg;
  json["sun_zenith_deg"] = options.view.sun_zenith_deg;
  json["azimuth_deg"] = options.view.azimuth_deg;
  json["sky_radiance"] = ToJson(result.sky_radiance);
  json["transmittance"] = ToJson(result.transmittance);
  json["sun_irradiance"] = ToJson(result.sun_irradiance);
  json["sky_irradiance"] = ToJson(result.sky_irradiance);
  json["solar_radiance"] = ToJson(result.solar_radiance);
  json["sky_radiance_colour"] = ColourJson(result.sky_radiance, "luminance_cd_m2");
  json["sun_irradiance_colour"] = ColourJson(result.sun_irradiance, "illuminance_lux");
  json["sky_irradiance_colour"] = ColourJson(result.sky_irradiance, "illuminance_lux");
  if (options.distance_m) {
    json["distance_m"] = *options.distance_m;
    json["radiance_to_point_colour"] = ColourJson(result.radiance_to_point, "luminance_cd_m2");
    json["radiance_to_point"] = ToJson(result.radiance_to_point);
    json["transmittance_to_point"] = ToJson(result.transmittance_to_point);
  }
  if (options.reference) {  // the Monte Carlo noise of the orders >= 2
    json["sky_radiance_std_error"] = ToJson(result.sky_radiance_std_error);
    json["sky_irradiance_std_error"] = ToJson(result.sky_irradiance_std_error);
    if (options.distance_m) json["radiance_to_point_std_error"] = ToJson(result.radiance_to_point_std_error);
  }
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
