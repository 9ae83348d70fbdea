#include "aerial/bench/results_files.h"

#include <cstdio>
#include <sstream>

#include "aerial/bench/variant_comparison.h"

namespace aerial::bench {

using validation::ErrorStats;
using validation::PixelClass;

const char* const kErrorDefinition =
    "per pixel and channel e = |actual - expected| / max(|expected|, floor), floor = 1e-3 x the mean "
    "|expected| of that channel over the pixel class; rel_rmse = sqrt(mean e^2) and rel_max = max e "
    "over the class's pixels and 3 channels";

namespace {

nlohmann::json ErrorJson(const ErrorStats& e) {
  if (e.pixels == 0) return {{"pixels", 0}, {"rel_rmse", nullptr}, {"rel_max", nullptr}};
  return {
      {"pixels", e.pixels}, {"rel_rmse", e.per_pixel_rel_rmse}, {"rel_max", e.rel_max}, {"max_at", {e.max_x, e.max_y}}};
}

nlohmann::json ResolutionJson(const TableResolution& r) {
  return {{"transmittance_mu_r", {r.transmittance_mu, r.transmittance_r}},
          {"irradiance_mu_s_r", {r.irradiance_mu_s, r.irradiance_r}},
          {"scattering_r_mu_mu_s_nu", {r.scattering_r, r.scattering_mu, r.scattering_mu_s, r.scattering_nu}}};
}

nlohmann::json FramePassesJson(const std::vector<RunResult>& frames) {
  nlohmann::json passes = nlohmann::json::object();
  for (const Series& s : GroupPasses(frames, [](const std::string& pass) { return pass; }))
    passes[s.name] = Summarize(s.ms).median;
  return passes;
}

// A figure that was not measured is null.
nlohmann::json OrNull(std::optional<double> v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

nlohmann::json EntryJson(const VariantResult& r) {
  nlohmann::json entry = VariantJson(r.precompute);
  entry["tier"] = r.tier;
  entry["resolution"] = ResolutionJson(r.precompute.options.resolution);
  entry["precompute_min_ms"] = Summarize(GpuTotals(r.precompute.runs)).min;
  entry["precompute_max_ms"] = Summarize(GpuTotals(r.precompute.runs)).max;
  entry["frame_ms"] = r.FrameMs();
  entry["per_pixel_frame_ms"] = OrNull(r.PerPixelFrameMs());
  entry["table_difference_frame_ms"] = r.TableDifferenceFrameMs();
  entry["froxel_build_ms"] = r.FroxelBuildMs();
  entry["frame_wall_ms"] = r.FrameWallMs();
  entry["frame_pass_median_ms"] = {{"froxel", FramePassesJson(r.froxel_frames)},
                                   {"per_pixel", FramePassesJson(r.per_pixel_frames)},
                                   {"table_difference", FramePassesJson(r.table_difference_frames)}};
  nlohmann::json accuracy = nlohmann::json::object();
  for (const ViewAccuracy& view : r.accuracy)
    for (const auto& [name, errors] : NamedComparisons(view))
      accuracy[view.view][name] = {{"sky", ErrorJson(errors->sky)}, {"opaque", ErrorJson(errors->opaque)}};
  entry["accuracy"] = accuracy;
  return entry;
}

std::string CsvNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// A figure that was not measured is an empty field.
std::string CsvNumber(std::optional<double> v) { return v ? CsvNumber(*v) : ""; }

}  // namespace

std::vector<std::pair<std::string, const ClassErrors*>> NamedComparisons(const ViewAccuracy& a) {
  if (a.shadow_view) return {{"froxel_vs_per_pixel", &a.froxel_vs_per_pixel}};
  std::vector<std::pair<std::string, const ClassErrors*>> named;
  if (a.vs_4d) named.emplace_back("3d_vs_4d", &*a.vs_4d);
  named.emplace_back("froxel_vs_reference", &a.froxel_vs_reference);
  named.emplace_back("per_pixel_vs_reference", &a.per_pixel_vs_reference);
  named.emplace_back("froxel_vs_per_pixel", &a.froxel_vs_per_pixel);
  named.emplace_back("table_difference_vs_reference", &a.table_difference_vs_reference);
  return named;
}

nlohmann::json ResultsJson(const BenchResults& b) {
  const BenchPlan& plan = b.plan;
  nlohmann::json doc;
  doc["tool"] = "aerial bench";
  doc["mode"] = plan.quick ? "quick" : "full";
  doc["command"] = b.machine.command;
  doc["date"] = b.machine.date;
  doc["version"] = b.machine.version;
  doc["seconds"] = b.seconds;
  doc["machine"] = {{"device", b.machine.device},
                    {"cores", b.machine.cores},
                    {"validation_layers", b.machine.validation},
                    {"load_average_before", b.machine.load_before},
                    {"load_average_after", b.machine.load_after}};
  if (!b.results.empty())
    doc["machine"]["lavapipe_threads"] = {{"count", b.results[0].precompute.threads},
                                          {"source", b.results[0].precompute.threads_source}};
  doc["settings"] = {{"frame_size", {plan.frame_width, plan.frame_height}},
                     {"frame_warmup", plan.frame_warmup},
                     {"frames", plan.frames},
                     {"frame_shadows", plan.shadows},
                     {"colour", ToString(plan.colour)},
                     {"frame_scene", "built-in default scene, preset noon"},
                     {"precompute_warmup", plan.precompute_warmup},
                     {"precompute_runs", plan.precompute_runs},
                     {"image_size", {plan.image_width, plan.image_height}},
                     {"accuracy_scene", "built-in default scene without its transparent meshes"},
                     {"views", plan.views},
                     {"reference_grid", {plan.reference_columns, plan.reference_rows}},
                     {"reference_paths_per_query", plan.reference_paths},
                     {"error_definition", kErrorDefinition},
                     {"times", "medians of GPU timestamps, ms"}};
  doc["results"] = nlohmann::json::array();
  for (const VariantResult& r : b.results) doc["results"].push_back(EntryJson(r));
  doc["ratios_3d_over_4d"] = nlohmann::json::array();
  for (const TableTier& tier : plan.tiers) {
    const VariantResult& lut4d = b.Find(tier.name, LutVariant::k4D);
    const VariantResult& lut3d = b.Find(tier.name, LutVariant::k3D);
    VariantRatios ratios = CompareVariants(lut4d.precompute, lut3d.precompute);
    nlohmann::json kinds = nlohmann::json::object();
    for (const auto& [kind, ratio] : ratios.kinds) kinds[kind] = ratio;
    doc["ratios_3d_over_4d"].push_back(
        {{"tier", tier.name},
         {"table_bytes", ratios.memory},
         {"precompute_ms", ratios.gpu},
         {"precompute_kinds", kinds},
         {"frame_ms", lut3d.FrameMs() / lut4d.FrameMs()},
         {"per_pixel_frame_ms", OrNull(PerPixelFrameRatio(lut3d, lut4d))},
         {"table_difference_frame_ms", lut3d.TableDifferenceFrameMs() / lut4d.TableDifferenceFrameMs()}});
  }
  doc["reference"] = nlohmann::json::array();
  for (const ReferenceSummary& s : b.references)
    doc["reference"].push_back({{"view", s.view},
                                {"sky_pixels", s.sky_pixels},
                                {"opaque_pixels", s.opaque_pixels},
                                {"sun_pixels_left_out", s.sun_pixels},
                                {"unmatched_pixels_left_out", s.unmatched_pixels},
                                {"median_relative_std_error", s.median_relative_std_error}});
  return doc;
}

std::string ResultsCsv(const BenchResults& b) {
  std::ostringstream csv;
  csv << "variant,tier,scattering_size,table_bytes,precompute_ms,frame_ms,per_pixel_frame_ms,"
         "table_difference_frame_ms,froxel_build_ms,frame_wall_ms,view,comparison,pixels,pixel_count,rel_rmse,"
         "rel_max\n";
  for (const VariantResult& r : b.results) {
    std::string head = ToString(r.variant()) + "," + r.tier + "," +
                       ScatteringSize(r.precompute.options.resolution) + "," +
                       std::to_string(r.precompute.table_bytes) + "," + CsvNumber(r.PrecomputeMs()) + "," +
                       CsvNumber(r.FrameMs()) + "," + CsvNumber(r.PerPixelFrameMs()) + "," +
                       CsvNumber(r.TableDifferenceFrameMs()) + "," +
                       CsvNumber(r.FroxelBuildMs()) + "," + CsvNumber(r.FrameWallMs());
    for (const ViewAccuracy& view : r.accuracy)
      for (const auto& [name, errors] : NamedComparisons(view))
        for (PixelClass pixels : {PixelClass::kSky, PixelClass::kOpaque}) {
          const ErrorStats& e = pixels == PixelClass::kSky ? errors->sky : errors->opaque;
          csv << head << "," << view.view << "," << name << "," << ToString(pixels) << "," << e.pixels << ","
              << (e.pixels ? CsvNumber(e.per_pixel_rel_rmse) : "") << "," << (e.pixels ? CsvNumber(e.rel_max) : "")
              << "\n";
        }
  }
  return csv.str();
}

}  // namespace aerial::bench
