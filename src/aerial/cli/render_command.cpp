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
#include "aerial/image/resample.h"
#include "aerial/precompute/spectral_precompute.h"
#include "aerial/render/renderer_options.h"

namespace aerial::cli {
namespace {

// Samples per pixel on each side: the frame is rendered this many times larger and each block
// averaged, so that edges (ridges against the sky, the landmarks) show no stair steps. The default
// falls back to one sample where the larger frame would not fit (the image limits or the memory
// budget); a factor asked for must fit.
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
  auto check_memory = [&](const RendererOptions& frame) {
    budget.Check(Combined(SceneMemoryUses(scene, options.scene.Source()),
                          Combined(TableMemoryUses(precompute), FrameMemoryUses(frame))));
  };
  check_memory(render);  // the frame as asked: its errors name --width/--height
  int supersample = options.supersample.value_or(kDefaultSupersample);
  try {
    RendererOptions larger = render;
    larger.width *= supersample;
    larger.height *= supersample;
    larger.Validate();
    check_memory(larger);
    render = larger;
  } catch (const Error& e) {
    if (options.supersample)
      throw Error("--supersample", std::to_string(supersample),
                  "a factor whose frame fits (" + e.field() + " = " + e.value() + ": " + e.allowed() + ")");
    supersample = 1;
  }
  Tables tables = Tables::LoadOrPrecompute(device, atmosphere, precompute, options.tables.MakeLoadOptions());
  SceneRenderer renderer = MakeSceneRenderer(tables, scene, render);
  renderer.Render(scene);  // the first frame includes lavapipe's shader compilation
  const auto start = std::chrono::steady_clock::now();
  std::vector<PassTime> times = renderer.Render(scene);
  const double frame_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ImageRgbF frame = DownsampleBox(renderer.ReadOutput(), supersample);
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
    const bool binned = ImplOf(device).context->physical_device().getProperties().deviceType ==
                        ::vk::PhysicalDeviceType::eCpu;
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
                      "Anti-aliasing: render N times larger on each side and average each N x N block "
                      "(1 to 4; default 2, or 1 where the larger frame would not fit)");
  command->add_flag("--timings", options->timings, "Print the GPU time of each pass");
  options->tables.AddTo(*command);
  command->callback([options] { RunRender(*options); });
}

}  // namespace aerial::cli
