// The terrain's level-of-detail selection made by the CPU (terrain/lod_selection.h, as the
// renderer makes it: with occlusion culling, and without) against the one made by the GPU
// (render/gpu_chunk_selection.h), per frame size: the selecting thread's CPU time per moving frame
// (bench::Moved), the GPU time of the selection's passes, with occlusion culling and without, and
// the chunks each draws. Every chunk the frames need is built before they are timed: building is
// not counted.
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "aerial/atmosphere.h"
#include "aerial/bench/frame_measurement.h"
#include "aerial/bench/pass_stats.h"
#include "aerial/error.h"
#include "aerial/render/gpu_chunk_selection.h"
#include "aerial/render/surface_reads.h"
#include "aerial/render/terrain_chunk_cache.h"
#include "aerial/renderer.h"
#include "aerial/scene.h"
#include "aerial/vk/context.h"
#include "aerial/vk/gpu_timer.h"
#include "bench_main.h"

namespace {

using aerial::bench::CpuClockMs;
using aerial::bench::Summarize;

constexpr uint32_t kSlots = 8192;  // the renderer's chunk slots
constexpr uint32_t kGroundInstance = 1;

struct BenchOptions {
  std::vector<std::string> sizes = {"1280x720", "1920x1080", "3840x2160"};
  int frames = 15;
  std::string preset = "noon";
  double terrain_error_px = aerial::kDefaultTerrainErrorPx;
};

struct Size {
  int width = 0, height = 0;
};

Size ParseSize(const std::string& text) {
  Size size;
  char x = 0;
  if (std::sscanf(text.c_str(), "%d%c%d", &size.width, &x, &size.height) != 3 || x != 'x' || size.width < 1 ||
      size.height < 1 || size.width > 16384 || size.height > 16384)
    throw aerial::Error("--sizes", text, "WxH with each in [1, 16384]");
  return size;
}

// Makes the GPU's tree hold what its selections of these views ask for, built through the cache
// (whose slots the draws read) when the CPU's selections did not build it already.
void FillTree(const aerial::vk::Context& context, const std::vector<aerial::terrain::LodView>& views,
              aerial::TerrainChunkCache& cache, aerial::GpuChunkSelection& gpu) {
  // The renderer's split of the chunks by where they read the froxels, at its defaults.
  const aerial::AirScales air = aerial::MakeAirScales(aerial::AtmosphereParameters::Earth());
  for (const aerial::terrain::LodView& view : views) {
    for (;;) {
      context.Submit([&](const aerial::vk::CommandBuffer& cmd) { gpu.Record(cmd, view); });
      const std::vector<aerial::terrain::ChunkId> requested = gpu.Read().requested;
      if (requested.empty()) break;
      cache.Build(requested);
      for (const aerial::terrain::ChunkId& id : requested) {
        const aerial::terrain::ChunkInfo& info = *cache.Find(id);
        gpu.Insert(uint32_t(cache.VertexOffset(id)) / aerial::terrain::kChunkVertices, id, info,
                   aerial::PerPixelReadsWithinM(aerial::FroxelGrid{}, air, info.longest_edge_m, info.largest_rise_m));
      }
    }
  }
}

void BenchSize(const aerial::vk::Context& context, const BenchOptions& cli, Size size) {
  const double R = aerial::AtmosphereParameters::Earth().bottom_radius_m;
  aerial::Scene scene;
  aerial::ApplyPresetView(scene, cli.preset, R);
  std::vector<aerial::terrain::LodView> views;
  for (int i = 0; i < cli.frames; ++i)
    views.push_back(aerial::terrain::MakeLodView(aerial::bench::Moved(scene, aerial::bench::Motion::kCamera, i).camera,
                                                 double(size.width) / size.height, size.height, cli.terrain_error_px,
                                                 R));

  aerial::TerrainChunkCache cache(context, R, kSlots, 1, nullptr);
  cache.BeginFrame(0.0);
  aerial::GpuChunkSelection gpu(context, kSlots, aerial::terrain::kChunkVertices, kGroundInstance);
  for (aerial::terrain::LodView view : views) aerial::terrain::SelectChunks(view, cache);
  FillTree(context, views, cache, gpu);

  std::vector<double> cpu_ms, cpu_unculled_ms, record_ms, dispatch_ms, dispatch_unculled_ms, cpu_chunks, gpu_chunks;
  aerial::vk::GpuTimer timer(context, 4);
  auto select_on_gpu = [&](const aerial::terrain::LodView& view, std::vector<double>& ms) {
    context.Submit([&](const aerial::vk::CommandBuffer& cmd) {
      timer.Reset(cmd);
      timer.Begin(cmd, "terrain selection");
      const double record_start = CpuClockMs(CLOCK_THREAD_CPUTIME_ID);
      gpu.Record(cmd, view);
      if (view.occlusion_culling) record_ms.push_back(CpuClockMs(CLOCK_THREAD_CPUTIME_ID) - record_start);
      timer.End(cmd);
    });
    ms.push_back(timer.Collect().front().milliseconds);
  };
  for (aerial::terrain::LodView view : views) {
    double start = CpuClockMs(CLOCK_THREAD_CPUTIME_ID);
    cpu_chunks.push_back(double(aerial::terrain::SelectChunks(view, cache).chunks.size()));
    cpu_ms.push_back(CpuClockMs(CLOCK_THREAD_CPUTIME_ID) - start);
    select_on_gpu(view, dispatch_ms);
    gpu_chunks.push_back(double(gpu.Read().chunks.size()));
    view.occlusion_culling = false;
    start = CpuClockMs(CLOCK_THREAD_CPUTIME_ID);
    aerial::terrain::SelectChunks(view, cache);
    cpu_unculled_ms.push_back(CpuClockMs(CLOCK_THREAD_CPUTIME_ID) - start);
    select_on_gpu(view, dispatch_unculled_ms);
  }
  std::printf("%5dx%-5d %12.3f %12.3f %14.3f %12.3f %12.3f %8.0f / %.0f\n", size.width, size.height,
              Summarize(cpu_ms).median, Summarize(cpu_unculled_ms).median, Summarize(record_ms).median,
              Summarize(dispatch_ms).median, Summarize(dispatch_unculled_ms).median, Summarize(cpu_chunks).median,
              Summarize(gpu_chunks).median);
}

void Bench(const BenchOptions& cli) {
  std::vector<Size> sizes;
  for (const std::string& text : cli.sizes) sizes.push_back(ParseSize(text));
  aerial::vk::Context context;
  std::printf("terrain selection per moving frame, %s, error bound %.2f px, medians of %d frames (ms)\n",
              cli.preset.c_str(), cli.terrain_error_px, cli.frames);
  std::printf("%-11s %12s %12s %14s %12s %12s %17s\n", "size", "CPU", "CPU no occl.", "GPU: CPU side",
              "GPU: passes", "GPU no occl.", "chunks CPU / GPU");
  for (Size size : sizes) BenchSize(context, cli, size);
  std::printf("CPU: the selecting thread's CPU time (with occlusion culling, as the renderer selects, and "
              "without); GPU: the thread's time to record the selection, and the GPU time of its passes (with "
              "occlusion culling, and without). Chunks drawn with occlusion culling.\n");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"aerial_bench_terrain_selection: the terrain's selection on the CPU against the GPU"};
  BenchOptions cli;
  app.add_option("--sizes", cli.sizes, "Frame sizes WxH (comma-separated)")->delimiter(',');
  app.add_option("--frames", cli.frames, "Measured frames per size")->check(CLI::Range(1, 10000));
  app.add_option("--preset", cli.preset, "Built-in scene")->check(CLI::IsMember(aerial::PresetNames()));
  app.add_option("--terrain-error-px", cli.terrain_error_px, "Terrain level of detail's error bound (px)")
      ->check(CLI::Range(0.25, 64.0));
  return aerial::bench::ParseAndRun(app, argc, argv, "aerial_bench_terrain_selection", [&] { Bench(cli); });
}
