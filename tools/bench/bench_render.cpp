// aerial_bench_render: GPU time of each render pass, froxel path against per-pixel path, as
// medians over several frames in one process. Both renderers draw the same scene (preset noon);
// warm-up frames first, then the measured frames alternate between the two modes
// (aerial/bench/frame_measurement.h).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "aerial/atmosphere/parameters.h"
#include "aerial/bench/frame_measurement.h"
#include "aerial/core/atomic_file.h"
#include "aerial/precompute/table_store.h"
#include "aerial/render/renderer.h"
#include "aerial/scene/presets.h"
#include "aerial/vk/context.h"
#include "bench_main.h"

namespace {

using aerial::bench::GroupPasses;
using aerial::bench::RunResult;
using aerial::bench::Series;
using aerial::bench::Stats;
using aerial::bench::SumOfPasses;
using aerial::bench::Summarize;

// shared/design.md, "Speed": a 1280x720 full-screen pass with one 3D tap takes ~6 ms here. The
// goal for the froxel path's aerial perspective (froxel build + composite) is under twice that.
constexpr double kFullScreenTapMs = 6.0;
constexpr double kGoalMs = 2.0 * kFullScreenTapMs;

struct BenchOptions {
  int width = 1280, height = 720, frames = 7, warmup = 2;
  std::string lut = "4d", froxels = "32x32x32", json_file;
};

struct ModeResult {
  const char* name;
  aerial::AerialMode mode;
  std::vector<RunResult> frames;
  std::vector<Series> Passes() const {
    auto series = GroupPasses(frames, [](const std::string& pass) { return pass; });
    series.push_back({"total", aerial::bench::GpuTotals(frames)});
    return series;
  }
  // The aerial-perspective cost: every pass but the scene rasters (the froxel path's sky-view
  // table included).
  Series Aerial() const {
    if (mode == aerial::AerialMode::kPerPixel)
      return SumOfPasses(frames, {aerial::bench::kCompositePass}, "composite");
    return SumOfPasses(frames, {aerial::bench::kFroxelBuildPass, "sky view", aerial::bench::kCompositePass},
                       "froxel build + sky view + composite");
  }
  Series Pass(const std::string& name) const { return SumOfPasses(frames, {name}, name); }
};

nlohmann::json StatsJson(const Series& s) {
  Stats st = Summarize(s.ms);
  return {{"median_ms", st.median}, {"min_ms", st.min}, {"max_ms", st.max}, {"frames_ms", s.ms}};
}

void PrintRow(const std::string& name, const Series& s) {
  Stats st = Summarize(s.ms);
  std::printf("  %-28s %9.2f %9.2f %9.2f\n", name.c_str(), st.median, st.min, st.max);
}

void Bench(const BenchOptions& cli) {
  aerial::RenderOptions render{.width = cli.width, .height = cli.height,
                               .froxels = aerial::FroxelGrid::Parse(cli.froxels)};
  render.Validate();
  aerial::PrecomputeOptions precompute =
      aerial::PrecomputeOptions::Default(aerial::ParseLutVariant(cli.lut, "--lut"));
  if (!cli.json_file.empty()) aerial::CheckWritable(cli.json_file);

  aerial::AtmosphereParameters atmosphere = aerial::AtmosphereParameters::Earth();
  aerial::vk::Context context;
  aerial::LoadedTables loaded = aerial::LoadOrPrecompute(context, atmosphere, precompute,
                                                         aerial::TableStoreOptions{.quiet = true});
  aerial::Scene scene = aerial::BuildPreset("noon", atmosphere.bottom_radius_m);
  std::vector<ModeResult> modes = {{"froxel", aerial::AerialMode::kFroxel, {}},
                                   {"per-pixel", aerial::AerialMode::kPerPixel, {}}};
  std::vector<std::unique_ptr<aerial::Renderer>> renderers;
  for (auto& m : modes) {
    render.mode = m.mode;
    renderers.push_back(std::make_unique<aerial::Renderer>(*loaded.tables, scene, render));
  }
  std::vector<aerial::Renderer*> pointers;
  for (auto& r : renderers) pointers.push_back(r.get());
  auto frames = aerial::bench::MeasureFrames(pointers, scene, cli.warmup, cli.frames, {});
  for (size_t m = 0; m < modes.size(); ++m) modes[m].frames = std::move(frames[m]);

  std::printf("device: %s\n%dx%d, froxels %s, %s tables, preset noon\n", context.device_name().c_str(),
              cli.width, cli.height, render.froxels.Describe().c_str(), cli.lut.c_str());
  std::printf("frames: %d measured per mode (interleaved) after %d warm-up\n", cli.frames, cli.warmup);
  nlohmann::json doc = {{"device", context.device_name()}, {"width", cli.width}, {"height", cli.height},
                        {"froxels", cli.froxels}, {"lut", cli.lut}, {"preset", "noon"},
                        {"frames", cli.frames}, {"warmup", cli.warmup}};
  for (const auto& m : modes) {
    std::printf("\n=== %s ===\n  %-28s %9s %9s %9s\n", m.name, "GPU time per pass", "median ms", "min ms",
                "max ms");
    nlohmann::json passes = nlohmann::json::array();
    for (const auto& s : m.Passes()) {
      PrintRow(s.name, s);
      passes.push_back(StatsJson(s));
      passes.back()["name"] = s.name;
    }
    doc["modes"][m.name] = {{"passes", passes}, {"aerial_perspective", StatsJson(m.Aerial())}};
  }

  double froxel_ap = Summarize(modes[0].Aerial().ms).median;
  double per_pixel_ap = Summarize(modes[1].Aerial().ms).median;
  std::printf("\n=== aerial perspective (excluding the scene rasters), medians ===\n");
  PrintRow("froxel: build+sky+composite", modes[0].Aerial());
  PrintRow("per-pixel: composite", modes[1].Aerial());
  std::printf("  froxel / per-pixel: %.2fx (per-pixel is %.2fx the froxel cost)\n",
              froxel_ap / per_pixel_ap, per_pixel_ap / froxel_ap);
  std::printf("  vs 1280x720 full-screen pass with one 3D tap (~%.0f ms, shared/design.md \"Speed\"): %.2fx\n",
              kFullScreenTapMs, froxel_ap / kFullScreenTapMs);
  std::printf("  goal froxel build + sky view + composite < %.0f ms (2x that): %s (%.2f ms)\n", kGoalMs,
              froxel_ap < kGoalMs ? "met" : "NOT met", froxel_ap);
  if (cli.width != 1280 || cli.height != 720)
    std::printf("  (the reference is for 1280x720; this run is %dx%d)\n", cli.width, cli.height);
  std::printf("\n=== transparent raster, medians ===\n");
  for (const auto& m : modes) PrintRow(m.name, m.Pass("transparent raster"));

  doc["comparison"] = {{"froxel_aerial_median_ms", froxel_ap},
                       {"per_pixel_composite_median_ms", per_pixel_ap},
                       {"froxel_over_per_pixel", froxel_ap / per_pixel_ap},
                       {"reference_full_screen_tap_ms", kFullScreenTapMs},
                       {"froxel_over_reference", froxel_ap / kFullScreenTapMs},
                       {"goal_ms", kGoalMs},
                       {"goal_met", froxel_ap < kGoalMs}};
  if (!cli.json_file.empty()) aerial::WriteFileAtomically(cli.json_file, doc.dump(2) + "\n");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"aerial_bench_render: median GPU time of each render pass, froxel vs per-pixel"};
  BenchOptions cli;
  app.add_option("--width", cli.width, "Frame width")->check(CLI::Range(1, 16384));
  app.add_option("--height", cli.height, "Frame height")->check(CLI::Range(1, 16384));
  app.add_option("--frames", cli.frames, "Measured frames per mode")->check(CLI::Range(1, 10000));
  app.add_option("--warmup", cli.warmup, "Unmeasured frames per mode first")->check(CLI::Range(0, 1000));
  app.add_option("--lut", cli.lut, "Scattering table variant")->check(CLI::IsMember({"4d", "3d"}));
  app.add_option("--froxels", cli.froxels, "Froxel grid WxHxD");
  app.add_option("--json", cli.json_file, "Also write the results as JSON to this file");
  return aerial::bench::ParseAndRun(app, argc, argv, "aerial_bench_render", [&] { Bench(cli); });
}
