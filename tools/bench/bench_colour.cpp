// aerial_bench_colour: the tables' colour against the spectral CPU reference (ProbeReferenceSpectral,
// all orders), by sun band: chromaticity distance du'v' and relative luminance error of the sky
// radiance, the radiance to a point 10 km away, the sky irradiance and the sun's irradiance, for
// rgb tables and spectral tables side by side (docs/colour.md). The reference takes minutes and is
// kept in --reference-file. As over the physical-sky grid (validation/sky_accuracy.h), values below
// 1e-4 of their noon value are not compared, and each reference value takes more paths until its
// chromaticity's standard error is a quarter of its band's target.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "aerial/cli/common_options.h"
#include "aerial/core/atomic_file.h"
#include "aerial/error.h"
#include "aerial/probe.h"
#include "aerial/probe/spectral_reference.h"
#include "aerial/spectrum/colour.h"
#include "aerial/tables.h"
#include "bench_main.h"

namespace {

using aerial::Spectrum;

constexpr double kPointDistanceM = 10000.0;
constexpr int kQuantities = 4;
const char* const kQuantityNames[kQuantities] = {"sky radiance", "radiance to a point", "sky irradiance",
                                                 "sun irradiance"};

struct Band {
  const char* name;
  std::vector<double> sun_zenith_deg;
  double chromaticity_target;
};
// Daylight and the low sun, the two targets (du'v' <= 0.003 and luminance <= 1% in daylight,
// du'v' <= 0.008 at sun zenith 85-95 degrees). The first view of the first band is noon's zenith.
const std::vector<Band> kBands = {{"day (sun zenith 0-60)", {0.0, 30.0, 60.0}, 0.003},
                                  {"low sun (85-95)", {85.0, 88.0, 90.0, 92.0, 95.0}, 0.008}};

// Below this fraction of its noon value (the sky's radiance at noon's zenith for both radiances,
// as the physical-sky grid has it) a value's colour is not compared: 1e-4 of noon is where the
// tables' own error is no longer held to a bound (docs/accuracy.md).
constexpr double kFloorFraction = 1e-4;
// A reference value takes 4, 16 then 64 times the paths while its chromaticity's standard error
// is above a quarter of its band's target.
constexpr int kMaxPathsFactor = 64;
constexpr int kReferenceFormat = 2;

std::vector<aerial::ViewAngles> Views(const Band& band) {
  std::vector<aerial::ViewAngles> views;
  for (double sun : band.sun_zenith_deg)
    for (double altitude : {0.0, 10000.0})
      for (double zenith : {0.0, 60.0, 85.0})
        for (double azimuth : {0.0, 180.0}) views.push_back({altitude, zenith, sun, azimuth});
  return views;
}

std::array<Spectrum, kQuantities> Quantities(const aerial::ProbeResult& r) {
  return {r.sky_radiance, r.radiance_to_point, r.sky_irradiance, r.sun_irradiance};
}
// The reference's standard errors, in the same order (the sun's irradiance is a quadrature).
std::array<Spectrum, kQuantities> StdErrors(const aerial::ProbeResult& r) {
  return {r.sky_radiance_std_error, r.radiance_to_point_std_error, r.sky_irradiance_std_error, Spectrum{}};
}

double Luminance(const Spectrum& linear_srgb) {
  return aerial::spectrum::Multiply(aerial::spectrum::XyzFromLinearSrgb(), linear_srgb)[1];
}

// The standard error of a colour's u'v' from its channels' independent standard errors, by a
// one-sigma step of each channel.
double ChromaticityNoise(const Spectrum& linear_srgb, const Spectrum& std_error) {
  const auto& to_xyz = aerial::spectrum::XyzFromLinearSrgb();
  const Spectrum xyz = aerial::spectrum::Multiply(to_xyz, linear_srgb);
  double variance = 0.0;
  for (int c = 0; c < 3; ++c) {
    Spectrum stepped = linear_srgb;
    stepped[c] += std_error[c];
    double d = aerial::spectrum::ChromaticityDistance(aerial::spectrum::Multiply(to_xyz, stepped), xyz);
    variance += d * d;
  }
  return std::sqrt(variance);
}

nlohmann::json ToJson(const Spectrum& s) { return {s[0], s[1], s[2]}; }
Spectrum FromJson(const nlohmann::json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

struct Errors {
  std::vector<double> chromaticity, luminance;
};

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
double Max(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

struct BenchOptions {
  aerial::cli::TableOptions tables;
  std::string reference_file;
  // 32768 paths: a standard error of ~0.3% per channel for orders >= 2, ~0.0005 in u'v'.
  int paths = 32768;
};

void Bench(const BenchOptions& cli) {
  aerial::AtmosphereParameters atmosphere = cli.tables.LoadAtmosphere();
  aerial::PrecomputeOptions spectral = cli.tables.MakePrecomputeOptions();
  spectral.colour = aerial::ColourMode::kSpectral;
  aerial::PrecomputeOptions rgb = spectral;
  rgb.colour = aerial::ColourMode::kRgb;

  // The reference: per band and view, the quantities and the paths they took; computed or read back.
  nlohmann::json reference;
  if (!cli.reference_file.empty() && std::filesystem::exists(cli.reference_file)) {
    std::ifstream in(cli.reference_file);
    reference = nlohmann::json::parse(in);
    if (reference.value("format", 1) != kReferenceFormat)
      throw aerial::Error("--reference-file", cli.reference_file, "a reference in this bench's format (delete it to recompute)");
    if (reference.value("wavelengths", 0) != spectral.spectral_wavelengths ||
        reference.value("orders", 0) != spectral.RepresentedOrders())
      throw aerial::Error("--reference-file", cli.reference_file, "a reference made with these --wavelengths");
  } else {
    reference["format"] = kReferenceFormat;
    reference["wavelengths"] = spectral.spectral_wavelengths;
    reference["orders"] = spectral.RepresentedOrders();
    reference["paths"] = cli.paths;
    std::array<double, kQuantities> floors{};  // luminance; 0 until noon's values are in
    for (const Band& band : kBands) {
      std::vector<aerial::ViewAngles> views = Views(band);
      for (size_t i = 0; i < views.size(); ++i) {
        aerial::reference::MonteCarloOptions monte_carlo{.paths_per_query = cli.paths};
        aerial::ProbeResult r;
        while (true) {
          r = aerial::ProbeReferenceSpectral(atmosphere, aerial::ToRayParameters(views[i], atmosphere),
                                             kPointDistanceM, spectral.RepresentedOrders(),
                                             spectral.spectral_wavelengths, monte_carlo);
          double noise = 0.0;
          for (int q = 0; q < kQuantities; ++q)
            if (Luminance(Quantities(r)[q]) > floors[q])
              noise = std::max(noise, ChromaticityNoise(Quantities(r)[q], StdErrors(r)[q]));
          if (noise <= 0.25 * band.chromaticity_target || monte_carlo.paths_per_query >= kMaxPathsFactor * cli.paths)
            break;
          monte_carlo.paths_per_query *= 4;
        }
        if (floors[0] == 0.0) {
          const std::array<Spectrum, kQuantities> noon = Quantities(r);
          floors = {kFloorFraction * Luminance(noon[0]), kFloorFraction * Luminance(noon[0]),
                    kFloorFraction * Luminance(noon[2]), kFloorFraction * Luminance(noon[3])};
          reference["floors"] = floors;
        }
        nlohmann::json values;
        for (const Spectrum& q : Quantities(r)) values.push_back(ToJson(q));
        reference["views"][band.name].push_back({{"values", values}, {"paths", monte_carlo.paths_per_query}});
        std::fprintf(stderr, "reference %s: %zu / %zu (%d paths)\n", band.name, i + 1, views.size(),
                     monte_carlo.paths_per_query);
      }
    }
    if (!cli.reference_file.empty()) aerial::WriteFileAtomically(cli.reference_file, reference.dump(1));
  }
  const std::array<double, kQuantities> floors = reference["floors"].get<std::array<double, kQuantities>>();

  aerial::Device device(cli.tables.MakeDeviceOptions());
  std::printf("reference: spectral, %d wavelengths, all orders\n\n", spectral.spectral_wavelengths);
  std::printf("| tables | band | quantity | du'v' median / max | luminance error median / max |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const aerial::PrecomputeOptions& options : {rgb, spectral}) {
    aerial::Tables tables = aerial::Tables::LoadOrPrecompute(device, atmosphere, options, cli.tables.MakeLoadOptions());
    for (const Band& band : kBands) {
      std::vector<aerial::ProbeQuery> queries;
      for (const aerial::ViewAngles& view : Views(band))
        queries.push_back({aerial::ToRayParameters(view, atmosphere), kPointDistanceM});
      std::vector<aerial::ProbeResult> results = aerial::Probe(tables, queries);
      std::array<Errors, kQuantities> errors;
      for (size_t i = 0; i < results.size(); ++i) {
        std::array<Spectrum, kQuantities> measured = Quantities(results[i]);
        for (int q = 0; q < kQuantities; ++q) {
          Spectrum expected = FromJson(reference["views"][band.name][i]["values"][q]);
          const auto& to_xyz = aerial::spectrum::XyzFromLinearSrgb();
          Spectrum xyz_expected = aerial::spectrum::Multiply(to_xyz, expected);
          // The sun below the horizon, the sky deep in the Earth's shadow: no colour to compare.
          if (xyz_expected[1] <= floors[q]) continue;
          Spectrum xyz_measured = aerial::spectrum::Multiply(to_xyz, measured[q]);
          errors[q].chromaticity.push_back(aerial::spectrum::ChromaticityDistance(xyz_measured, xyz_expected));
          errors[q].luminance.push_back(std::abs(xyz_measured[1] / xyz_expected[1] - 1.0) * 100.0);
        }
      }
      for (int q = 0; q < kQuantities; ++q)
        std::printf("| %s | %s | %s | %.4f / %.4f | %.2f%% / %.2f%% |\n",
                    aerial::ToString(options.colour).c_str(), band.name, kQuantityNames[q],
                    Median(errors[q].chromaticity), Max(errors[q].chromaticity), Median(errors[q].luminance),
                    Max(errors[q].luminance));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"aerial_bench_colour: rgb and spectral tables against the spectral CPU reference, in colour"};
  BenchOptions cli;
  cli.tables.AddTo(app);
  app.add_option("--paths", cli.paths, "Reference paths per query")->check(CLI::Range(512, 1 << 24));
  app.add_option("--reference-file", cli.reference_file,
                 "Reference values: read if the file exists, else computed and written there (JSON)");
  return aerial::bench::ParseAndRun(app, argc, argv, "aerial_bench_colour", [&] { Bench(cli); });
}
