// aerial_bench_render: the cost of a whole frame and of its parts, in one process.
//
// Renderers of the same scene (a preset, noon by default) draw frames in turn after warm-up frames
// (aerial/bench/frame_measurement.h), the camera moving a little every frame so that each frame
// rebuilds its froxel volume and sky-view table: the frame as `aerial render` and the viewer draw
// it, the same with a still camera, and with a still camera under a moving sun; all three again
// without the sun's shadow map (a moving sun redraws every tile of the shadow map, a moving camera
// only the tiles whose window or casters changed, shown as tiles redrawn per frame; a still view
// keeps it and the screen's sun visibility: shadows on minus off is the shadows' cost in each
// case); the frame with aerial perspective read per pixel from the tables; with the fixed
// 294K-triangle terrain mesh instead of the level of detail; without the terrain's occlusion
// culling; and with one part left out at a time. lavapipe defers rasterization and its threads
// take a timestamp when they reach it, so a pass's interval can hold the work of others (even of a
// compute pass, on a loaded machine): a raster part's cost is the frame's time minus the time of
// the frame without it, and the passes' timestamps are indications. Each frame also has its wall
// clock time, CPU work included. A full-screen pass with one 3D tap, timed in the same run, is the
// unit of cost.
#include <cstdio>
#include <functional>
#include <tuple>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "aerial/atmosphere.h"
#include "aerial/bench/frame_measurement.h"
#include "aerial/bench/full_screen_tap.h"
#include "aerial/core/atomic_file.h"
#include "aerial/device.h"
#include "aerial/render/renderer_options.h"
#include "aerial/scene.h"
#include "aerial/tables.h"
#include "aerial/vk/context.h"
#include "bench_main.h"

namespace {

using aerial::bench::RunResult;
using aerial::bench::Stats;
using aerial::bench::Summarize;

// The goals for the moving-camera frame at 1280x720 with shadows (froxel path): 30 frames a
// second on lavapipe, GPU and wall.
constexpr double kFrameGoalMs = 33.0, kFrameWallGoalMs = 40.0;

struct BenchOptions {
  int width = 1280, height = 720, frames = 9, warmup = 2;
  std::string lut = "4d", froxels = "32x32x32", preset = "noon", colour = "rgb", json_file;
  std::string precision;  // empty: the variant's default
  double terrain_error_px = aerial::kDefaultTerrainErrorPx;
};

struct Configuration {
  std::string name;
  std::function<void(aerial::RendererOptions&)> change;
  aerial::bench::Motion motion = aerial::bench::Motion::kCamera;
  std::vector<RunResult> frames;
  Stats Gpu() const { return Summarize(aerial::bench::GpuTotals(frames)); }
  Stats Wall() const { return Summarize(aerial::bench::WallTotals(frames)); }
  Stats Cpu() const { return Summarize(aerial::bench::CpuTotals(frames)); }
  Stats CallerCpu() const { return Summarize(aerial::bench::CallerCpuTotals(frames)); }
};

nlohmann::json StatsJson(const Stats& s) {
  return {{"median_ms", s.median}, {"min_ms", s.min}, {"max_ms", s.max}};
}

void PrintRow(const std::string& name, const Stats& s) {
  std::printf("  %-34s %9.2f %9.2f %9.2f\n", name.c_str(), s.median, s.min, s.max);
}

void Bench(const BenchOptions& cli) {
  aerial::RendererOptions base{{.width = cli.width, .height = cli.height,
                                .froxels = aerial::FroxelGrid::Parse(cli.froxels),
                                .terrain_error_px = cli.terrain_error_px}};
  base.Validate();
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
  using aerial::RendererOptions;
  using aerial::bench::Motion;
  auto same = [](RendererOptions&) {};
  // The parts measured by their absence come last (kFirstAblation on).
  std::vector<Configuration> configurations = {
      {"frame", same},
      {"frame, still camera", same, Motion::kStill},
      {"frame, no shadows", [](RendererOptions& o) { o.shadows = false; }},
      {"frame, still camera, no shadows", [](RendererOptions& o) { o.shadows = false; }, Motion::kStill},
      {"frame, moving sun", same, Motion::kSun},
      {"frame, moving sun, no shadows", [](RendererOptions& o) { o.shadows = false; }, Motion::kSun},
      {"per-pixel aerial perspective", [](RendererOptions& o) { o.mode = aerial::AerialMode::kPerPixel; }},
      {"per pixel, two table reads",
       [](RendererOptions& o) { o.mode = aerial::AerialMode::kTableDifference; }},
      {"fixed fine terrain mesh", [](RendererOptions& o) { o.terrain = aerial::TerrainMode::kStaticMesh; }},
      {"no terrain occlusion culling", [](RendererOptions& o) { o.terrain_occlusion_culling = false; }},
      {"without the sky", [](RendererOptions& o) { o.passes.sky = false; }},
      {"without transparent objects", [](RendererOptions& o) { o.passes.transparent = false; }},
      {"without the terrain", [](RendererOptions& o) { o.passes.terrain = false; }},
  };
  constexpr size_t kFirstAblation = 10;
  constexpr size_t kStill = 1, kNoShadows = 2, kStillNoShadows = 3, kSun = 4, kSunNoShadows = 5, kPerPixel = 6,
                   kTableDifference = 7, kFineMesh = 8;
  std::vector<std::unique_ptr<aerial::SceneRenderer>> renderers;
  std::vector<aerial::bench::FrameSource> order;
  for (Configuration& c : configurations) {
    RendererOptions options = base;
    c.change(options);
    renderers.push_back(std::make_unique<aerial::SceneRenderer>(aerial::MakeSceneRenderer(tables, scene, options)));
    order.push_back({renderers.back().get(), c.motion});
  }
  aerial::bench::FullScreenTap tap(context, uint32_t(base.render_width()), uint32_t(base.render_height()),
                                   renderers.front()->froxel_rayleigh());
  std::vector<RunResult> tap_runs;
  // The reference pass runs once after every round of frames, so it sees the same load.
  int round = 0;
  auto frames = aerial::bench::MeasureFrames(order, scene, cli.warmup, cli.frames, [&] {
    if (++round % int(order.size()) != 0) return;
    RunResult run{.passes = tap.Run()};
    if (round / int(order.size()) > cli.warmup) tap_runs.push_back(run);
  });
  for (size_t c = 0; c < configurations.size(); ++c) configurations[c].frames = std::move(frames[c]);
  const Configuration& frame = configurations[0];
  const aerial::FrameInfo& terrain = renderers[0]->frame_info();

  std::printf("device: %s\n%dx%d, froxels %s, %s %s tables, preset %s, terrain error <= %.2f px "
              "(%zu chunks, %zu triangles)\n",
              context.device_name().c_str(), cli.width, cli.height, base.froxels.Describe().c_str(),
              cli.lut.c_str(), cli.colour.c_str(), cli.preset.c_str(), base.terrain_error_px, terrain.chunks, terrain.triangles);
  std::printf("frames: %d measured per configuration (interleaved) after %d warm-up\n", cli.frames, cli.warmup);
  std::printf("\n=== whole frame, GPU (sum of the passes' timestamps) ===\n  %-34s %9s %9s %9s\n", "",
              "median ms", "min ms", "max ms");
  nlohmann::json doc = {{"device", context.device_name()}, {"width", cli.width}, {"height", cli.height},
                        {"froxels", cli.froxels}, {"lut", cli.lut}, {"colour", cli.colour}, {"preset", cli.preset},
                        {"frames", cli.frames}, {"warmup", cli.warmup},
                        {"terrain", {{"error_px", base.terrain_error_px}, {"chunks", terrain.chunks},
                                     {"triangles", terrain.triangles}}}};
  for (const Configuration& c : configurations) {
    PrintRow(c.name, c.Gpu());
    doc["configurations"][c.name] = {
        {"gpu", StatsJson(c.Gpu())}, {"wall", StatsJson(c.Wall())}, {"cpu", StatsJson(c.Cpu())},
        {"caller_cpu", StatsJson(c.CallerCpu())}};
  }
  std::printf("\n=== whole frame, wall clock (CPU and GPU: the call to Render until its frame is done) ===\n");
  for (const Configuration& c : configurations) PrintRow(c.name, c.Wall());

  std::printf("\n=== whole frame, CPU time of the process (lavapipe's threads and ours; steadier than the "
              "times above on a shared machine) ===\n");
  for (const Configuration& c : configurations) PrintRow(c.name, c.Cpu());

  std::printf("\n=== the CPU side of a frame: CPU time of the thread that renders (terrain and shadow caster "
              "selection, sorting, recording, submitting; not lavapipe's threads) ===\n");
  for (const Configuration& c : configurations) PrintRow(c.name, c.CallerCpu());

  std::printf("\n=== the frame's passes: timestamps of the compute passes; raster parts by their absence, "
              "in GPU time and in process CPU time ===\n");
  nlohmann::json parts;
  for (const char* pass : {aerial::bench::kShadowMapPass, aerial::bench::kFroxelBuildPass, "sky view correction", "sky view"}) {
    Stats s = Summarize(aerial::bench::SumOfPasses(frame.frames, {pass}, pass).ms);
    PrintRow(pass, s);
    parts[pass] = {{"gpu_ms", s.median}};
  }
  for (size_t c = kFirstAblation; c < configurations.size(); ++c) {
    std::string part = configurations[c].name.substr(std::string("without ").size());
    double gpu = frame.Gpu().median - configurations[c].Gpu().median;
    double cpu = frame.Cpu().median - configurations[c].Cpu().median;
    std::printf("  %-34s %9.2f GPU, %6.2f CPU\n", part.c_str(), gpu, cpu);
    parts[part] = {{"gpu_ms", gpu}, {"cpu_ms", cpu}};
  }
  doc["parts_median"] = parts;

  // lavapipe defers rasterization and takes a timestamp when its threads reach it, so the
  // interval of a pass that drew nothing can hold other work: the tiles redrawn say what the
  // shadow pass did, and shadows on minus off what they cost.
  std::printf("\n=== the sun's shadow map (medians): tiles redrawn per frame and its pass's timestamps with a "
              "moving camera, a still one and a moving sun (still camera), and the whole frame's cost of shadows (on "
              "minus off: the pass, the lookups in the froxels and on surfaces, chunk selection) ===\n");
  nlohmann::json shadows;
  for (auto [name, on, off] : {std::tuple{"moving", size_t(0), kNoShadows}, std::tuple{"still", kStill, kStillNoShadows},
                               std::tuple{"sun moving", kSun, kSunNoShadows}}) {
    const Configuration& with = configurations[on];
    const Configuration& without = configurations[off];
    Stats pass = Summarize(aerial::bench::SumOfPasses(with.frames, {aerial::bench::kShadowMapPass}, name).ms);
    double tiles = aerial::bench::MeanShadowTilesRedrawn(with.frames);
    double gpu = with.Gpu().median - without.Gpu().median, cpu = with.Cpu().median - without.Cpu().median;
    std::printf("  %-10s %.2f tiles redrawn, pass %7.2f ms; frame %7.2f ms GPU with, %7.2f without (%+.2f ms, "
                "%+.1f%%), %+.2f ms CPU\n", name, tiles, pass.median, with.Gpu().median, without.Gpu().median, gpu,
                100.0 * gpu / without.Gpu().median, cpu);
    shadows[name] = {{"tiles_redrawn_per_frame", tiles}, {"shadow_map_pass_gpu_ms", pass.median},
                     {"frame_gpu_ms", with.Gpu().median}, {"frame_without_shadows_gpu_ms", without.Gpu().median},
                     {"shadows_gpu_ms", gpu}, {"shadows_cpu_ms", cpu}};
  }
  doc["shadows_median"] = shadows;

  Stats tap_stats = Summarize(aerial::bench::GpuTotals(tap_runs));
  double frame_ms = frame.Gpu().median;
  std::printf("\n=== comparisons, medians ===\n");
  PrintRow("full-screen pass, one 3D tap", tap_stats);
  std::printf("  frame / full-screen tap pass:      %6.2fx\n", frame_ms / tap_stats.median);
  std::printf("  per-pixel / froxel frame:          %6.2fx\n", configurations[kPerPixel].Gpu().median / frame_ms);
  std::printf("  table difference / froxel frame:   %6.2fx\n",
              configurations[kTableDifference].Gpu().median / frame_ms);
  std::printf("  fine mesh / level-of-detail frame: %6.2fx\n", configurations[kFineMesh].Gpu().median / frame_ms);
  double wall_ms = frame.Wall().median;
  std::printf("  goal: frame <= %.0f ms GPU: %s (%.2f ms)\n", kFrameGoalMs,
              frame_ms <= kFrameGoalMs ? "met" : "NOT met", frame_ms);
  std::printf("  goal: frame <= %.0f ms wall: %s (%.2f ms)\n", kFrameWallGoalMs,
              wall_ms <= kFrameWallGoalMs ? "met" : "NOT met", wall_ms);
  if (cli.width != 1280 || cli.height != 720)
    std::printf("  (the goal is for 1280x720; this run is %dx%d)\n", cli.width, cli.height);
  doc["comparison"] = {{"full_screen_tap", StatsJson(tap_stats)},
                       {"frame_over_full_screen_tap", frame_ms / tap_stats.median},
                       {"per_pixel_over_frame", configurations[kPerPixel].Gpu().median / frame_ms},
                       {"table_difference_over_frame", configurations[kTableDifference].Gpu().median / frame_ms},
                       {"fine_mesh_over_frame", configurations[kFineMesh].Gpu().median / frame_ms},
                       {"goal_ms", kFrameGoalMs},
                       {"goal_met", frame_ms <= kFrameGoalMs},
                       {"wall_goal_ms", kFrameWallGoalMs},
                       {"wall_goal_met", wall_ms <= kFrameWallGoalMs}};
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
  return aerial::bench::ParseAndRun(app, argc, argv, "aerial_bench_render", [&] { Bench(cli); });
}
