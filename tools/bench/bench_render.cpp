// aerial_bench_render: the cost of a whole frame and of its parts, in one process.
//
// Renderers of the same scene (a preset, noon by default) draw frames in turn after warm-up frames
// (aerial/bench/frame_measurement.h), the camera moving a little every frame so that each frame
// rebuilds its froxel volume and sky-view table: the frame as `aerial render` and the viewer draw
// it, the same with a still camera, and with a still camera under a moving sun; all three again
// without the sun's shadow map (a moving sun redraws a tile a frame, a moving camera only the tiles
// whose window or casters changed, shown as tiles redrawn per frame; a still view keeps it and the
// screen's sun visibility: shadows on minus off is the shadows' cost in each case); all three
// again with the surfaces' shading and the sky left out, the floor of what the frame rasterizes;
// the frame with aerial perspective read per pixel from the tables; with the fixed 294K-triangle
// terrain mesh instead of the level of detail; without the terrain's occlusion culling; and with
// one part left out at a time. lavapipe defers rasterization and its threads take a timestamp when
// they reach it, so a pass's interval can hold the work of others (even of a compute pass, on a
// loaded machine): a raster part's cost is the frame's time minus the time of the frame without
// it, and the passes' timestamps are indications. Each frame also has its wall clock time, CPU
// work included. A full-screen pass with one 3D tap, timed in the same run, is the unit of cost.
#include <algorithm>
#include <cstdio>
#include <functional>
#include <tuple>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "aerial/atmosphere.h"
#include "aerial/bench/frame_measurement.h"
#include "aerial/bench/full_screen_tap.h"
#include "aerial/core/atomic_file.h"
#include "aerial/device.h"
#include "aerial/error.h"
#include "aerial/render/renderer_options.h"
#include "aerial/scene.h"
#include "aerial/tables.h"
#include "aerial/vk/context.h"
#include "bench_main.h"

namespace {

using aerial::bench::RunResult;
using aerial::bench::Stats;
using aerial::bench::Summarize;

// The frame's goals on lavapipe at 1280x720 with shadows, in full-screen one-tap passes of the same
// run (a unit that moves with the machine's pace): a moving camera, a still one, a moving sun.
constexpr double kMovingGoalUnits = 7.0, kStillGoalUnits = 5.0, kSunGoalUnits = 9.0;
// The frame with its terrain selected by the GPU against the CPU's selection: lavapipe runs the
// selection's passes on the same cores as the rest of the frame, and may spend this much more.
constexpr double kGpuSelectionGoalRatio = 1.05;

struct BenchOptions {
  int width = 1280, height = 720, frames = 9, warmup = 2;
  std::string lut = "4d", froxels = "32x32x32", preset = "noon", colour = "rgb", json_file;
  std::string precision;  // empty: the variant's default
  double terrain_error_px = aerial::kDefaultTerrainErrorPx;
  std::vector<std::string> only;  // configuration keys; empty: all
};

struct Configuration {
  std::string key, name;
  std::function<void(aerial::RendererOptions&)> change;
  aerial::bench::Motion motion = aerial::bench::Motion::kCamera;
  // A part of the moving frame left out: what it costs is the moving frame's time minus this one's.
  bool part_left_out = false;
  std::vector<RunResult> frames;
  Stats Gpu() const { return Summarize(aerial::bench::GpuTotals(frames)); }
  Stats Wall() const { return Summarize(aerial::bench::WallTotals(frames)); }
  Stats Cpu() const { return Summarize(aerial::bench::CpuTotals(frames)); }
  Stats CallerCpu() const { return Summarize(aerial::bench::CallerCpuTotals(frames)); }
  Stats Draws() const { return Summarize(aerial::bench::DrawCounts(frames)); }
  Stats DrawBinds() const { return Summarize(aerial::bench::DrawBindCounts(frames)); }
};

// Every configuration the bench knows, the moving frame first (the others are compared with it).
std::vector<Configuration> AllConfigurations() {
  using aerial::RendererOptions;
  using aerial::bench::Motion;
  auto same = [](RendererOptions&) {};
  auto no_shadows = [](RendererOptions& o) { o.shadows = false; };
  // The frame's floor: its surfaces a constant radiance and no sky, so that what is left is the
  // rasterization and every pass but the shading (the goals are compared with it).
  auto unshaded = [](RendererOptions& o) {
    o.left_out_reads.shading = true;
    o.passes.sky = false;
  };
  return {
      {"moving", "frame", same},
      {"still", "frame, still camera", same, Motion::kStill},
      {"sun", "frame, moving sun", same, Motion::kSun},
      {"moving-no-shadows", "frame, no shadows", no_shadows},
      {"still-no-shadows", "frame, still camera, no shadows", no_shadows, Motion::kStill},
      {"sun-no-shadows", "frame, moving sun, no shadows", no_shadows, Motion::kSun},
      {"froxels-per-pixel", "froxels read per pixel on every surface",
       [](RendererOptions& o) { o.surface_froxel_reads = aerial::SurfaceFroxelReads::kPerPixel; }},
      {"froxels-per-vertex", "froxels read per vertex on every surface",
       [](RendererOptions& o) { o.surface_froxel_reads = aerial::SurfaceFroxelReads::kPerVertex; }},
      {"froxels-full-screen", "froxels in a full-screen pass (deferred)",
       [](RendererOptions& o) { o.surface_froxel_reads = aerial::SurfaceFroxelReads::kFullScreenPass; }},
      {"per-pixel", "per-pixel aerial perspective", [](RendererOptions& o) { o.mode = aerial::AerialMode::kPerPixel; }},
      {"table-difference", "per pixel, two table reads",
       [](RendererOptions& o) { o.mode = aerial::AerialMode::kTableDifference; }},
      {"fine-mesh", "fixed fine terrain mesh", [](RendererOptions& o) { o.terrain = aerial::TerrainMode::kStaticMesh; }},
      {"no-occlusion", "no terrain occlusion culling", [](RendererOptions& o) { o.terrain_occlusion_culling = false; }},
      {"gpu-selection", "terrain selected on the GPU",
       [](RendererOptions& o) { o.terrain_selector = aerial::TerrainSelector::kGpu; }},
      {"cpu-selection", "terrain selected on the CPU",
       [](RendererOptions& o) { o.terrain_selector = aerial::TerrainSelector::kCpu; }},
      {"no-froxel-reads", "without the surfaces' froxel reads",
       [](RendererOptions& o) { o.left_out_reads.froxels = true; }, Motion::kCamera, true},
      {"no-sun-visibility", "without the surfaces' sun visibility",
       [](RendererOptions& o) { o.left_out_reads.sun_visibility = true; }, Motion::kCamera, true},
      {"no-ground-detail", "without the ground's albedo detail", [](RendererOptions& o) { o.ground_detail = false; },
       Motion::kCamera, true},
      {"no-sky", "without the sky", [](RendererOptions& o) { o.passes.sky = false; }, Motion::kCamera, true},
      {"no-transparent", "without transparent objects", [](RendererOptions& o) { o.passes.transparent = false; },
       Motion::kCamera, true},
      {"no-terrain", "without the terrain", [](RendererOptions& o) { o.passes.terrain = false; }, Motion::kCamera,
       true},
      {"unshaded", "without the surfaces' shading and the sky", unshaded, Motion::kCamera, true},
      {"still-unshaded", "frame, still camera, unshaded, no sky", unshaded, Motion::kStill},
      {"sun-unshaded", "frame, moving sun, unshaded, no sky", unshaded, Motion::kSun},
  };
}

// The configurations to run: the moving frame and those of `only` (all when it is empty).
std::vector<Configuration> ChosenConfigurations(const std::vector<std::string>& only) {
  std::vector<Configuration> all = AllConfigurations(), chosen;
  for (const std::string& key : only)
    if (std::none_of(all.begin(), all.end(), [&](const Configuration& c) { return c.key == key; })) {
      std::string keys;
      for (const Configuration& c : all) keys += (keys.empty() ? "" : ", ") + c.key;
      throw aerial::Error("--only", key, "one of " + keys);
    }
  for (Configuration& c : all)
    if (only.empty() || c.key == "moving" || std::find(only.begin(), only.end(), c.key) != only.end())
      chosen.push_back(std::move(c));
  return chosen;
}

const Configuration* Find(const std::vector<Configuration>& configurations, const std::string& key) {
  for (const Configuration& c : configurations)
    if (c.key == key) return &c;
  return nullptr;
}

nlohmann::json StatsJson(const Stats& s) {
  return {{"median_ms", s.median}, {"min_ms", s.min}, {"max_ms", s.max}};
}

void PrintRow(const std::string& name, const Stats& s) {
  std::printf("  %-40s %9.2f %9.2f %9.2f\n", name.c_str(), s.median, s.min, s.max);
}

void PrintTable(const char* title, const std::vector<Configuration>& configurations,
                Stats (Configuration::*stats)() const) {
  std::printf("\n=== %s ===\n  %-40s %9s %9s %9s\n", title, "", "median ms", "min ms", "max ms");
  for (const Configuration& c : configurations) PrintRow(c.name, (c.*stats)());
}

// What a read, a part or a way of reading costs: a configuration's GPU median against the moving
// frame's, in ms and in one-tap units.
nlohmann::json PrintDifference(const std::string& label, const Configuration& frame, const Configuration& other,
                               double unit_ms) {
  double gpu = frame.Gpu().median - other.Gpu().median, cpu = frame.Cpu().median - other.Cpu().median;
  std::printf("  %-40s %+8.2f ms GPU (%+5.2f units), %+8.2f ms process CPU\n", label.c_str(), gpu, gpu / unit_ms, cpu);
  return {{"gpu_ms", gpu}, {"cpu_ms", cpu}, {"units", gpu / unit_ms}};
}

void Bench(const BenchOptions& cli) {
  aerial::RendererOptions base{{.width = cli.width, .height = cli.height,
                                .froxels = aerial::FroxelGrid::Parse(cli.froxels),
                                .terrain_error_px = cli.terrain_error_px}};
  // Each configuration builds its terrain as a fresh renderer does, whatever ran before it.
  base.share_built_terrain = false;
  base.Validate();
  std::vector<Configuration> configurations = ChosenConfigurations(cli.only);
  aerial::PrecomputeOptions precompute =
      aerial::PrecomputeOptions::Default(aerial::ParseLutVariant(cli.lut, "--lut"));
  if (!cli.precision.empty()) precompute.precision = aerial::ParseTablePrecision(cli.precision, "--precision");
  precompute.colour = aerial::ParseColourMode(cli.colour, "--colour");
  if (!cli.json_file.empty()) aerial::CheckWritable(cli.json_file);

  aerial::AtmosphereParameters atmosphere = aerial::AtmosphereParameters::Earth();
  // The bench's own device (its reference pass is its own), handed to aerial as an engine would.
  aerial::vk::Context context;
  aerial::Device device(context.Handoff());
  aerial::Tables tables = aerial::Tables::LoadOrPrecompute(device, atmosphere, precompute);
  aerial::Scene scene = aerial::BuildPreset(cli.preset, atmosphere.bottom_radius_m);
  std::vector<std::unique_ptr<aerial::SceneRenderer>> renderers;
  std::vector<aerial::bench::FrameSource> order;
  for (Configuration& c : configurations) {
    aerial::RendererOptions options = base;
    c.change(options);
    renderers.push_back(std::make_unique<aerial::SceneRenderer>(aerial::MakeSceneRenderer(tables, scene, options)));
    order.push_back({renderers.back().get(), c.motion});
  }
  aerial::bench::FullScreenTap tap(context, uint32_t(base.render_width()), uint32_t(base.render_height()),
                                   renderers.front()->froxel_rayleigh());
  std::vector<RunResult> tap_runs;
  // The reference pass runs once after every round of frames, so it sees the same load.
  int round = 0;
  auto frames = aerial::bench::MeasureFrames(order, scene, cli.warmup, cli.frames, [&](size_t) {
    if (++round % int(order.size()) != 0) return;
    RunResult run{.passes = tap.Run()};
    if (round / int(order.size()) > cli.warmup) tap_runs.push_back(run);
  });
  for (size_t c = 0; c < configurations.size(); ++c) configurations[c].frames = std::move(frames[c]);
  const Configuration& frame = configurations[0];
  const aerial::FrameInfo& terrain = renderers[0]->frame_info();
  const Stats unit = Summarize(aerial::bench::GpuTotals(tap_runs));

  std::printf("device: %s\n%dx%d, froxels %s, %s %s tables, preset %s, terrain error <= %.2f px "
              "(%zu chunks, %zu triangles)\n",
              context.device_name().c_str(), cli.width, cli.height, base.froxels.Describe().c_str(),
              cli.lut.c_str(), cli.colour.c_str(), cli.preset.c_str(), base.terrain_error_px, terrain.chunks, terrain.triangles);
  std::printf("frames: %d measured per configuration (interleaved) after %d warm-up\n", cli.frames, cli.warmup);
  nlohmann::json doc = {{"device", context.device_name()}, {"width", cli.width}, {"height", cli.height},
                        {"froxels", cli.froxels}, {"lut", cli.lut}, {"colour", cli.colour}, {"preset", cli.preset},
                        {"frames", cli.frames}, {"warmup", cli.warmup},
                        {"terrain", {{"error_px", base.terrain_error_px}, {"chunks", terrain.chunks},
                                     {"triangles", terrain.triangles}}}};
  PrintTable("whole frame, GPU (sum of the passes' timestamps)", configurations, &Configuration::Gpu);
  PrintTable("whole frame, wall clock (CPU and GPU: the call to Render until its frame is done)", configurations,
             &Configuration::Wall);
  PrintTable("whole frame, CPU time of the process (lavapipe's threads and ours; steadier than the times above on a "
             "shared machine)", configurations, &Configuration::Cpu);
  PrintTable("the CPU side of a frame: CPU time of the thread that renders (terrain and shadow caster selection, "
             "sorting, recording, submitting; not lavapipe's threads)", configurations, &Configuration::CallerCpu);
  std::printf("\n=== recording: draw calls and pipeline binds a frame, medians (min-max): indirect draws, a few per "
              "pass whatever the terrain draws; each shadow tile redrawn binds once and draws twice ===\n"
              "  %-40s %17s %17s\n", "",
              "draws", "binds");
  for (const Configuration& c : configurations) {
    Stats draws = c.Draws(), binds = c.DrawBinds();
    std::printf("  %-40s %7.0f (%.0f-%.0f) %7.0f (%.0f-%.0f)\n", c.name.c_str(), draws.median, draws.min, draws.max,
                binds.median, binds.min, binds.max);
  }
  auto counts = [](const Stats& s) { return nlohmann::json{{"median", s.median}, {"min", s.min}, {"max", s.max}}; };
  for (const Configuration& c : configurations)
    doc["configurations"][c.name] = {{"key", c.key}, {"gpu", StatsJson(c.Gpu())}, {"wall", StatsJson(c.Wall())},
                                     {"cpu", StatsJson(c.Cpu())}, {"caller_cpu", StatsJson(c.CallerCpu())},
                                     {"draws", counts(c.Draws())}, {"draw_binds", counts(c.DrawBinds())},
                                     {"units", c.Gpu().median / unit.median}};

  std::printf("\n=== the frame's parts: timestamps of the compute passes; raster parts and the surfaces' reads by "
              "their absence (the moving frame minus the frame without them) ===\n");
  nlohmann::json parts;
  for (const char* pass : {aerial::bench::kShadowMapPass, aerial::bench::kFroxelBuildPass, "sky view correction", "sky view"}) {
    Stats s = Summarize(aerial::bench::SumOfPasses(frame.frames, {pass}, pass).ms);
    std::printf("  %-40s %8.2f ms GPU (timestamps)\n", pass, s.median);
    parts[pass] = {{"gpu_ms", s.median}};
  }
  for (const Configuration& c : configurations)
    if (c.part_left_out) parts[c.name.substr(std::string("without ").size())] =
        PrintDifference(c.name.substr(std::string("without ").size()), frame, c, unit.median);
  doc["parts_median"] = parts;

  const Configuration* per_pixel = Find(configurations, "froxels-per-pixel");
  const Configuration* full_screen = Find(configurations, "froxels-full-screen");
  if (per_pixel || full_screen)
    std::printf("\n=== where the surfaces read the froxels: per vertex on triangles thin in depth (the "
                "frame, forward) against per pixel everywhere, and against once per pixel in a full-screen "
                "pass after the surfaces (deferred) ===\n");
  if (per_pixel)
    doc["froxel_reads"]["per_pixel_minus_frame"] =
        PrintDifference("per pixel everywhere, minus the frame", *per_pixel, frame, unit.median);
  if (full_screen)
    doc["froxel_reads"]["full_screen_minus_frame"] =
        PrintDifference("full-screen pass, minus the frame", *full_screen, frame, unit.median);

  // Fragment-shader invocations (pipeline statistics, where the device counts them): the opaque
  // pass's count over the pixels its surfaces cover is how many times each covered pixel was
  // shaded, by overdraw and by the rasterizer's stamps (llvmpipe shades 4x4 stamps and counts them
  // before the depth test: its sky, drawn only where nothing is, counts about every screen pixel).
  nlohmann::json shading;
  const double covered = double(aerial::bench::CoveredPixels(*renderers.front()));
  for (const Configuration& c : configurations) {
    std::optional<double> opaque = aerial::bench::MedianFragmentInvocations(c.frames, "opaque raster");
    std::optional<double> sky = aerial::bench::MedianFragmentInvocations(c.frames, "sky");
    if (!opaque || !sky || c.motion == aerial::bench::Motion::kSun || c.part_left_out) continue;
    const double pixels = double(base.render_width()) * base.render_height();
    if (shading.empty())
      std::printf("\n=== fragment-shader invocations (pipeline statistics, medians): the opaque pass's per pixel "
                  "its surfaces cover (%.1f%% of the screen, the last frame's), and the sky's per screen pixel "
                  "===\n", 100.0 * covered / pixels);
    std::printf("  %-40s %11.0f opaque: %.3f per covered pixel; sky %.3f per pixel\n", c.name.c_str(), *opaque,
                *opaque / covered, *sky / pixels);
    shading[c.key] = {{"opaque_invocations", *opaque}, {"sky_invocations", *sky}, {"covered_pixels", covered},
                      {"opaque_per_covered_pixel", *opaque / covered}};
  }
  if (!shading.empty()) doc["fragment_invocations_median"] = shading;

  // lavapipe defers rasterization and takes a timestamp when its threads reach it, so the
  // interval of a pass that drew nothing can hold other work: the tiles redrawn say what the
  // shadow pass did, and shadows on minus off what they cost.
  nlohmann::json shadows;
  for (auto [name, on, off] : {std::tuple{"moving", "moving", "moving-no-shadows"},
                               std::tuple{"still", "still", "still-no-shadows"},
                               std::tuple{"sun moving", "sun", "sun-no-shadows"}}) {
    const Configuration *with = Find(configurations, on), *without = Find(configurations, off);
    if (!with || !without) continue;
    if (shadows.empty())
      std::printf("\n=== the sun's shadow map (medians): tiles redrawn per frame (whole + in part) and its pass's timestamps, and the "
                  "whole frame's cost of shadows (on minus off: the pass, the lookups in the froxels and on "
                  "surfaces, chunk selection) ===\n");
    Stats pass = Summarize(aerial::bench::SumOfPasses(with->frames, {aerial::bench::kShadowMapPass}, name).ms);
    double tiles = aerial::bench::MeanPerRun(with->frames, &RunResult::shadow_tiles_redrawn);
    double regions = aerial::bench::MeanPerRun(with->frames, &RunResult::shadow_tile_regions_redrawn);
    double gpu = with->Gpu().median - without->Gpu().median, cpu = with->Cpu().median - without->Cpu().median;
    std::printf("  %-10s %.2f + %.2f tiles redrawn, pass %7.2f ms; frame %7.2f ms GPU with, %7.2f without (%+.2f ms, "
                "%+.1f%%), %+.2f ms CPU\n", name, tiles, regions, pass.median, with->Gpu().median, without->Gpu().median, gpu,
                100.0 * gpu / without->Gpu().median, cpu);
    shadows[name] = {{"tiles_redrawn_per_frame", tiles}, {"tile_regions_redrawn_per_frame", regions},
                     {"shadow_map_pass_gpu_ms", pass.median},
                     {"frame_gpu_ms", with->Gpu().median}, {"frame_without_shadows_gpu_ms", without->Gpu().median},
                     {"shadows_gpu_ms", gpu}, {"shadows_cpu_ms", cpu}};
  }
  if (!shadows.empty()) doc["shadows_median"] = shadows;

  std::printf("\n=== comparisons, medians, in one-tap units (a full-screen pass with one trilinear 3D tap, timed in "
              "the same run) ===\n");
  PrintRow("full-screen pass, one 3D tap", unit);
  nlohmann::json comparison = {{"full_screen_tap", StatsJson(unit)}};
  for (auto [key, goal, floor_key] : {std::tuple{"moving", kMovingGoalUnits, "unshaded"},
                                      std::tuple{"still", kStillGoalUnits, "still-unshaded"},
                                      std::tuple{"sun", kSunGoalUnits, "sun-unshaded"}}) {
    const Configuration* c = Find(configurations, key);
    if (!c) continue;
    double units = c->Gpu().median / unit.median;
    std::printf("  %-40s %6.2f units (goal <= %.0f: %s)", c->name.c_str(), units, goal, units <= goal ? "met" : "NOT met");
    comparison[std::string(key) + "_units"] = units;
    comparison[std::string(key) + "_goal_units"] = goal;
    if (const Configuration* floor = Find(configurations, floor_key)) {
      double floor_units = floor->Gpu().median / unit.median;
      std::printf("; unshaded, without the sky, %.2f units", floor_units);
      comparison[std::string(key) + "_unshaded_units"] = floor_units;
    }
    std::printf("\n");
  }
  for (auto [key, label] : {std::pair{"per-pixel", "per-pixel / froxel frame"},
                            std::pair{"table-difference", "table difference / froxel frame"},
                            std::pair{"fine-mesh", "fine mesh / level-of-detail frame"}}) {
    const Configuration* c = Find(configurations, key);
    if (!c) continue;
    double ratio = c->Gpu().median / frame.Gpu().median;
    std::printf("  %-40s %6.2fx\n", label, ratio);
    comparison[std::string(key) + "_over_frame"] = ratio;
  }
  if (const Configuration *gpu = Find(configurations, "gpu-selection"), *cpu = Find(configurations, "cpu-selection");
      gpu && cpu) {
    // The two configurations' frames take turns, so each pair saw the same stretch of the machine.
    using aerial::bench::MedianPairedRatio;
    const double frames = MedianPairedRatio(aerial::bench::GpuTotals(gpu->frames), aerial::bench::GpuTotals(cpu->frames));
    const double process = MedianPairedRatio(aerial::bench::CpuTotals(gpu->frames), aerial::bench::CpuTotals(cpu->frames));
    const double wall = MedianPairedRatio(aerial::bench::WallTotals(gpu->frames), aerial::bench::WallTotals(cpu->frames));
    const double medians = gpu->Gpu().median / cpu->Gpu().median;
    std::printf("  %-40s %6.3fx GPU, median of frame pairs (goal <= %.2f: %s; %.3fx of the medians), %.3fx process "
                "CPU, %.3fx wall\n", "GPU / CPU terrain selection", frames, kGpuSelectionGoalRatio,
                frames <= kGpuSelectionGoalRatio ? "met" : "NOT met", medians, process, wall);
    comparison["gpu_over_cpu_selection"] = {{"gpu_paired", frames},     {"gpu_medians", medians},
                                            {"process_cpu_paired", process}, {"wall_paired", wall},
                                            {"goal", kGpuSelectionGoalRatio}};
  }
  if (cli.width != 1280 || cli.height != 720)
    std::printf("  (the goals are for 1280x720; this run is %dx%d)\n", cli.width, cli.height);
  doc["comparison"] = comparison;
  if (!cli.json_file.empty()) aerial::WriteFileAtomically(cli.json_file, doc.dump(2) + "\n");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"aerial_bench_render: the GPU and wall-clock time of a frame and of its parts"};
  BenchOptions cli;
  app.add_option("--width", cli.width, "Frame width")->check(CLI::Range(1, 16384));
  app.add_option("--height", cli.height, "Frame height")->check(CLI::Range(1, 16384));
  app.add_option("--frames", cli.frames, "Measured frames per configuration")->check(CLI::Range(1, 10000));
  app.add_option("--warmup", cli.warmup, "Unmeasured frames per configuration first")->check(CLI::Range(0, 1000));
  app.add_option("--lut", cli.lut, "Scattering table variant")->check(CLI::IsMember({"4d", "3d"}));
  app.add_option("--precision", cli.precision,
                 "Scattering tables' floats: float16 or float32 (default: the variant's)")
      ->check(CLI::IsMember({"float16", "float32"}));
  app.add_option("--froxels", cli.froxels, "Froxel grid WxHxD");
  app.add_option("--colour", cli.colour, "What the tables' channels hold: rgb or spectral (12 wavelengths)")
      ->check(CLI::IsMember({"rgb", "spectral"}));
  app.add_option("--preset", cli.preset, "Built-in scene")->check(CLI::IsMember(aerial::PresetNames()));
  app.add_option("--terrain-error-px", cli.terrain_error_px, "Terrain level of detail's error bound (px)");
  app.add_option("--json", cli.json_file, "Also write the results as JSON to this file");
  app.add_option("--only", cli.only, "Run only these configurations (keys, comma-separated) besides the moving frame")
      ->delimiter(',');
  return aerial::bench::ParseAndRun(app, argc, argv, "aerial_bench_render", [&] { Bench(cli); });
}
