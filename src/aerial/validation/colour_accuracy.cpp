#include "aerial/validation/colour_accuracy.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "aerial/core/atomic_file.h"
#include "aerial/error.h"
#include "aerial/probe/spectral_reference.h"
#include "aerial/spectrum/colour.h"
#include "aerial/spectrum/spectral_sampling.h"
#include "aerial/validation/reference_file.h"

namespace aerial::validation {
namespace {

constexpr int kFileVersion = 1;
constexpr double kFloorFraction = 1e-4;
// The noise goal: a quarter of the band's targets, so that an error against the reference says
// whether the target is met.
constexpr double kNoiseGoalFraction = 0.25;

double Luminance(const Spectrum& linear_srgb) {
  return spectrum::Multiply(spectrum::XyzFromLinearSrgb(), linear_srgb)[1];
}

const ColourBand& BandNamed(const std::string& name) {
  for (const ColourBand& band : ColourBands())
    if (band.name == name) return band;
  throw Error("band", name, "a band of ColourBands()");
}

ProbeResult ProbeView(const AtmosphereParameters& atmosphere, const ColourReference& reference, const ViewAngles& view,
                      int paths) {
  return ProbeReferenceSpectral(atmosphere, ToRayParameters(view, atmosphere), kColourPointDistanceM,
                                spectrum::SpectralSampling::Midpoint(reference.wavelengths),
                                {.orders = reference.orders, .paths_per_query = paths});
}

// Whether every compared value of a sample is within its band's noise goal.
bool MeetsNoiseGoal(const ColourSample& s, const ColourBand& band,
                    const std::array<double, kColourQuantities>& floors) {
  for (int q = 0; q < kColourQuantities; ++q) {
    if (!(Luminance(s.value[q]) > floors[q])) continue;
    if (ChromaticityNoise(s.value[q], s.std_error[q]) > kNoiseGoalFraction * band.chromaticity_target ||
        LuminanceNoise(s.value[q], s.std_error[q]) > kNoiseGoalFraction * band.luminance_target)
      return false;
  }
  return true;
}

bool SameView(const ViewAngles& a, const ViewAngles& b) {
  return a.altitude_m == b.altitude_m && a.view_zenith_deg == b.view_zenith_deg &&
         a.sun_zenith_deg == b.sun_zenith_deg && a.azimuth_deg == b.azimuth_deg;
}

nlohmann::json ToJson(const Spectrum& s) { return {s[0], s[1], s[2]}; }
Spectrum SpectrumFrom(const nlohmann::json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}
double Max(const std::vector<double>& values) {
  return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}
template <typename Field>
std::vector<double> Errors(const std::vector<ColourError>& errors, Field field) {
  std::vector<double> values;
  for (const ColourError& e : errors) values.push_back(e.*field);
  return values;
}

}  // namespace

std::string ToString(ColourQuantity quantity) {
  switch (quantity) {
    case ColourQuantity::kSkyRadiance: return "sky radiance";
    case ColourQuantity::kRadianceToPoint: return "radiance to a point";
    case ColourQuantity::kSkyIrradiance: return "sky irradiance";
    case ColourQuantity::kSunIrradiance: return "sun irradiance";
  }
  return "";
}

std::array<Spectrum, kColourQuantities> ColourQuantities(const ProbeResult& r) {
  return {r.sky_radiance, r.radiance_to_point, r.sky_irradiance, r.sun_irradiance};
}

std::array<Spectrum, kColourQuantities> ColourStdErrors(const ProbeResult& r) {
  return {r.sky_radiance_std_error, r.radiance_to_point_std_error, r.sky_irradiance_std_error, Spectrum{}};
}

const std::vector<ColourBand>& ColourBands() {
  static const std::vector<ColourBand> bands = {{"day (sun zenith 0-60)", {0.0, 30.0, 60.0}, 0.001, 0.01},
                                                {"low sun (85-92)", {85.0, 88.0, 90.0, 92.0}, 0.001, 0.03},
                                                {"twilight (93-98)", {93.0, 95.0, 96.0, 98.0}, 0.0015, 0.03}};
  return bands;
}

std::vector<ViewAngles> ColourViews(const ColourBand& band) {
  std::vector<ViewAngles> views;
  for (double sun : band.sun_zeniths_deg)
    for (double altitude : {0.0, 10e3})
      for (double zenith : {0.0, 60.0, 85.0})
        for (double azimuth : {0.0, 180.0}) views.push_back({altitude, zenith, sun, azimuth});
  return views;
}

// By a one-sigma step of each channel in turn.
double ChromaticityNoise(const Spectrum& linear_srgb, const Spectrum& std_error) {
  const auto& to_xyz = spectrum::XyzFromLinearSrgb();
  const Spectrum xyz = spectrum::Multiply(to_xyz, linear_srgb);
  double variance = 0.0;
  for (int c = 0; c < 3; ++c) {
    Spectrum stepped = linear_srgb;
    stepped[c] += std_error[c];
    const double d = spectrum::ChromaticityDistance(spectrum::Multiply(to_xyz, stepped), xyz);
    variance += d * d;
  }
  return std::sqrt(variance);
}

double LuminanceNoise(const Spectrum& linear_srgb, const Spectrum& std_error) {
  const auto& to_xyz = spectrum::XyzFromLinearSrgb();
  double variance = 0.0;
  for (int c = 0; c < 3; ++c) variance += std::pow(to_xyz[1][c] * std_error[c], 2.0);
  const double y = Luminance(linear_srgb);
  return y > 0.0 ? std::sqrt(variance) / y : 0.0;
}

size_t ColourReferenceViewCount() {
  size_t total = 0;
  for (const ColourBand& band : ColourBands()) total += ColourViews(band).size();
  return total;
}

bool IsComplete(const ColourReference& reference) {
  return reference.samples.size() == ColourReferenceViewCount();
}

void ContinueColourReference(const AtmosphereParameters& atmosphere, ColourReference& reference,
                             const ColourProgress& progress,
                             const std::function<void(const ColourReference&)>& after_each_sample) {
  const size_t total = ColourReferenceViewCount();
  if (reference.samples.size() > total)
    throw Error("colour reference samples", std::to_string(reference.samples.size()), "at most " + std::to_string(total));
  size_t index = 0;
  for (const ColourBand& band : ColourBands()) {
    for (const ViewAngles& view : ColourViews(band)) {
      if (index < reference.samples.size()) {
        const ColourSample& held = reference.samples[index++];
        if (held.band != band.name || !SameView(held.view, view))
          throw Error("colour reference sample", std::to_string(index - 1), "the view ColourViews() puts there");
        continue;
      }
      ColourSample sample{.band = band.name, .view = view};
      for (int paths = reference.paths_per_query;; paths *= 4) {
        const ProbeResult r = ProbeView(atmosphere, reference, view, paths);
        sample.value = ColourQuantities(r);
        sample.std_error = ColourStdErrors(r);
        sample.paths = paths;
        if (reference.samples.empty() && paths == reference.paths_per_query) {  // noon's zenith, the first view
          for (int q = 0; q < kColourQuantities; ++q)
            reference.floors[q] = kFloorFraction * Luminance(sample.value[q == 1 ? 0 : q]);
        }
        if (MeetsNoiseGoal(sample, band, reference.floors) ||
            paths >= kMaxColourPathsFactor * reference.paths_per_query)
          break;
      }
      reference.samples.push_back(sample);
      ++index;
      if (after_each_sample) after_each_sample(reference);
      if (progress) progress(index, total, sample.paths);
    }
  }
}

ColourSample RecomputeColourSample(const AtmosphereParameters& atmosphere, const ColourReference& reference,
                                   const ColourSample& sample) {
  const ProbeResult r = ProbeView(atmosphere, reference, sample.view, sample.paths);
  return {sample.band, sample.view, ColourQuantities(r), ColourStdErrors(r), sample.paths};
}

void WriteColourReference(const ColourReference& reference, const std::filesystem::path& path) {
  nlohmann::json j;
  j["version"] = kFileVersion;
  j["wavelengths"] = reference.wavelengths;
  j["orders"] = reference.orders;
  j["paths_per_query"] = reference.paths_per_query;
  j["floors"] = reference.floors;
  for (const ColourSample& s : reference.samples) {
    nlohmann::json values, errors;
    for (int q = 0; q < kColourQuantities; ++q) {
      values.push_back(ToJson(s.value[q]));
      errors.push_back(ToJson(s.std_error[q]));
    }
    j["samples"].push_back({{"band", s.band},
                            {"view", {s.view.altitude_m, s.view.view_zenith_deg, s.view.sun_zenith_deg,
                                      s.view.azimuth_deg}},
                            {"value", values},
                            {"std_error", errors},
                            {"paths", s.paths}});
  }
  WriteFileAtomically(path, j.dump(1));
}

ColourReference ReadColourReference(const std::filesystem::path& path) {
  try {
    const nlohmann::json j = ReadReferenceJson(path, kFileVersion);
    ColourReference r{.wavelengths = j.at("wavelengths").get<int>(),
                      .orders = j.at("orders").get<int>(),
                      .paths_per_query = j.at("paths_per_query").get<int>(),
                      .floors = j.at("floors").get<std::array<double, kColourQuantities>>()};
    for (const nlohmann::json& s : j.at("samples")) {
      const nlohmann::json& v = s.at("view");
      ColourSample sample{.band = s.at("band").get<std::string>(),
                          .view = {v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>(),
                                   v.at(3).get<double>()},
                          .paths = s.at("paths").get<int>()};
      BandNamed(sample.band);
      for (int q = 0; q < kColourQuantities; ++q) {
        sample.value[q] = SpectrumFrom(s.at("value").at(q));
        sample.std_error[q] = SpectrumFrom(s.at("std_error").at(q));
      }
      r.samples.push_back(sample);
    }
    return r;
  } catch (const nlohmann::json::exception& e) {
    throw Error("colour reference file", path.string(), std::string("valid JSON of this tool (") + e.what() + ")");
  }
}

ColourError CompareColour(const Spectrum& measured, const Spectrum& expected) {
  const auto& to_xyz = spectrum::XyzFromLinearSrgb();
  const Spectrum m = spectrum::Multiply(to_xyz, measured), e = spectrum::Multiply(to_xyz, expected);
  return {spectrum::ChromaticityDistance(m, e), std::abs(m[1] / e[1] - 1.0)};
}

double ColourRegion::MedianChromaticity() const { return Median(Errors(errors, &ColourError::chromaticity)); }
double ColourRegion::MaxChromaticity() const { return Max(Errors(errors, &ColourError::chromaticity)); }
double ColourRegion::MedianLuminance() const { return Median(Errors(errors, &ColourError::luminance)); }
double ColourRegion::MaxLuminance() const { return Max(Errors(errors, &ColourError::luminance)); }
double ColourRegion::MaxChromaticityNoise() const { return Max(chromaticity_noise); }
const ViewAngles& ColourRegion::WorstChromaticityView() const {
  auto worst = std::max_element(errors.begin(), errors.end(), [](const ColourError& a, const ColourError& b) {
    return a.chromaticity < b.chromaticity;
  });
  return views.at(size_t(worst - errors.begin()));
}

std::vector<ColourRegion> CompareColourWithTables(const Tables& tables, const ColourReference& reference) {
  std::vector<ProbeQuery> queries;
  for (const ColourSample& s : reference.samples)
    queries.push_back({ToRayParameters(s.view, tables.atmosphere()), kColourPointDistanceM});
  const std::vector<ProbeResult> results = Probe(tables, queries);
  std::vector<ColourRegion> regions;
  for (const ColourBand& band : ColourBands())
    for (double altitude : {0.0, 10e3})
      for (int q = 0; q < kColourQuantities; ++q) regions.push_back({ColourQuantity(q), band.name, altitude, {}, {}});
  for (size_t i = 0; i < results.size(); ++i) {
    const ColourSample& s = reference.samples[i];
    const std::array<Spectrum, kColourQuantities> measured = ColourQuantities(results[i]);
    for (ColourRegion& region : regions) {
      if (region.band != s.band || region.altitude_m != s.view.altitude_m) continue;
      const int q = int(region.quantity);
      // The sun below the horizon, the sky deep in the Earth's shadow: no colour to compare.
      if (!(Luminance(s.value[q]) > reference.floors[q])) continue;
      region.errors.push_back(CompareColour(measured[q], s.value[q]));
      region.chromaticity_noise.push_back(ChromaticityNoise(s.value[q], s.std_error[q]));
      region.views.push_back(s.view);
    }
  }
  return regions;
}

std::string FormatColourAccuracy(const std::string& tables_name, const std::vector<ColourRegion>& regions) {
  std::string text =
      "| tables | band | camera | quantity | values | du'v' median / max | luminance median / max | worst du'v' at "
      "(view zenith, sun zenith, azimuth) | reference du'v' noise |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const ColourRegion& r : regions) {
    if (r.errors.empty()) continue;
    const ViewAngles& worst = r.WorstChromaticityView();
    char row[320];
    std::snprintf(row, sizeof row, "| %s | %s | %.0f km | %s | %zu | %.4f / %.4f | %.2f%% / %.2f%% | %.0f, %.0f, %.0f | %.4f |\n",
                  tables_name.c_str(), r.band.c_str(), r.altitude_m / 1000.0, ToString(r.quantity).c_str(),
                  r.errors.size(), r.MedianChromaticity(), r.MaxChromaticity(), 100.0 * r.MedianLuminance(),
                  100.0 * r.MaxLuminance(), worst.view_zenith_deg, worst.sun_zenith_deg, worst.azimuth_deg,
                  r.MaxChromaticityNoise());
    text += row;
  }
  return text;
}

}  // namespace aerial::validation
