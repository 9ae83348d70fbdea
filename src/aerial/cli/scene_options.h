#pragma once
// Options shared by the commands that draw a scene (render, view): which scene, camera and sun
// overrides, and the frame's shape (size, froxels, aerial perspective mode, exposure).
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "aerial/render/renderer.h"
#include "aerial/scene/scene_overrides.h"

namespace aerial::cli {

struct SceneOptions {
  std::filesystem::path scene_file;
  std::string preset;
  std::vector<double> camera_position_m;  // x, y, z
  SceneOverrides overrides;

  void AddTo(CLI::App& command);
  // The preset (noon by default) or the scene file, with the overrides applied.
  Scene Load(double planet_radius_m) const;
};

struct FrameOptions {
  std::string froxels = "32x32x32";
  double froxel_far_m = 128e3;
  int width = 1280;
  int height = 720;
  double exposure = 8.0;
  std::string aerial = "froxel";

  // size_help: what --width/--height set ("Image width in pixels").
  void AddTo(CLI::App& command, const std::string& size_help);
  RenderOptions MakeRenderOptions() const;  // validated
};

}  // namespace aerial::cli
