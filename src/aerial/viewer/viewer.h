#pragma once
// aerial view: the real-time viewer, a client of aerial's public API (include/aerial/) like an
// engine. It makes its device with the window's extensions and hands it to aerial::Device; each
// frame the scene goes through aerial's SceneRenderer (as in `aerial render`), recorded into the
// viewer's command buffer; the viewer's own passes only tone map it, or show a debug view of the
// images the renderer hands out, into the swapchain, with a Dear ImGui panel on top. Table changes
// are asked for and adopted apart from the window (table_supply.h) and made on a worker thread
// with its own device (table_worker.h), so the window keeps drawing
// with the old tables until the new ones arrive.
#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

#include "aerial/device.h"
#include "aerial/image/exposure.h"
#include "aerial/render/renderer_options.h"
#include "aerial/tables.h"
#include "aerial/viewer/camera_path.h"
#include "aerial/viewer/table_worker.h"
#include "aerial/viewer/view_settings.h"

struct GLFWwindow;

namespace aerial::viewer {

// How the window's picture reaches the screen: auto takes the X11 presenter on a CPU device whose
// window allows it (x11_presenter.h), a swapchain otherwise.
enum class PresentMode { kAuto, kSwapchain, kX11 };

struct ViewerOptions {
  Scene scene;
  AtmosphereParameters atmosphere;  // the base the panel's knobs change
  // The precompute options of each variant the panel may switch to (a variant missing here, e.g.
  // 3D with a nu resolution above 1, is not offered); `variant` is the one shown first.
  std::map<LutVariant, PrecomputeOptions> tables;
  LutVariant variant = LutVariant::k4D;
  TableLoadOptions load;
  DeviceOptions device;             // device and validation; the window's needs are added
  RendererOptions render;           // width and height: the window's first size
  Exposure exposure;                // automatic by default (aerial/image/exposure.h)
  // Gains of the pictures (the window, --screenshot and F12's PNG): the sun's white balance with
  // --white-balance on, {1, 1, 1} off; EXR screenshots stay linear radiance.
  std::array<double, 3> white_balance = {1.0, 1.0, 1.0};
  int frames = 0;                   // > 0: close after that many presented frames
  std::filesystem::path screenshot;  // written after the last frame, .png or .exr (checked by the caller)
  bool screenshot_panel = false;     // the screenshot (.png) is the window's picture, panel and all
  std::filesystem::path stats;       // frame statistics (frame_stats.h), written at exit
  std::optional<CameraPath> camera_path;
  // Dynamic resolution toward this frame time (dynamic_resolution.h); 0: off, the scale stays the
  // render options'. None: kCpuDeviceTargetMs on a CPU device (lavapipe), off on a GPU.
  std::optional<double> target_ms;
  PresentMode present = PresentMode::kAuto;
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
  const SceneRenderer& renderer() const;  // the one of the last frame
  const std::vector<PassTime>& last_passes() const;
  TableWorkStatus table_work() const;
  GLFWwindow* window() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

// Viewer(options).Run().
void RunViewer(ViewerOptions options);

}  // namespace aerial::viewer
