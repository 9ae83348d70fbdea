#pragma once
// aerial view: the real-time viewer. Each frame the scene goes through aerial's one Renderer
// (render/renderer.h, as in `aerial render`); the viewer's own passes only tone map it, or show a
// debug view of the renderer's images, into the swapchain, with a Dear ImGui panel on top. Table
// changes are made on a worker thread with its own device (table_worker.h), so the window keeps
// drawing with the old tables until the new ones are uploaded.
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

#include "aerial/precompute/table_store.h"
#include "aerial/render/renderer.h"
#include "aerial/viewer/camera_path.h"
#include "aerial/viewer/table_worker.h"
#include "aerial/viewer/view_settings.h"

struct GLFWwindow;

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

class Viewer {
 public:
  // Opens the window and loads (or precomputes) the first tables.
  explicit Viewer(ViewerOptions options);
  ~Viewer();  // waits for a running background precompute

  // Draws frames until the window is closed or `frames` frames were presented, then writes the
  // screenshot and the statistics.
  void Run();
  // One frame (what Run repeats): false once the window is closed.
  bool Step();

  // For tests and tools that drive the viewer without a user: the panel's settings, changed in
  // place. Frame and display settings apply at the next Step; the atmosphere knobs only once
  // applied, as the panel applies them when a slider is released.
  ViewSettings& settings();
  void ApplyTableSettings();
  const Renderer& renderer() const;  // the one of the last frame
  const std::vector<vk::PassTime>& last_passes() const;
  TableWorkStatus table_work() const;
  GLFWwindow* window() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

// Viewer(options).Run().
void RunViewer(ViewerOptions options);

}  // namespace aerial::viewer
