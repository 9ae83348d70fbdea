#pragma once
// Options shared by the commands that draw a frame of a scene (render, view, export-vdb): which
// scene, the camera and sun overrides, the froxel grid and the frame's shape. Registered once
// here so every command spells and checks them the same way.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "aerial/cli/scene_overrides.h"
#include "aerial/cli/sun_date_options.h"
#include "aerial/core/memory_budget.h"
#include "aerial/froxel_grid.h"
#include "aerial/image/exposure.h"
#include "aerial/render/renderer_options.h"
#include "aerial/scene.h"

namespace aerial::cli {

struct SceneOptions {
  std::filesystem::path scene_file;
  std::string preset;
  std::vector<double> camera_position_m;  // x, y, z
  SceneOverrides overrides;
  SunDateOptions sun_date;

  // --scene, --preset and the camera and sun overrides (angles, or a date and a place).
  void AddTo(CLI::App& command);
  // The preset (noon by default) or the scene file, with the overrides applied (validated); the
  // scene's glTF models load within budget.
  Scene Load(double planet_radius_m, const MemoryBudget& budget) const;
  // The scene file's path, or the preset's name, for messages.
  std::string Source() const;
};

struct FroxelOptions {
  std::string froxels = "32x32x32";
  double froxel_far_m = 128e3;

  // --froxels and --froxel-far-m.
  void AddTo(CLI::App& command);
  FroxelGrid Make() const;  // validated
};

// --shadows on|off, as aerial bench also takes it: true for "on"; anything but on or off throws
// Error("--shadows", value, "on or off").
bool ParseShadows(const std::string& value);

// --aerial froxel|per-pixel|table-difference; anything else throws Error("--aerial", value, ...).
AerialMode ParseAerialMode(const std::string& value);

struct FrameOptions {
  FroxelOptions froxels;
  int width = 1280;
  int height = 720;
  std::optional<double> exposure, ev100;  // neither: automatic exposure
  std::string aerial = "froxel";
  std::string froxel_reads = "auto";
  double render_scale = 1.0;
  std::string terrain = "lod";
  std::string terrain_selection = "auto";
  double terrain_error_px = kDefaultTerrainErrorPx;
  std::string shadows = "on";
  std::string white_balance = "on";

  // The froxel options, --width/--height (size_help: what they size, "Image"), --exposure,
  // --aerial, --froxel-reads, --render-scale, --terrain, --terrain-selection, --terrain-error-px,
  // --shadows and --white-balance.
  void AddTo(CLI::App& command, const std::string& size_help);
  RendererOptions MakeRenderOptions() const;  // validated
  Exposure MakeExposure() const;            // validated
  // The tone map of PNG pictures for tables whose sun has this colour (ShaderAtmosphere's
  // solar_irradiance): the exposure metered from `frame`, and WhiteBalance(sun_colour).
  ToneMapOptions MakeToneMap(const ImageRgbF& frame, const Spectrum& sun_colour) const;
  // The sun's white balance (WhiteBalanceForSun) with --white-balance on, else {1, 1, 1}.
  std::array<double, 3> WhiteBalance(const Spectrum& sun_colour) const;
};

}  // namespace aerial::cli
