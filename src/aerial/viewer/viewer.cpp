#include "aerial/viewer/viewer.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "aerial/core/error.h"
#include "aerial/image/image_writer.h"
#include "aerial/viewer/display_passes.h"
#include "aerial/viewer/frame_stats.h"
#include "aerial/viewer/froxel_export.h"
#include "aerial/viewer/imgui_layer.h"
#include "aerial/viewer/input.h"
#include "aerial/viewer/panel.h"
#include "aerial/viewer/render_stack.h"
#include "aerial/viewer/screenshot.h"
#include "aerial/viewer/sun_control.h"
#include "aerial/viewer/table_worker.h"
#include "aerial/viewer/window.h"
#include "aerial/vk/swapchain.h"

namespace aerial::viewer {
namespace {

using Clock = std::chrono::steady_clock;

// Frames the panel's FPS and frame time are the median of.
constexpr size_t kPanelWindow = 30;

LutVariant Other(LutVariant variant) {
  return variant == LutVariant::k4D ? LutVariant::k3D : LutVariant::k4D;
}

vk::ContextCreateInfo WithWindowSupport(vk::ContextCreateInfo info) {
  GlfwSession::AddWindowSupport(info);
  return info;
}

const char* PassName(DebugView view) {
  return view == DebugView::kFinal ? "present" : "debug view";
}

class Viewer {
 public:
  explicit Viewer(ViewerOptions options);
  void Run();

 private:
  RenderOptions CurrentRenderOptions() const;
  bool HasCurrentTables(LutVariant variant) const;
  void RequestTables();
  void AdoptFinishedTables();
  void Resize(::vk::Extent2D extent);
  void Steer(const FrameInput& input, double dt_s);
  double MaxSunZenithDeg() const;
  void FollowSunClock();
  void Act(const PanelEvents& events, const std::vector<int>& keys, const Renderer& renderer);
  void Say(std::string message);
  std::vector<vk::PassTime> Draw(Renderer& primary, Renderer* other);
  PanelInfo MakePanelInfo(const Renderer& primary) const;

  ViewerOptions options_;
  ViewSettings settings_;
  AtmosphereParameters wanted_;                // the base with the panel's knobs applied
  std::map<LutVariant, uint64_t> requested_;   // atmosphere hash asked of the worker, per variant
  GlfwSession glfw_;
  vk::ContextCreateInfo context_info_;
  vk::Context context_;
  RenderStack stack_;
  TableWorker worker_;
  Window window_;
  vk::Swapchain swapchain_;
  ImGuiLayer imgui_;
  InputReader input_;
  DisplayPasses display_;
  vk::GpuTimer timer_;
  FrameStats stats_;
  std::vector<vk::PassTime> last_passes_;
  std::string message_;
  int frames_ = 0;
};

Viewer::Viewer(ViewerOptions options)
    : options_(std::move(options)),
      wanted_(options_.atmosphere),
      context_info_(WithWindowSupport(options_.context)),
      context_(context_info_),
      stack_(options_.scene),
      worker_(options_.context),
      window_(context_, options_.render.width, options_.render.height, "aerial view: " + options_.scene.name),
      swapchain_(context_, window_.surface(), window_.framebuffer_extent()),
      imgui_(context_, window_.handle(), swapchain_),
      input_(window_.handle()),
      display_(context_, swapchain_.extent().width, swapchain_.extent().height),
      timer_(context_) {
  settings_.variant = options_.variant;
  settings_.knobs = ReadKnobs(options_.atmosphere);
  settings_.froxels = options_.render.froxels;
  settings_.mode = options_.render.mode;
  settings_.exposure = float(options_.exposure);
  // The first tables are loaded (or precomputed, with the terminal's progress bar) before the
  // first frame, on the viewer's own context.
  LoadedTables loaded = LoadOrPrecompute(context_, options_.atmosphere,
                                         options_.tables.at(options_.variant), options_.store);
  requested_[options_.variant] = options_.atmosphere.Hash();
  stack_.Install(std::move(loaded.tables), CurrentRenderOptions());
}

RenderOptions Viewer::CurrentRenderOptions() const {
  return {.width = int(swapchain_.extent().width),
          .height = int(swapchain_.extent().height),
          .froxels = settings_.froxels,
          .mode = settings_.mode};
}

bool Viewer::HasCurrentTables(LutVariant variant) const {
  const AtmosphereTables* tables = stack_.tables(variant);
  return tables && tables->atmosphere().Hash() == wanted_.Hash();
}

// Asks the worker for what the settings need and the stack lacks: the shown variant, and for the
// difference view the other one too. Edited atmospheres are not written to the cache, so that
// exploring does not fill it with a 32 MiB file per slider release.
void Viewer::RequestTables() {
  wanted_ = ApplyKnobs(options_.atmosphere, settings_.knobs);
  std::vector<LutVariant> needed = {settings_.variant};
  if (settings_.view == DebugView::kDifference) needed.push_back(Other(settings_.variant));
  for (LutVariant variant : needed) {
    if (HasCurrentTables(variant) || requested_[variant] == wanted_.Hash()) continue;
    auto options = options_.tables.find(variant);
    if (options == options_.tables.end()) {
      Say(ToString(variant) + " tables are not available with these table sizes");
      continue;
    }
    TableStoreOptions store = options_.store;
    store.write_cache = wanted_.Hash() == options_.atmosphere.Hash();
    worker_.Submit({.slot = int(variant), .atmosphere = wanted_, .options = options->second, .store = store});
    requested_[variant] = wanted_.Hash();
  }
}

// Uploads the worker's finished tables into this context; results for an atmosphere the panel has
// since left are dropped.
void Viewer::AdoptFinishedTables() {
  while (std::optional<TableResult> result = worker_.TakeResult()) {
    const TableRequest& request = result->request;
    if (!result->tables) {
      Say("tables: " + result->error);
      continue;
    }
    if (request.atmosphere.Hash() != wanted_.Hash()) continue;
    auto tables = std::make_unique<AtmosphereTables>(context_, request.atmosphere, request.options);
    tables->Upload(*result->tables);
    stack_.Install(std::move(tables), CurrentRenderOptions());
  }
}

void Viewer::Resize(::vk::Extent2D extent) {
  swapchain_.Recreate(extent);
  imgui_.OnSwapchainRecreated(swapchain_);
  display_.Resize(swapchain_.extent().width, swapchain_.extent().height);
}

// The camera follows the path while it lasts, then the fly controls; the sun follows the keys and
// the mouse, within the zenith angles the tables cover.
void Viewer::Steer(const FrameInput& input, double dt_s) {
  Scene& scene = options_.scene;
  double path_time = frames_ * kFrameStepS;
  if (options_.camera_path && path_time <= options_.camera_path->duration_s()) {
    options_.camera_path->Apply(path_time, scene.camera);
  } else {
    Fly(scene.camera, input.fly, dt_s, options_.atmosphere.bottom_radius_m);
  }
  SteerSun(scene.sun, input.sun_d_azimuth_deg, input.sun_d_zenith_deg, MaxSunZenithDeg());
}

// The lowest sun the tables cover: mu_s_min (parameters.h).
double Viewer::MaxSunZenithDeg() const {
  return std::acos(options_.atmosphere.mu_s_min) * 180.0 / std::numbers::pi;
}

void Viewer::Say(std::string message) {
  std::printf("%s\n", message.c_str());
  std::fflush(stdout);
  message_ = std::move(message);
}

void Viewer::FollowSunClock() {
  options_.scene.sun = SunAtSolarTime(settings_.solar_time_h, settings_.latitude_deg, settings_.declination_deg);
  SteerSun(options_.scene.sun, 0.0, 0.0, MaxSunZenithDeg());
}

// Screenshots and exports of the frame just rendered.
void Viewer::Act(const PanelEvents& events, const std::vector<int>& keys, const Renderer& renderer) {
  bool screenshot = events.screenshot, export_vdb = events.export_vdb;
  for (int key : keys) {
    screenshot |= key == GLFW_KEY_F12 || key == GLFW_KEY_P;
    export_vdb |= key == GLFW_KEY_V;
  }
  if (screenshot) {
    try {
      Say(SaveScreenshots(renderer, settings_.exposure));
    } catch (const Error& e) {
      Say(std::string("screenshot: ") + e.what());
    }
  }
  if (export_vdb) Say(ExportFroxelsToVdb(renderer));
}

// The display pass for the settings' view, the blit into the swapchain and the panel over it.
std::vector<vk::PassTime> Viewer::Draw(Renderer& primary, Renderer* other) {
  bool recorded = false;
  auto prepare = [&](const ::vk::raii::CommandBuffer& cmd) {
    recorded = true;
    timer_.Reset(cmd);
    timer_.Begin(cmd, PassName(other ? DebugView::kDifference : settings_.view));
    switch (other ? DebugView::kDifference : settings_.view) {
      case DebugView::kFinal:
        display_.RecordToneMap(cmd, primary.output_image(), settings_.exposure);
        break;
      case DebugView::kRayleigh:
      case DebugView::kMie:
      case DebugView::kTransmittance:
        display_.RecordTerm(cmd, primary, DisplayPasses::Term(int(settings_.view) - int(DebugView::kRayleigh)),
                            settings_.exposure);
        break;
      case DebugView::kFroxelSlice:
        display_.RecordFroxelSlice(cmd, primary.froxels(), settings_.froxel_slice, settings_.exposure);
        break;
      case DebugView::kDifference: {
        bool primary_4d = primary.tables().options().variant == LutVariant::k4D;
        const Renderer& l4 = primary_4d ? primary : *other;
        const Renderer& l3 = primary_4d ? *other : primary;
        display_.RecordDifference(cmd, l4.output_image(), l3.output_image(), settings_.difference_full_scale);
        break;
      }
    }
    timer_.End(cmd);
  };
  auto overlay = [&](const ::vk::raii::CommandBuffer& cmd) {
    timer_.Begin(cmd, "panel");
    imgui_.Record(cmd);
    timer_.End(cmd);
  };
  bool presented = swapchain_.Present(display_.display(), prepare, overlay);
  std::vector<vk::PassTime> times = recorded ? timer_.Collect() : std::vector<vk::PassTime>{};
  if (presented) return times;
  ::vk::Extent2D extent = window_.framebuffer_extent();
  if (extent.width > 0 && extent.height > 0) Resize(extent);
  return {};
}

PanelInfo Viewer::MakePanelInfo(const Renderer& primary) const {
  const AtmosphereTables& tables = primary.tables();
  double frame_ms = stats_.MedianFrameMs(kPanelWindow);
  return {.fps = frame_ms > 0.0 ? 1000.0 / frame_ms : 0.0,
          .frame_ms = frame_ms,
          .passes = last_passes_,
          .work = worker_.status(),
          .tables = tables.options().Describe() +
                    (tables.atmosphere().Hash() == wanted_.Hash() ? "" : " (previous atmosphere)"),
          .message = message_,
          .difference_ready = HasCurrentTables(LutVariant::k4D) && HasCurrentTables(LutVariant::k3D)};
}

void Viewer::Run() {
  Clock::time_point last = Clock::now();
  Renderer* primary = nullptr;
  while (options_.frames == 0 || frames_ < options_.frames) {
    glfwPollEvents();
    if (window_.should_close()) break;
    ::vk::Extent2D extent = window_.framebuffer_extent();
    if (extent.width == 0 || extent.height == 0) {  // minimized: nothing to draw into
      glfwWaitEvents();
      last = Clock::now();
      continue;
    }
    if (extent != swapchain_.extent()) Resize(extent);
    AdoptFinishedTables();
    double dt_s = std::chrono::duration<double>(Clock::now() - last).count();

    imgui_.NewFrame();
    Steer(input_.Read(dt_s, imgui_.wants_mouse(), imgui_.wants_keyboard()), dt_s);
    RenderOptions render = CurrentRenderOptions();
    primary = stack_.Get(settings_.variant, render);
    if (!primary) primary = stack_.Get(Other(settings_.variant), render);
    PanelEvents events = DrawPanel(settings_, MakePanelInfo(*primary));
    imgui_.EndFrame();
    if (events.sun_clock_moved) FollowSunClock();
    RequestTables();

    std::vector<vk::PassTime> passes = primary->Render(options_.scene);
    std::vector<int> keys = window_.TakeKeyPresses();
    if (imgui_.wants_keyboard()) keys.clear();
    Act(events, keys, *primary);
    Renderer* other = nullptr;
    if (settings_.view == DebugView::kDifference && HasCurrentTables(LutVariant::k4D) &&
        HasCurrentTables(LutVariant::k3D) && HasCurrentTables(settings_.variant)) {
      other = stack_.Get(Other(settings_.variant), render);
      for (vk::PassTime pass : other->Render(options_.scene)) {
        pass.pass += " (" + ToString(other->tables().options().variant) + ")";
        passes.push_back(pass);
      }
    }
    std::vector<vk::PassTime> display = Draw(*primary, other);
    if (display.empty()) continue;  // not presented: the swapchain was out of date
    passes.insert(passes.end(), display.begin(), display.end());
    Clock::time_point now = Clock::now();
    stats_.AddFrame(std::chrono::duration<double, std::milli>(now - last).count(), passes);
    last = now;
    last_passes_ = std::move(passes);
    ++frames_;
  }
  if (!options_.screenshot.empty() && primary)
    WriteImage(options_.screenshot, primary->ReadOutput(), {.exposure = settings_.exposure});
  if (!options_.stats.empty()) stats_.Write(options_.stats);
}

}  // namespace

void RunViewer(ViewerOptions options) { Viewer(std::move(options)).Run(); }

}  // namespace aerial::viewer
