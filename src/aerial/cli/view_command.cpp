// aerial view: the real-time viewer (src/aerial/viewer/). Scripted runs (--frames, --screenshot,
// --stats, --camera-path) check every path and file before the window opens, the outputs against
// each other and the inputs too.
#include <memory>
#include <optional>

#include "aerial/cli/commands.h"
#include "aerial/cli/common_options.h"
#include "aerial/cli/memory_uses.h"
#include "aerial/cli/path_option.h"
#include "aerial/cli/scene_options.h"
#include "aerial/core/atomic_file.h"
#include "aerial/core/output_conflicts.h"
#include "aerial/error.h"
#include "aerial/image/image_writer.h"
#include "aerial/precompute/spectral_precompute.h"
#include "aerial/viewer/viewer.h"

namespace aerial::cli {
namespace {

struct ViewCommandOptions {
  TableOptions tables;
  SceneOptions scene;
  FrameOptions frame;
  int frames = 0;
  std::filesystem::path screenshot;
  bool screenshot_panel = false;
  std::filesystem::path stats;
  std::filesystem::path camera_path;
  std::optional<double> target_ms;
  std::string present = "auto";
  bool render_scale_given = false;
};

// The precompute options of both variants, for the panel's 3D/4D switch: the command line's
// resolutions with the other --lut. A variant those resolutions do not allow (3D needs NU = 1) is
// left out, unless it is the one asked for, which then fails as in any other command.
std::map<LutVariant, PrecomputeOptions> TableVariants(const TableOptions& tables) {
  std::map<LutVariant, PrecomputeOptions> variants;
  LutVariant asked = ParseLutVariant(tables.lut, "--lut");
  variants[asked] = tables.MakePrecomputeOptions();
  TableOptions other = tables;
  other.lut = asked == LutVariant::k4D ? "3d" : "4d";
  try {
    variants[ParseLutVariant(other.lut, "--lut")] = other.MakePrecomputeOptions();
  } catch (const Error&) {
    // Offered as unavailable in the panel.
  }
  return variants;
}

// The scene, each variant's tables (the difference view shows both, each drawn by its own
// renderer), the background precompute's scratch, and the window. A short-lived device of the same choice gives
// the budget its heap size, before the viewer allocates anything.
void CheckViewerMemory(const TableOptions& tables, const viewer::ViewerOptions& viewer, const std::string& scene) {
  std::vector<MemoryUse> uses =
      Combined(SwapchainMemoryUses(viewer.render), SceneMemoryUses(viewer.scene, scene, int(viewer.tables.size())));
  for (const auto& [variant, precompute] : viewer.tables) uses = Combined(uses, TableMemoryUses(precompute));
  uses = Combined(uses, FrameMemoryUses(viewer.render, int(viewer.tables.size())));
  tables.MakeMemoryBudget(Device(viewer.device).largest_heap_bytes()).Check(uses);
}

void RunView(const ViewCommandOptions& options) {
  if (!options.screenshot.empty()) {
    if (options.frames == 0) {
      throw Error("--screenshot", options.screenshot.string(),
                  "--frames N as well (it saves the last frame)");
    }
    CheckImageOutputPath(options.screenshot, "--screenshot");
  }
  if (options.screenshot_panel &&
      (options.screenshot.empty() || ImageFormatFromPath(options.screenshot, "--screenshot") != ImageFormat::kPng))
    throw Error("--screenshot-panel", options.screenshot.string(), "with --screenshot FILE.png (the window's 8-bit picture)");
  if (!options.stats.empty()) CheckOutputFile(options.stats, "--stats");
  viewer::ViewerOptions viewer;
  viewer.atmosphere = options.tables.LoadAtmosphere();
  viewer.render = options.frame.MakeRenderOptions();
  viewer.tables = TableVariants(options.tables);
  viewer.variant = ParseLutVariant(options.tables.lut, "--lut");
  if (!options.camera_path.empty())
    viewer.camera_path = viewer::CameraPath::Load(options.camera_path, viewer.atmosphere.bottom_radius_m);
  viewer.scene = options.scene.Load(viewer.atmosphere.bottom_radius_m, options.tables.MakeHostMemoryBudget());
  CheckOutputConflicts({{"--screenshot", options.screenshot}, {"--stats", options.stats}});
  viewer.load = options.tables.MakeLoadOptions();
  viewer.device = options.tables.MakeDeviceOptions();
  CheckViewerMemory(options.tables, viewer, options.scene.Source());
  viewer.exposure = options.frame.MakeExposure();
  // Both variants' tables share the colour mode and the sun, which the panel does not change.
  viewer.white_balance = options.frame.WhiteBalance(
      ShaderAtmosphere(viewer.atmosphere, viewer.tables.at(viewer.variant)).solar_irradiance);
  viewer.frames = options.frames;
  viewer.screenshot = options.screenshot;
  viewer.screenshot_panel = options.screenshot_panel;
  viewer.stats = options.stats;
  // A scale asked for is kept; else the viewer chooses (dynamic on a CPU device).
  viewer.target_ms = options.render_scale_given ? options.target_ms.value_or(0.0) : options.target_ms;
  viewer.present = options.present == "x11"         ? viewer::PresentMode::kX11
                   : options.present == "swapchain" ? viewer::PresentMode::kSwapchain
                                                    : viewer::PresentMode::kAuto;
  viewer::RunViewer(std::move(viewer));
}

}  // namespace

void AddViewCommand(CLI::App& app) {
  auto options = std::make_shared<ViewCommandOptions>();
  CLI::App* command = app.add_subcommand("view", "Real-time viewer: fly through a scene, tune the atmosphere");
  options->scene.AddTo(*command);
  options->frame.AddTo(*command, "Window");
  command->add_option("--frames", options->frames, "Close after N frames (scripted runs)")
      ->check(CLI::Range(1, 100000000));
  AddPathOption(*command, "--screenshot", options->screenshot,
                      "With --frames: save the last frame, .exr (linear) or .png (sRGB)");
  command->add_flag("--screenshot-panel", options->screenshot_panel,
                    "The --screenshot PNG is the window as shown, the panel included");
  AddPathOption(*command, "--stats", options->stats,
                      "Write frame statistics (median and p95 frame ms, FPS, GPU ms per pass) as JSON");
  command->add_option("--target-ms", options->target_ms,
                      "Dynamic resolution: while the view moves, the render scale (0.5, 0.75 or 1; it starts "
                      "at 0.5) follows the frame time toward this many milliseconds; 0: off (default: 33.3 "
                      "on a CPU device unless --render-scale is given, off on a GPU)")
      ->check(CLI::Range(0.0, 1000.0));
  command->add_option("--present", options->present,
                      "How the picture reaches the window: a Vulkan swapchain, or sent to the X server by "
                      "aerial in bands of rows (x11; an X server without DRI3 takes a CPU device's "
                      "swapchain frames in one large request, slowly); auto: x11 on a CPU device, swapchain "
                      "on a GPU")
      ->check(CLI::IsMember({"auto", "swapchain", "x11"}));
  AddPathOption(*command, "--camera-path", options->camera_path,
                      "Camera path to play, 1/30 s of path time per frame (TOML, examples/paths/)");
  options->tables.AddTo(*command);
  command->callback([options, command] {
    options->render_scale_given = command->get_option("--render-scale")->count() > 0;
    RunView(*options);
  });
}

}  // namespace aerial::cli
