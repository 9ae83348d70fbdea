#include "aerial/validation/sky_accuracy.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "aerial/core/atomic_file.h"
#include "aerial/error.h"
#include "aerial/probe.h"
#include "aerial/reference/reference.h"
#include "aerial/validation/reference_file.h"

namespace aerial::validation {
namespace {

constexpr int kFileVersion = 2;
constexpr double kFloorFraction = 1e-4;

// One reference query: its quantity and view.
struct Query {
  SkyQuantity quantity;
  std::string band;
  ViewAngles view;
  double noise_goal;  // NoiseGoal(band, quantity)
};

std::vector<Query> Queries(const AtmosphereParameters& atmosphere, const SkyGrid& grid) {
  std::vector<Query> queries;
  reference::Reference model(atmosphere);
  for (const SunBand& band : grid.bands) {
    for (double altitude : grid.altitudes_m) {
      for (double sun : band.sun_zeniths_deg) {
        queries.push_back(
            {SkyQuantity::kSkyIrradiance, band.name, {altitude, 0.0, sun, 0.0},
             NoiseGoal(band, SkyQuantity::kSkyIrradiance)});
        for (double view_zenith : grid.view_zeniths_deg) {
          for (double azimuth : grid.azimuths_deg) {
            ViewAngles view{altitude, view_zenith, sun, azimuth};
            queries.push_back(
                {SkyQuantity::kSkyRadiance, band.name, view, NoiseGoal(band, SkyQuantity::kSkyRadiance)});
            // A point 10 km along the ray, where the ray is that long.
            RayParameters ray = ToRayParameters(view, atmosphere);
            if (model.DistanceToBoundary(ray.r, ray.mu) > grid.point_distance_m)
              queries.push_back({SkyQuantity::kRadianceToPoint, band.name, view,
                                 NoiseGoal(band, SkyQuantity::kRadianceToPoint)});
          }
        }
      }
    }
  }
  return queries;
}

reference::Estimate Evaluate(const reference::Reference& model, const AtmosphereParameters& atmosphere,
                             SkyQuantity quantity, const ViewAngles& view, double distance_m, int orders,
                             const reference::MonteCarloOptions& options) {
  RayParameters ray = ToRayParameters(view, atmosphere);
  switch (quantity) {
    case SkyQuantity::kSkyRadiance:
      return model.ComputeRadiance(ray.r, ray.mu, ray.mu_s, ray.nu, orders, INFINITY, options);
    case SkyQuantity::kRadianceToPoint:
      return model.ComputeRadiance(ray.r, ray.mu, ray.mu_s, ray.nu, orders, distance_m, options);
    case SkyQuantity::kSkyIrradiance:
      return model.ComputeSkyIrradiance(ray.r, ray.mu_s, orders, options);
  }
  return {};
}

double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

std::string Describe(const ViewAngles& v) {
  char text[128];
  std::snprintf(text, sizeof text, "altitude %.0f m, view zenith %.1f, sun zenith %.1f, azimuth %.0f",
                v.altitude_m, v.view_zenith_deg, v.sun_zenith_deg, v.azimuth_deg);
  return text;
}

nlohmann::json ToJson(const Spectrum& s) { return {s[0], s[1], s[2]}; }
Spectrum SpectrumFrom(const nlohmann::json& j) { return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()}; }

double ProbedValue(const ProbeResult& result, SkyQuantity quantity, int c) {
  switch (quantity) {
    case SkyQuantity::kSkyRadiance: return result.sky_radiance[c];
    case SkyQuantity::kRadianceToPoint: return result.radiance_to_point[c];
    case SkyQuantity::kSkyIrradiance: return result.sky_irradiance[c];
  }
  return 0.0;
}

}  // namespace

std::string ToString(SkyQuantity quantity) {
  switch (quantity) {
    case SkyQuantity::kSkyRadiance: return "sky radiance";
    case SkyQuantity::kRadianceToPoint: return "radiance to a point 10 km away";
    case SkyQuantity::kSkyIrradiance: return "sky irradiance";
  }
  return "?";
}

double NoiseGoal(const SunBand& band, SkyQuantity quantity) {
  return quantity == SkyQuantity::kSkyIrradiance ? std::min(band.noise_goal, kIrradianceNoiseGoal)
                                                 : band.noise_goal;
}

SkyGrid SkyGrid::Full() {
  return {.altitudes_m = {0.0, 10e3, 50e3},
          .view_zeniths_deg = {0.0, 30.0, 60.0, 80.0, 85.0, 88.0, 89.5, 90.5, 92.0, 95.0, 100.0, 120.0, 150.0, 180.0},
          .azimuths_deg = {0.0, 60.0, 120.0, 180.0},
          .bands = {{"day (sun zenith 0-60)", {0.0, 30.0, 45.0, 60.0}, 0.0025},
                    {"afternoon (60-85)", {70.0, 80.0}},
                    {"low sun (85-95)", {85.0, 87.0, 88.0, 89.0, 90.0, 91.0, 92.0, 93.0, 95.0}, 0.0075},
                    {"twilight (95-108)", {96.0, 98.0, 100.0, 102.0, 104.0, 106.0, 108.0}}}};
}

SkyGrid SkyGrid::Quick() {
  return {.altitudes_m = {0.0, 10e3, 50e3},
          .view_zeniths_deg = {0.0, 60.0, 88.0, 92.0, 120.0},
          .azimuths_deg = {0.0, 90.0, 180.0},
          .bands = {{"day (sun zenith 0-60)", {0.0, 45.0, 60.0}, 0.0025},
                    {"afternoon (60-85)", {75.0}},
                    {"low sun (85-95)", {85.0, 88.0, 90.0, 92.0, 95.0}, 0.0075},
                    {"twilight (95-108)", {97.0, 100.0, 104.0, 108.0}}}};
}

SkyReference ComputeSkyReference(const AtmosphereParameters& atmosphere, const SkyGrid& grid, int orders,
                                 const reference::MonteCarloOptions& options, const SkyProgress& progress) {
  reference::Reference model(atmosphere);
  std::vector<Query> queries = Queries(atmosphere, grid);
  SkyReference result{.orders = orders, .paths_per_query = options.paths_per_query,
                      .point_distance_m = grid.point_distance_m};
  // Radiances: 1e-4 of the noon zenith sky; irradiance: of the noon sky irradiance.
  reference::Estimate noon_sky = Evaluate(model, atmosphere, SkyQuantity::kSkyRadiance, {0.0, 0.0, 0.0, 0.0},
                                          grid.point_distance_m, orders, options);
  reference::Estimate noon_irradiance = Evaluate(model, atmosphere, SkyQuantity::kSkyIrradiance,
                                                 {0.0, 0.0, 0.0, 0.0}, grid.point_distance_m, orders, options);
  for (int c = 0; c < 3; ++c) {
    result.floors[size_t(SkyQuantity::kSkyRadiance)][c] = kFloorFraction * noon_sky.value[c];
    result.floors[size_t(SkyQuantity::kRadianceToPoint)][c] = kFloorFraction * noon_sky.value[c];
    result.floors[size_t(SkyQuantity::kSkyIrradiance)][c] = kFloorFraction * noon_irradiance.value[c];
  }
  for (size_t i = 0; i < queries.size(); ++i) {
    const Query& q = queries[i];
    const Spectrum& floor = result.floors[size_t(q.quantity)];
    // More paths until the noise is small beside the band's target (low sun and twilight skies
    // come from rare paths that reach the sunlit air).
    reference::MonteCarloOptions more = options;
    reference::Estimate e;
    while (true) {
      e = Evaluate(model, atmosphere, q.quantity, q.view, grid.point_distance_m, orders, more);
      double noise = 0.0;
      for (int c = 0; c < 3; ++c)
        if (e.value[c] >= floor[c]) noise = std::max(noise, e.std_error[c] / e.value[c]);
      if (noise <= q.noise_goal || more.paths_per_query >= kMaxReferencePathsFactor * options.paths_per_query) break;
      more.paths_per_query *= 4;
    }
    result.samples.push_back({q.quantity, q.band, q.view, e.value, e.std_error, more.paths_per_query});
    if (progress) progress(i + 1, queries.size());
  }
  return result;
}

reference::Estimate RecomputeSkySample(const AtmosphereParameters& atmosphere, const SkyReference& reference,
                                       const SkySample& sample) {
  reference::Reference model(atmosphere);
  return Evaluate(model, atmosphere, sample.quantity, sample.view, reference.point_distance_m, reference.orders,
                  {.paths_per_query = sample.paths});
}

void WriteSkyReference(const SkyReference& reference, const std::filesystem::path& path) {
  nlohmann::json j;
  j["version"] = kFileVersion;
  j["orders"] = reference.orders;
  j["paths_per_query"] = reference.paths_per_query;
  j["point_distance_m"] = reference.point_distance_m;
  for (const Spectrum& floor : reference.floors) j["floors"].push_back(ToJson(floor));
  for (const SkySample& s : reference.samples) {
    j["samples"].push_back({{"quantity", int(s.quantity)}, {"band", s.band},
                            {"view", {s.view.altitude_m, s.view.view_zenith_deg, s.view.sun_zenith_deg,
                                      s.view.azimuth_deg}},
                            {"value", ToJson(s.value)}, {"std_error", ToJson(s.std_error)},
                            {"paths", s.paths}});
  }
  WriteFileAtomically(path, j.dump());
}

SkyReference ReadSkyReference(const std::filesystem::path& path) {
  try {
    const nlohmann::json j = ReadReferenceJson(path, kFileVersion);
    SkyReference r{.orders = j.at("orders").get<int>(), .paths_per_query = j.at("paths_per_query").get<int>(),
                   .point_distance_m = j.at("point_distance_m").get<double>()};
    for (size_t q = 0; q < r.floors.size(); ++q) r.floors[q] = SpectrumFrom(j.at("floors").at(q));
    for (const nlohmann::json& s : j.at("samples")) {
      int quantity = s.at("quantity").get<int>();
      if (quantity < 0 || quantity > 2) throw Error("quantity", std::to_string(quantity), "0, 1 or 2", path.string());
      const nlohmann::json& v = s.at("view");
      r.samples.push_back({SkyQuantity(quantity), s.at("band").get<std::string>(),
                           {v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>(), v.at(3).get<double>()},
                           SpectrumFrom(s.at("value")), SpectrumFrom(s.at("std_error")), s.at("paths").get<int>()});
    }
    return r;
  } catch (const nlohmann::json::exception& e) {
    throw Error("sky reference file", path.string(), std::string("valid JSON of this tool (") + e.what() + ")");
  }
}

double RegionAccuracy::Median() const {
  return std::max({channels[0].median, channels[1].median, channels[2].median});
}

double RegionAccuracy::Max() const { return std::max({channels[0].max, channels[1].max, channels[2].max}); }

std::vector<RegionAccuracy> CompareSkyWithTables(const Tables& tables, const SkyReference& reference,
                                                 std::vector<Spectrum>* tables_values) {
  const AtmosphereParameters& atmosphere = tables.atmosphere();
  const double distance = reference.point_distance_m;
  std::vector<ProbeQuery> queries;
  for (const SkySample& s : reference.samples)
    queries.push_back({ToRayParameters(s.view, atmosphere), s.quantity == SkyQuantity::kRadianceToPoint ? distance : 0.0});
  std::vector<ProbeResult> results = Probe(tables, queries);
  if (tables_values) {
    tables_values->clear();
    for (size_t i = 0; i < results.size(); ++i) {
      SkyQuantity quantity = reference.samples[i].quantity;
      tables_values->push_back({ProbedValue(results[i], quantity, 0), ProbedValue(results[i], quantity, 1),
                                ProbedValue(results[i], quantity, 2)});
    }
  }

  std::vector<RegionAccuracy> regions;
  std::vector<std::array<std::vector<double>, 3>> errors;
  for (size_t i = 0; i < reference.samples.size(); ++i) {
    const SkySample& s = reference.samples[i];
    auto it = std::find_if(regions.begin(), regions.end(), [&](const RegionAccuracy& r) {
      return r.quantity == s.quantity && r.band == s.band && r.altitude_m == s.view.altitude_m;
    });
    if (it == regions.end()) {
      regions.push_back({s.quantity, s.band, s.view.altitude_m, {}});
      errors.emplace_back();
      it = regions.end() - 1;
    }
    auto& region_errors = errors[size_t(it - regions.begin())];
    for (int c = 0; c < 3; ++c) {
      if (!(s.value[c] >= reference.floors[size_t(s.quantity)][c])) continue;
      double error = std::abs(ProbedValue(results[i], s.quantity, c) - s.value[c]) / s.value[c];
      ChannelAccuracy& channel = it->channels[c];
      ++channel.samples;
      channel.max_relative_std_error = std::max(channel.max_relative_std_error, s.std_error[c] / s.value[c]);
      if (!(error <= channel.max)) {  // NaN counts as the worst
        channel.max = std::isnan(error) ? INFINITY : error;
        channel.worst = Describe(s.view);
      }
      region_errors[c].push_back(error);
    }
  }
  for (size_t r = 0; r < regions.size(); ++r)
    for (int c = 0; c < 3; ++c) regions[r].channels[c].median = Median(errors[r][c]);
  return regions;
}

std::string FormatSkyAccuracy(const std::vector<RegionAccuracy>& regions) {
  std::ostringstream out;
  out << "| quantity | sun | camera | samples | 680 nm median / max | 550 nm | 440 nm |\n"
      << "|---|---|---|---|---|---|---|\n";
  char cell[64];
  for (const RegionAccuracy& r : regions) {
    out << "| " << ToString(r.quantity) << " | " << r.band << " | " << r.altitude_m / 1000.0 << " km | "
        << r.channels[0].samples + r.channels[1].samples + r.channels[2].samples << " |";
    for (const ChannelAccuracy& c : r.channels) {
      std::snprintf(cell, sizeof cell, " %.2f%% / %.2f%% |", 100.0 * c.median, 100.0 * c.max);
      out << cell;
    }
    out << "\n";
  }
  return out.str();
}

std::string FormatWorstSamples(const std::vector<RegionAccuracy>& regions) {
  std::ostringstream out;
  const char* names[] = {"680 nm", "550 nm", "440 nm"};
  for (const RegionAccuracy& r : regions) {
    for (int c = 0; c < 3; ++c) {
      if (r.channels[c].samples == 0) continue;
      out << ToString(r.quantity) << ", " << r.band << ", " << r.altitude_m / 1000.0 << " km, " << names[c]
          << ": " << 100.0 * r.channels[c].max << "% at " << r.channels[c].worst << " (reference noise <= "
          << 100.0 * r.channels[c].max_relative_std_error << "%)\n";
    }
  }
  return out.str();
}

std::string FormatSampleErrorsCsv(const SkyReference& reference, const std::vector<Spectrum>& tables_values) {
  std::ostringstream out;
  out << "quantity,band,altitude_m,view_zenith_deg,sun_zenith_deg,azimuth_deg,channel,reference,std_error,"
         "tables,relative_error\n";
  const char* channels[] = {"680", "550", "440"};
  char row[256];
  for (size_t i = 0; i < reference.samples.size() && i < tables_values.size(); ++i) {
    const SkySample& s = reference.samples[i];
    for (int c = 0; c < 3; ++c) {
      std::snprintf(row, sizeof row, "%s,%s,%g,%g,%g,%g,%s,%.9g,%.9g,%.9g,%.6g\n", ToString(s.quantity).c_str(),
                    s.band.c_str(), s.view.altitude_m, s.view.view_zenith_deg, s.view.sun_zenith_deg,
                    s.view.azimuth_deg, channels[c], s.value[c], s.std_error[c], tables_values[i][c],
                    tables_values[i][c] / s.value[c] - 1.0);
      out << row;
    }
  }
  return out.str();
}

}  // namespace aerial::validation
