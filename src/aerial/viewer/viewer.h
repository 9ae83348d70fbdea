#pragma once
// aerial view: the real-time viewer. Each frame the scene goes through aerial's one Renderer
// (render/renderer.h, as in `aerial render`); the viewer's own passes only tone map it, or show a
// debug view of the renderer's images, into the swapchain, with a Dear ImGui panel on top. Table
// changes are made on a worker thread with its own device (table_worker.h), so the window keeps
// drawing with the old tables until the new ones are uploaded.
#include <filesystem>
#include <map>
#include <optional>

#include "aerial/precompute/table_store.h"
#include "aerial/render/renderer.h"
#include "aerial/viewer/camera_path.h"

namespace aerial::viewer {

struct ViewerOptions {
  Scene scene;
  AtmosphereParameters atmosphere;  // the base the panel's knobs change
  // The precompute options of each variant the panel may switch to (a variant missing here, e.g.
  // 3D with a nu resolution above 1, is not offered); `variant` is the one shown first.
  std::map<LutVariant, PrecomputeOptions> tables;
  LutVariant variant = LutVariant::k4D;
  TableStoreOptions store;
  vk::ContextCreateInfo context;    // device and validation; the window's needs are added
  RenderOptions render;             // width and height: the window's first size
  double exposure = 8.0;
  int frames = 0;                   // > 0: close after that many presented frames
  std::filesystem::path screenshot;  // written after the last frame, .png or .exr (checked by the caller)
  std::filesystem::path stats;       // frame statistics (frame_stats.h), written at exit
  std::optional<CameraPath> camera_path;
};

// Opens the window and runs until it is closed or `frames` frames were presented.
void RunViewer(ViewerOptions options);

}  // namespace aerial::viewer
