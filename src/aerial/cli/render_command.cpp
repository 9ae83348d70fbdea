// aerial render: one frame of a scene through the atmosphere, to EXR (linear radiance) or PNG
// (tone-mapped sRGB). The output path is checked before any work, and written atomically.
#include <cstdio>
#include <memory>
#include <optional>

#include "aerial/cli/commands.h"
#include "aerial/cli/common_options.h"
#include "aerial/image/image_writer.h"
#include "aerial/render/renderer.h"
#include "aerial/scene/presets.h"
#include "aerial/scene/scene_file.h"
#include "aerial/scene/scene_overrides.h"

namespace aerial::cli {
namespace {

struct RenderCommandOptions {
  TableOptions tables;
  std::filesystem::path scene_file;
  std::string preset;
  std::string froxels = "32x32x32";
  double froxel_far_m = 128e3;
  int width = 1280;
  int height = 720;
  double exposure = 8.0;
  std::string aerial = "froxel";
  bool timings = false;
  std::filesystem::path out;
  std::vector<double> camera_position_m;  // x, y, z
  SceneOverrides overrides;
};

void RunRender(const RenderCommandOptions& options) {
  CheckImageOutputPath(options.out);
  AtmosphereParameters atmosphere = options.tables.LoadAtmosphere();
  RenderOptions render;
  render.width = options.width;
  render.height = options.height;
  render.froxels = FroxelGrid::Parse(options.froxels);
  render.froxels.far_m = options.froxel_far_m;
  render.mode = options.aerial == "per-pixel" ? AerialMode::kPerPixel : AerialMode::kFroxel;
  render.Validate();
  Scene scene = options.scene_file.empty()
                    ? BuildPreset(options.preset.empty() ? "noon" : options.preset,
                                  atmosphere.bottom_radius_m)
                    : LoadSceneFile(options.scene_file, atmosphere.bottom_radius_m);
  SceneOverrides overrides = options.overrides;
  if (!options.camera_position_m.empty()) {
    overrides.camera_position_m = glm::dvec3(options.camera_position_m[0], options.camera_position_m[1],
                                             options.camera_position_m[2]);
  }
  ApplyOverrides(scene, overrides, atmosphere.bottom_radius_m);
  auto context = options.tables.MakeContext();
  LoadedTables loaded = LoadOrPrecompute(*context, atmosphere, options.tables.MakePrecomputeOptions(),
                                         options.tables.MakeStoreOptions());
  Renderer renderer(*loaded.tables, scene, render);
  renderer.Render(scene);  // the first frame includes lavapipe's shader compilation
  std::vector<vk::PassTime> times = renderer.Render(scene);
  WriteImage(options.out, renderer.ReadOutput(), {.exposure = options.exposure});
  if (options.timings) {
    double total = 0.0;
    for (const auto& pass : times) {
      std::printf("  %-24s %9.2f ms\n", pass.pass.c_str(), pass.milliseconds);
      total += pass.milliseconds;
    }
    std::printf("  %-24s %9.2f ms\n", "total", total);
  }
}

}  // namespace

void AddRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderCommandOptions>();
  CLI::App* command = app.add_subcommand("render", "Render one frame of a scene to EXR or PNG");
  options->tables.AddTo(*command);
  auto* scene = command->add_option("--scene", options->scene_file, "Scene file (TOML)");
  command->add_option("--preset", options->preset,
                      "Built-in scene: noon (default), afternoon, sunset, twilight, high-altitude")
      ->excludes(scene);
  command->add_option("--froxels", options->froxels, "Froxel grid WxHxD (default 32x32x32)");
  command->add_option("--froxel-far-m", options->froxel_far_m, "Distance covered by the froxels (m)");
  command->add_option("--width", options->width, "Image width in pixels");
  command->add_option("--height", options->height, "Image height in pixels");
  command->add_option("--exposure", options->exposure, "Radiance multiplier before tone mapping (PNG)");
  command->add_option("--aerial", options->aerial, "Aerial perspective: froxel or per-pixel")
      ->check(CLI::IsMember({"froxel", "per-pixel"}));
  command->add_flag("--timings", options->timings, "Print the GPU time of each pass");
  command->add_option("--camera-position-m", options->camera_position_m,
                      "Camera position x,y,z in the scene frame (m; x east, y north, z up)")
      ->delimiter(',')->expected(3);
  command->add_option("--camera-yaw-deg", options->overrides.camera_yaw_deg, "Camera compass azimuth (deg)");
  command->add_option("--camera-pitch-deg", options->overrides.camera_pitch_deg, "Camera elevation (deg)");
  command->add_option("--camera-fov-deg", options->overrides.camera_fov_deg, "Vertical field of view (deg)");
  command->add_option("--sun-zenith-deg", options->overrides.sun_zenith_deg, "Sun zenith angle (deg)");
  command->add_option("--sun-azimuth-deg", options->overrides.sun_azimuth_deg, "Sun compass azimuth (deg)");
  command->add_option("--out", options->out, "Output image, .exr (linear) or .png (sRGB)")->required();
  command->callback([options] { RunRender(*options); });
}

}  // namespace aerial::cli
