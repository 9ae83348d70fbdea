#pragma once
// Options shared by the commands that draw a frame of a scene (render, export-vdb): which scene,
// the camera and sun overrides, and the froxel grid. Registered once here so both commands spell
// and check them the same way.
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "aerial/scene/scene.h"
#include "aerial/scene/scene_overrides.h"
#include "froxel/froxel_grid.h"

namespace aerial::cli {

struct SceneOptions {
  std::filesystem::path scene_file;
  std::string preset;
  std::vector<double> camera_position_m;  // x, y, z
  SceneOverrides overrides;

  // --scene, --preset and the camera and sun overrides.
  void AddTo(CLI::App& command);
  // The preset (noon by default) or the scene file, with the overrides applied (validated).
  Scene Load(double planet_radius_m) const;
};

struct FroxelOptions {
  std::string froxels = "32x32x32";
  double froxel_far_m = 128e3;

  // --froxels and --froxel-far-m.
  void AddTo(CLI::App& command);
  FroxelGrid Make() const;  // validated
};

}  // namespace aerial::cli
