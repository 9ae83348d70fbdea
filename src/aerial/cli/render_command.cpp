// aerial render: one frame of a scene through the atmosphere, to EXR (linear radiance) or PNG
// (tone-mapped sRGB). The output path is checked before any work, and written atomically.
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "aerial/api/impl.h"
#include "aerial/cli/commands.h"
#include "aerial/cli/common_options.h"
#include "aerial/cli/memory_uses.h"
#include "aerial/cli/path_option.h"
#include "aerial/cli/scene_options.h"
#include "aerial/core/output_conflicts.h"
#include "aerial/error.h"
#include "aerial/image.h"
#include "aerial/image/image_writer.h"
#include "aerial/precompute/spectral_precompute.h"
#include "aerial/render/renderer_options.h"
#include "aerial/scene/camera.h"

namespace aerial::cli {
namespace {

// Samples per pixel on each side: the frame is drawn n x n times with the camera jittered to the
// centres of each pixel's sub-pixels (SupersampleJitters) and the frames averaged, so that edges
// (ridges against the sky, the landmarks) show no stair steps, at the memory of one frame, as
// offline accumulation in engines does (e.g. Unreal's Movie Render Queue's spatial samples). The
// viewer's still view is the same mean (viewer/frame_accumulator.h).
constexpr int kDefaultSupersample = 2;
constexpr int kMaxSupersample = 4;

struct RenderCommandOptions {
  TableOptions tables;
  SceneOptions scene;
  FrameOptions frame;
  bool timings = false;
  std::optional<int> supersample;
  std::filesystem::path out;
};

void RunRender(const RenderCommandOptions& options) {
  CheckImageOutputPath(options.out, "--out");
  AtmosphereParameters atmosphere = options.tables.LoadAtmosphere();
  if (options.supersample && (*options.supersample < 1 || *options.supersample > kMaxSupersample))
    throw Error("--supersample", std::to_string(*options.supersample), "1 to " + std::to_string(kMaxSupersample));
  RendererOptions render = options.frame.MakeRenderOptions();
  Scene scene = options.scene.Load(atmosphere.bottom_radius_m, options.tables.MakeHostMemoryBudget());
  CheckOutputConflicts({{"--out", options.out}});
  PrecomputeOptions precompute = options.tables.MakePrecomputeOptions();
  Device device(options.tables.MakeDeviceOptions());
  const MemoryBudget budget = options.tables.MakeMemoryBudget(device.largest_heap_bytes());
  budget.Check(Combined(SceneMemoryUses(scene, options.scene.Source()),
                        Combined(TableMemoryUses(precompute), FrameMemoryUses(render))));
  const int supersample = options.supersample.value_or(kDefaultSupersample);
  Tables tables = Tables::LoadOrPrecompute(device, atmosphere, precompute, options.tables.MakeLoadOptions());
  SceneRenderer renderer = MakeSceneRenderer(tables, scene, render);
  renderer.Render(scene);  // the first frame includes lavapipe's shader compilation
  std::vector<PassTime> times;
  double frame_ms = 0.0;
  ImageRgbF frame;
  const std::vector<glm::dvec2> jitters = SupersampleJitters(supersample);
  for (const glm::dvec2& jitter : jitters) {
    scene.camera.jitter_px = jitter;
    const auto start = std::chrono::steady_clock::now();
    times = renderer.Render(scene);  // --timings: the last jittered frame's
    frame_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    ImageRgbF jittered = renderer.ReadOutput();
    if (frame.rgba.empty()) frame = ImageRgbF{jittered.width, jittered.height, std::vector<float>(jittered.rgba.size())};
    for (size_t i = 0; i < frame.rgba.size(); ++i) frame.rgba[i] += jittered.rgba[i] / float(jitters.size());
  }
  ToneMapOptions tone_map =
      options.frame.MakeToneMap(frame, ShaderAtmosphere(atmosphere, precompute).solar_irradiance);
  WriteImage(options.out, frame, tone_map);
  const std::string out = Printable(options.out.native());
  if (ImageFormatFromPath(options.out, "--out") == ImageFormat::kExr) {
    std::printf("wrote %s: %dx%d, %dx%d samples per pixel, linear radiance\n", out.c_str(), frame.width,
                frame.height, supersample, supersample);
  } else {
    std::printf("wrote %s: %dx%d, %dx%d samples per pixel, EV100 %.2f (%s)\n", out.c_str(), frame.width,
                frame.height, supersample, supersample, Ev100FromRadianceMultiplier(tone_map.exposure),
                options.frame.ev100 || options.frame.exposure ? "fixed" : "metered");
  }
  if (options.timings) {
    // A CPU rasterizer (lavapipe) bins a raster scope's draws and rasterizes them when the scope
    // ends, after the timestamps around each draw: those times are not the draws' own.
    const bool binned = ImplOf(device).context->cpu_device();
    const std::set<std::string> raster = {"opaque raster", "sky", "transparent raster"};
    double total = 0.0;
    for (const auto& pass : times) {
      if (binned && raster.count(pass.pass)) continue;
      std::printf("  %-24s %9.2f ms\n", pass.pass.c_str(), pass.milliseconds);
      total += pass.milliseconds;
    }
    std::printf("  %-24s %9.2f ms%s\n", "total", total, binned ? " (without the raster passes)" : "");
    std::printf("  %-24s %9.2f ms wall clock\n", "frame", frame_ms);
    if (binned)
      std::printf("  %s rasterizes a pass's draws at its end, so its opaque, sky and transparent times are left out;\n"
                  "  aerial_bench_render measures each by the frame's time without it\n",
                  device.name().c_str());
    const FrameInfo& terrain = renderer.frame_info();
    if (terrain.chunks > 0)
      std::printf("  terrain: %zu chunks, %zu triangles (%d chunks hidden by nearer ones)\n", terrain.chunks,
                  terrain.triangles, terrain.hidden);
  }
}

}  // namespace

void AddRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderCommandOptions>();
  CLI::App* command = app.add_subcommand("render", "Render one frame of a scene to EXR or PNG");
  options->scene.AddTo(*command);
  AddPathOption(*command, "--out", options->out, "Output image, .exr (linear radiance) or .png (exposed, sRGB)")
      ->required();
  options->frame.AddTo(*command, "Image");
  command->add_option("--supersample", options->supersample,
                      "Anti-aliasing: N x N samples per pixel, the mean of N x N frames with the camera "
                      "jittered to each sub-pixel's centre (1 to 4; default 2)");
  command->add_flag("--timings", options->timings, "Print the GPU time of each pass");
  options->tables.AddTo(*command);
  command->callback([options] { RunRender(*options); });
}

}  // namespace aerial::cli
