#include "aerial/cli/scene_options.h"

#include <new>
#include <utility>
#include <vector>

#include "aerial/cli/path_option.h"
#include "aerial/core/toml_reader.h"
#include "aerial/error.h"
#include "aerial/scene/scene_file.h"

namespace aerial::cli {

void SceneOptions::AddTo(CLI::App& command) {
  auto* scene = AddPathOption(command, "--scene", scene_file, "Scene file (TOML)");
  command.add_option("--preset", preset, "Built-in scene (default noon)")
      ->check(CLI::IsMember(PresetNames()))
      ->excludes(scene);
  command.add_option("--camera-position-m", camera_position_m,
                     "Camera position x,y,z in the scene frame (m; x east, y north, z up)")
      ->delimiter(',')->expected(3)->default_str("");  // a vector: no default to show
  command.add_option("--camera-yaw-deg", overrides.camera_yaw_deg, "Camera compass azimuth (deg)");
  command.add_option("--camera-pitch-deg", overrides.camera_pitch_deg, "Camera elevation (deg)");
  command.add_option("--camera-fov-deg", overrides.camera_fov_deg, "Vertical field of view (deg)");
  command.add_option("--sun-zenith-deg", overrides.sun_zenith_deg, "Sun zenith angle (deg)");
  command.add_option("--sun-azimuth-deg", overrides.sun_azimuth_deg, "Sun compass azimuth (deg)");
  sun_date.AddTo(command);
}

Scene SceneOptions::Load(double planet_radius_m, const MemoryBudget& budget) const {
  Scene scene;
  try {
    scene = scene_file.empty() ? BuildPreset(preset.empty() ? "noon" : preset, planet_radius_m)
                               : LoadSceneFile(scene_file, planet_radius_m, budget);
  } catch (const std::bad_alloc&) {
    // Past the models' estimates (gltf_loader.h): it is the scene that is too big, not the frame.
    throw Error("--scene", scene_file.string(),
                "a scene whose models fit in this machine's memory (a lower --max-memory-mib makes "
                "the estimate stop it first)");
  }
  SceneOverrides all = overrides;
  all.sun_date = sun_date.Make();
  if (!camera_position_m.empty()) {
    all.camera_position_m =
        glm::dvec3(camera_position_m[0], camera_position_m[1], camera_position_m[2]);
  }
  ApplyOverrides(scene, all, planet_radius_m);
  return scene;
}

std::string SceneOptions::Source() const {
  return !scene_file.empty() ? scene_file.string() : preset.empty() ? "noon" : preset;
}

void FroxelOptions::AddTo(CLI::App& command) {
  command.add_option("--froxels", froxels, "Froxel grid WxHxD (default 32x32x32)");
  command.add_option("--froxel-far-m", froxel_far_m, "Distance covered by the froxels (m)");
}

FroxelGrid FroxelOptions::Make() const {
  FroxelGrid grid = FroxelGrid::Parse(froxels);
  grid.far_m = froxel_far_m;
  grid.Validate();  // the resolution passed Parse, so only the distance can fail here
  return grid;
}

namespace {

// --aerial's names, the one place they are spelled (the option's check and ParseAerialMode).
const std::vector<std::pair<std::string, AerialMode>> kAerialModes = {
    {"froxel", AerialMode::kFroxel},
    {"per-pixel", AerialMode::kPerPixel},
    {"table-difference", AerialMode::kTableDifference},
};

std::vector<std::string> AerialModeNames() {
  std::vector<std::string> names;
  for (const auto& [name, mode] : kAerialModes) names.push_back(name);
  return names;
}

}  // namespace

AerialMode ParseAerialMode(const std::string& value) {
  for (const auto& [name, mode] : kAerialModes)
    if (name == value) return mode;
  throw Error("--aerial", value, "froxel, per-pixel or table-difference");
}

bool ParseShadows(const std::string& value) {
  if (value != "on" && value != "off") throw Error("--shadows", value, "on or off");
  return value == "on";
}

void FrameOptions::AddTo(CLI::App& command, const std::string& size_help) {
  command.add_option("--width", width, size_help + " width in pixels");
  command.add_option("--height", height, size_help + " height in pixels");
  CLI::Option* ev100_option = command.add_option(
      "--ev100", ev100,
      "Fixed exposure value at ISO 100 for PNG images and the viewer's window (default: automatic, "
      "metered from the frame's log-average luminance; EXR is always linear radiance)");
  command.add_option("--exposure", exposure, "Fixed radiance multiplier before tone mapping, instead of --ev100")
      ->excludes(ev100_option);
  command.add_option("--aerial", aerial,
                     "Aerial perspective: froxel (default), per-pixel (marched per pixel, the reference) "
                     "or table-difference (two table reads per pixel, as Bruneton 2017's demo)")
      ->check(CLI::IsMember(AerialModeNames()));
  command.add_option("--froxel-reads", froxel_reads,
                     "Where surfaces read the froxels: auto (per vertex on triangles small in the air or "
                     "the volume, per pixel on the others; default), per-pixel, per-vertex or full-screen "
                     "(per pixel, in a pass over the screen after the surfaces: deferred)")
      ->check(CLI::IsMember({"auto", "per-pixel", "per-vertex", "full-screen"}));
  command.add_option("--render-scale", render_scale,
                     "Rasterize at this fraction (0.25 to 1) of the size, then upscale (default 1)");
  command.add_option("--terrain", terrain,
                     "Terrain: lod (level of detail following the camera, default) or mesh (the fixed "
                     "294K-triangle reference mesh)")
      ->check(CLI::IsMember({"lod", "mesh"}));
  command.add_option("--terrain-selection", terrain_selection,
                     "Where the terrain's chunks and shadow casters are selected: auto (on the GPU, on the "
                     "CPU on a CPU device such as lavapipe; default), cpu or gpu")
      ->check(CLI::IsMember({"auto", "cpu", "gpu"}));
  command.add_option("--terrain-error-px", terrain_error_px,
                     "Terrain level of detail: largest height error on screen, in pixels at 720 rows "
                     "or more (0.25 to 64)");
  command.add_option("--shadows", shadows,
                     "The sun's shadow map of the terrain and the opaque meshes on surfaces: on (default) "
                     "or off");
  command.add_option("--white-balance", white_balance,
                     "PNG pictures (and the viewer's window) divided by the sun's colour, so that sunlight "
                     "is white: on (default) or off; EXR output is never white-balanced")
      ->check(CLI::IsMember({"on", "off"}));
  froxels.AddTo(command);
}

ToneMapOptions FrameOptions::MakeToneMap(const ImageRgbF& frame, const Spectrum& sun_colour) const {
  std::array<double, 3> white_balance = WhiteBalance(sun_colour);
  return {.exposure = MakeExposure().MultiplierFor(frame, white_balance), .white_balance = white_balance};
}

std::array<double, 3> FrameOptions::WhiteBalance(const Spectrum& sun_colour) const {
  if (white_balance == "on") return WhiteBalanceForSun(sun_colour);
  return {1.0, 1.0, 1.0};
}

Exposure FrameOptions::MakeExposure() const {
  if (exposure) {
    // A radiance multiplier, as a float in the viewer's shader and the tone map: above 1e6 even
    // the sun's disc (~2e4 W/m^2/sr/nm) is white a million times over, and 1e300 is infinite as a
    // float.
    if (!(*exposure > 0.0 && *exposure <= 1e6))
      throw Error("--exposure", TomlFloat(*exposure), "a multiplier in (0, 1e6]");
    return {.mode = Exposure::Mode::kMultiplier, .value = *exposure};
  }
  if (ev100) {
    // From a moonless night (-6) to the sun's disc (about 24), with room on both sides.
    if (!(*ev100 >= -10.0 && *ev100 <= 30.0)) throw Error("--ev100", TomlFloat(*ev100), "-10 to 30");
    return {.mode = Exposure::Mode::kEv100, .value = *ev100};
  }
  return {};
}

RendererOptions FrameOptions::MakeRenderOptions() const {
  MakeExposure();  // checked with the rest of the frame's options, before any work
  RendererOptions render;
  render.width = width;
  render.height = height;
  render.froxels = froxels.Make();
  render.mode = ParseAerialMode(aerial);
  render.surface_froxel_reads = froxel_reads == "per-pixel"     ? SurfaceFroxelReads::kPerPixel
                                : froxel_reads == "per-vertex"  ? SurfaceFroxelReads::kPerVertex
                                : froxel_reads == "full-screen" ? SurfaceFroxelReads::kFullScreenPass
                                                                : SurfaceFroxelReads::kPerVertexWhereThin;
  render.render_scale = render_scale;
  render.terrain = terrain == "mesh" ? TerrainMode::kStaticMesh : TerrainMode::kLod;
  render.terrain_selector = terrain_selection == "cpu"   ? TerrainSelector::kCpu
                            : terrain_selection == "gpu" ? TerrainSelector::kGpu
                                                         : TerrainSelector::kAuto;
  render.terrain_error_px = terrain_error_px;
  render.shadows = ParseShadows(shadows);
  render.Validate();
  return render;
}

}  // namespace aerial::cli
