#include "aerial/viewer/viewer.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <tuple>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "aerial/core/atomic_file.h"
#include "aerial/error.h"
#include "aerial/image.h"
#include "aerial/image/exposure.h"
#include "aerial/image/resample.h"
#include "aerial/viewer/display_passes.h"
#include "aerial/viewer/dynamic_resolution.h"
#include "aerial/viewer/exposure_meter.h"
#include "aerial/viewer/frame_accumulator.h"
#include "aerial/viewer/frame_stats.h"
#include "aerial/viewer/froxel_export.h"
#include "aerial/viewer/imgui_layer.h"
#include "aerial/viewer/input.h"
#include "aerial/viewer/key_commands.h"
#include "aerial/viewer/panel.h"
#include "aerial/viewer/render_stack.h"
#include "aerial/viewer/screenshot.h"
#include "aerial/viewer/sun_control.h"
#include "aerial/viewer/table_supply.h"
#include "aerial/viewer/window.h"
#include "aerial/viewer/x11_presenter.h"
#include "aerial/vk/command_ring.h"
#include "aerial/vk/gpu_timer.h"
#include "aerial/vk/swapchain.h"

namespace aerial::viewer {
namespace {

using Clock = std::chrono::steady_clock;

// Frames the panel's FPS and frame time are the median of.
constexpr size_t kPanelWindow = 30;

// The CPU records frame n + 1 (input, panel, terrain selection, sorting) while the GPU draws
// frame n.
constexpr uint32_t kFramesInFlight = 2;

// The X11 presenter where the device renders into host memory (a CPU device: its frames are read
// where they are) and the window takes its texels; a swapchain everywhere else, and always on a
// GPU, whose images would cross the bus each frame (x11_presenter.h).
std::unique_ptr<vk::PresentTarget> MakePresentTarget(const vk::Context& context, const Window& window,
                                                     PresentMode mode) {
  const bool x11 = mode == PresentMode::kX11 ||
                   (mode == PresentMode::kAuto && context.cpu_device() && !X11Presenter::Unsupported(window.handle()));
  if (x11)
    return std::make_unique<X11Presenter>(context, window.handle(), window.framebuffer_extent(), kFramesInFlight);
  return std::make_unique<vk::Swapchain>(context, window.surface(), window.framebuffer_extent(), kFramesInFlight);
}

// CPU time a frame may spend building terrain chunks when the camera moves into new detail: the
// chunks it lacks are drawn coarser until later frames have built them.
constexpr double kTerrainBuildBudgetMs = 3.0;

LutVariant Other(LutVariant variant) {
  return variant == LutVariant::k4D ? LutVariant::k3D : LutVariant::k4D;
}

// The viewer's own Vulkan device: the one aerial is asked for, with what the window needs.
vk::ContextCreateInfo WithWindowSupport(const DeviceOptions& device) {
  vk::ContextCreateInfo info{.device_name = device.device_name, .validation = device.validation};
  GlfwSession::AddWindowSupport(info);
  return info;
}


const char* PassName(DebugView view) {
  return view == DebugView::kFinal ? "present" : "debug view";
}

// The viewer's renderers differ from `aerial render`'s in how they pace work: frames in flight,
// and terrain chunks built within a budget.
RendererOptions ForTheWindow(RendererOptions render) {
  render.terrain_build_budget_ms = kTerrainBuildBudgetMs;
  render.frames_in_flight = kFramesInFlight;
  return render;
}

// The first tables, loaded (or precomputed, with the terminal's progress bar) on the viewer's own
// device before the window opens, and their renderer at the size asked for.
RenderStack FirstStack(const Device& device, const ViewerOptions& options, std::function<void()> before_rebuild) {
  RenderStack stack(options.scene, std::move(before_rebuild));
  stack.Install(std::make_unique<Tables>(Tables::LoadOrPrecompute(device, options.atmosphere,
                                                                   options.tables.at(options.variant), options.load)),
                ForTheWindow(options.render));
  return stack;
}

}  // namespace

// The viewer's state; Viewer's methods forward to it. Members are declared in the order they are
// built (GLFW before the Vulkan instance that needs its extensions, the context before everything
// made with it) and so destroyed in reverse; the worker last, so that the window closes before it
// waits for a running precompute.
class Viewer::Impl {
 public:
  explicit Impl(ViewerOptions options);
  // Frames in flight use what the members below own: wait for them before any is destroyed.
  // (A destructor must not throw: a lost device has nothing left to wait for.)
  ~Impl() {
    try {
      ring_.WaitAll();
    } catch (const std::exception&) {
    }
  }
  bool Step();
  void Run();
  GLFWwindow* window() const { return window_.handle(); }

  TableSupply supply_;             // its worker has its own context, and nothing of the others
  ViewSettings settings_;
  AtmosphereKnobs applied_knobs_;  // the knobs the tables are asked for (the panel's, on release)
  std::vector<PassTime> last_passes_;
  SceneRenderer* shown_ = nullptr;  // the renderer of the last frame

 private:
  RendererOptions CurrentRenderOptions() const;
  bool HasCurrentTables(LutVariant variant) const;
  void RequestTables();
  void AdoptFinishedTables();
  void Resize(::vk::Extent2D extent);
  void Steer(const FrameInput& input, double dt_s);
  double MaxSunZenithDeg() const;
  void FollowSunClock();
  void Act(const PanelEvents& events, const std::vector<int>& keys, const SceneRenderer& renderer);
  void Say(std::string message);
  void CollectFinishedFrame(uint32_t slot);
  void AdaptExposure(uint32_t slot, double dt_s);
  float DisplayExposure() const { return float(RadianceMultiplierFromEv100(settings_.ev100)); }
  void ForgetRecordedFrames();
  void RecordDisplay(const vk::CommandBuffer& cmd, uint32_t slot, const SceneRenderer& primary,
                     const SceneRenderer* other);
  ImageRgbF ShownFrame() const;
  PanelInfo MakePanelInfo(const SceneRenderer& primary) const;

  ViewerOptions options_;
  GlfwSession glfw_;
  vk::ContextCreateInfo context_info_;
  vk::Context context_;  // the window's device, the viewer's own
  Device device_;        // the same device, handed to aerial
  vk::CommandRing ring_;
  // The renderers each slot's frame was recorded with (and the suffix of their pass names), so
  // that their GPU times are read once the slot's frame has finished.
  std::vector<std::vector<std::pair<const SceneRenderer*, std::string>>> recorded_;
  RenderStack stack_;
  Window window_;
  std::unique_ptr<vk::PresentTarget> target_;  // the swapchain or the X11 presenter
  ImGuiLayer imgui_;
  InputReader input_;
  DisplayPasses display_;
  ExposureMeter meter_;
  FrameAccumulator accumulator_;  // the still view's antialiasing
  bool exposure_metered_ = false;  // auto exposure has had a first reading to start from
  std::vector<std::unique_ptr<vk::GpuTimer>> timers_;  // the display passes', per slot
  FrameStats stats_;
  // What the renderer's image shows, when the frame that drew it left nothing for later: the next
  // frames of the same view are drawn jittered into the accumulator's mean (frame_accumulator.h),
  // and once it is complete a frame only presents it again (the display pass and the panel), as an
  // idle view in an editor does. A still view on a CPU rasterizer then costs its present, not a frame.
  struct DrawnView {
    const SceneRenderer* renderer;
    Camera camera;
    Sun sun;
    double terrain_error_px;
    bool operator==(const DrawnView&) const = default;
  };
  std::optional<DrawnView> settled_view_;
  std::vector<bool> slot_used_ = std::vector<bool>(kFramesInFlight, false);
  std::string message_;
  const Camera start_camera_;  // where R puts the camera back
  bool panel_shown_ = true, help_shown_ = false;
  int frames_ = 0;
  Clock::time_point last_frame_end_;
  std::optional<DynamicResolution> resolution_;  // with --target-ms, or by default on a CPU device
  // The camera, sun and terrain error bound of the last frame: a view that keeps them is still.
  std::optional<std::tuple<Camera, Sun, double>> last_pose_;
  // The last frame's window picture (--screenshot-panel) and its size.
  std::optional<vk::Buffer> window_picture_;
  ::vk::Extent2D window_picture_extent_;
  void WriteWindowPicture() const;
};

Viewer::Impl::Impl(ViewerOptions options)
    : supply_(options.device, options.atmosphere, options.tables, options.load, options.variant),
      options_(std::move(options)),
      context_info_(WithWindowSupport(options_.device)),
      context_(context_info_),
      device_(context_.Handoff()),  // as an engine hands over its own (aerial/device.h)
      ring_(context_, kFramesInFlight),
      recorded_(kFramesInFlight),
      stack_(FirstStack(device_, options_, [this] { ForgetRecordedFrames(); })),
      window_(context_, options_.render.width, options_.render.height, "aerial view: " + options_.scene.name),
      target_(MakePresentTarget(context_, window_, options_.present)),
      imgui_(context_, window_.handle(), *target_),
      input_(window_.handle()),
      display_(context_, target_->render_pass(), target_->format()),
      meter_(context_, kFramesInFlight),
      accumulator_(context_),
      start_camera_(options_.scene.camera) {
  if (options_.screenshot_panel && !target_->can_copy_out())
    throw Error("--screenshot-panel", "on", "a window whose images can be copied out (this surface does not allow it)");
  for (uint32_t slot = 0; slot < kFramesInFlight; ++slot)
    timers_.push_back(std::make_unique<vk::GpuTimer>(context_));
  settings_.variant = options_.variant;
  settings_.knobs = applied_knobs_ = ReadKnobs(options_.atmosphere);
  settings_.froxels = options_.render.froxels;
  settings_.mode = options_.render.mode;
  settings_.render_scale = float(options_.render.render_scale);
  settings_.shadows = options_.render.shadows;
  settings_.terrain_error_px = float(options_.render.terrain_error_px);
  settings_.auto_exposure = options_.exposure.mode == Exposure::Mode::kAuto;
  if (!settings_.auto_exposure) settings_.ev100 = float(options_.exposure.FixedEv100());
  const double target_ms = options_.target_ms.value_or(context_.cpu_device() ? kCpuDeviceTargetMs : 0.0);
  if (target_ms > 0.0) {
    resolution_.emplace(target_ms);
    settings_.render_scale = std::min(settings_.render_scale, DynamicResolution::kMinScale);
  }
  last_frame_end_ = Clock::now();
}

RendererOptions Viewer::Impl::CurrentRenderOptions() const {
  RendererOptions render = ForTheWindow(options_.render);
  render.width = int(target_->extent().width);
  render.height = int(target_->extent().height);
  render.froxels = settings_.froxels;
  render.mode = settings_.mode;
  render.render_scale = settings_.render_scale;
  render.shadows = settings_.shadows;
  render.terrain_error_px = settings_.terrain_error_px;
  return render;
}

bool Viewer::Impl::HasCurrentTables(LutVariant variant) const {
  const Tables* tables = stack_.tables(variant);
  return tables && supply_.IsWanted(*tables);
}

// Asks for what the settings need and the stack lacks: the shown variant, and for the difference
// view the other one too.
void Viewer::Impl::RequestTables() {
  supply_.Want(applied_knobs_);
  std::vector<LutVariant> needed = {settings_.variant};
  if (settings_.view == DebugView::kDifference) needed.push_back(Other(settings_.variant));
  for (std::string& message : supply_.Request(needed, [this](LutVariant v) { return HasCurrentTables(v); }))
    Say(std::move(message));
}

void Viewer::Impl::AdoptFinishedTables() {
  std::vector<std::string> errors;
  for (std::unique_ptr<Tables>& tables : supply_.TakeFinished(device_, errors))
    stack_.Install(std::move(tables), CurrentRenderOptions());
  for (std::string& error : errors) Say(std::move(error));
}

void Viewer::Impl::Resize(::vk::Extent2D extent) {
  target_->Recreate(extent);
  imgui_.OnTargetRecreated(*target_);
}

// The camera (and the sun, where the path moves it) follows the path while it lasts, then the fly
// controls; the sun follows the keys and the mouse, within the zenith angles the tables cover.
void Viewer::Impl::Steer(const FrameInput& input, double dt_s) {
  Scene& scene = options_.scene;
  double path_time = frames_ * kFrameStepS;
  if (options_.camera_path && path_time <= options_.camera_path->duration_s()) {
    options_.camera_path->Apply(path_time, scene.camera);
    options_.camera_path->ApplySun(path_time, scene.sun);
  } else {
    Fly(scene.camera, input.fly, dt_s, options_.atmosphere.bottom_radius_m);
  }
  SteerSun(scene.sun, input.sun_d_azimuth_deg, input.sun_d_zenith_deg, MaxSunZenithDeg());
}

// The lowest sun the tables cover: mu_s_min (aerial/atmosphere.h).
double Viewer::Impl::MaxSunZenithDeg() const {
  return std::acos(options_.atmosphere.mu_s_min) * 180.0 / std::numbers::pi;
}

void Viewer::Impl::Say(std::string message) {
  std::printf("%s\n", Printable(message).c_str());
  std::fflush(stdout);
  message_ = std::move(message);
}

void Viewer::Impl::FollowSunClock() {
  options_.scene.sun = SunAtSolarTime(settings_.solar_time_h, settings_.latitude_deg, settings_.declination_deg);
  SteerSun(options_.scene.sun, 0.0, 0.0, MaxSunZenithDeg());
}

// The keys' commands (key_commands.h), and screenshots and exports of the frame just rendered.
void Viewer::Impl::Act(const PanelEvents& events, const std::vector<int>& keys, const SceneRenderer& renderer) {
  KeyCommands commands = ReadKeyCommands(keys);
  if (commands.quit) glfwSetWindowShouldClose(window_.handle(), GLFW_TRUE);
  if (commands.reset_camera) options_.scene.camera = start_camera_;
  panel_shown_ ^= commands.toggle_panel;
  help_shown_ ^= commands.toggle_help;
  bool screenshot = events.screenshot || commands.screenshot, export_vdb = events.export_vdb || commands.export_vdb;
  if (screenshot) {
    try {
      Say(SaveScreenshots(ShownFrame(), {.exposure = DisplayExposure(), .white_balance = options_.white_balance}));
    } catch (const Error& e) {
      Say(std::string("screenshot: ") + e.what());
    }
  }
  if (export_vdb) Say(ExportFroxelsToVdb(renderer, options_.scene));
}

// The picture the window shows, at the window's size: the still view's mean while it has one,
// the renderer's last frame otherwise.
ImageRgbF Viewer::Impl::ShownFrame() const {
  if (accumulator_.frames() == 0) return shown_->ReadOutput();
  ImageRgbF mean = accumulator_.Read();
  const ::vk::Extent2D window = target_->extent();
  if (mean.width == int(window.width) && mean.height == int(window.height)) return mean;
  return ResizeBilinear(mean, int(window.width), int(window.height));
}

// Before a renderer is destroyed: no frame in flight may still use it, and its pass times are not
// read any more.
void Viewer::Impl::ForgetRecordedFrames() {
  ring_.WaitAll();
  // The frames in flight have finished: their GPU times are read while their renderers are as
  // they recorded them, oldest first.
  for (uint32_t i = 1; i <= kFramesInFlight; ++i) CollectFinishedFrame((ring_.slot() + i) % kFramesInFlight);
  settled_view_.reset();
}

// The GPU times of the frame the slot held, which has finished (CommandRing::Begin waited for it).
void Viewer::Impl::CollectFinishedFrame(uint32_t slot) {
  std::vector<PassTime> passes;
  for (const auto& [renderer, suffix] : recorded_[slot]) {
    for (PassTime pass : renderer->PassTimes(slot)) {
      pass.pass += suffix;
      passes.push_back(pass);
    }
  }
  recorded_[slot].clear();
  if (!slot_used_[slot]) return;  // nothing recorded in this slot yet, or collected already
  slot_used_[slot] = false;
  for (const PassTime& pass : timers_[slot]->Collect()) passes.push_back(pass);
  stats_.AddGpuFrame(passes);
  last_passes_ = std::move(passes);
}

// Auto exposure: the slot's finished frame metered its luminance; the exposure moves toward it
// (AdaptEv100), from the first reading on. A fixed exposure leaves the EV100 to the panel.
void Viewer::Impl::AdaptExposure(uint32_t slot, double dt_s) {
  std::optional<MeterReading> reading = meter_.TakeReading(slot);
  if (!settings_.auto_exposure) {
    exposure_metered_ = false;
    return;
  }
  if (!reading) return;
  double target = Ev100FromMeter(*reading);
  settings_.ev100 = float(exposure_metered_ ? AdaptEv100(settings_.ev100, target, dt_s) : target);
  exposure_metered_ = true;
}

// The display pass for the settings' view and the panel over it, into the window target's image.
void Viewer::Impl::RecordDisplay(const vk::CommandBuffer& cmd, uint32_t slot,
                                 const SceneRenderer& primary, const SceneRenderer* other) {
  // The difference view needs both frames; until the other variant's tables arrive, the picture.
  DebugView view = settings_.view == DebugView::kDifference && !other ? DebugView::kFinal : settings_.view;
  ::vk::Extent2D extent = target_->extent();
  vk::GpuTimer& timer = *timers_[slot];
  timer.Reset(cmd);
  target_->RecordDraw(cmd, [&](const vk::CommandBuffer& cmd) {
    timer.Begin(cmd, PassName(view));
    switch (view) {
      case DebugView::kFinal:
        display_.RecordToneMap(cmd, extent, accumulator_.frames() > 0 ? accumulator_.mean() : primary.output(),
                               DisplayExposure(),
                               {float(options_.white_balance[0]), float(options_.white_balance[1]),
                                float(options_.white_balance[2])});
        break;
      case DebugView::kRayleigh:
      case DebugView::kMie:
      case DebugView::kTransmittance:
        display_.RecordTerm(cmd, extent, primary, slot,
                            DisplayPasses::Term(int(view) - int(DebugView::kRayleigh)), DisplayExposure());
        break;
      case DebugView::kFroxelSlice:
        display_.RecordFroxelSlice(cmd, extent, primary, settings_.froxel_slice, DisplayExposure());
        break;
      case DebugView::kDifference: {
        bool primary_4d = primary.tables().options().variant == LutVariant::k4D;
        const SceneRenderer& l4 = primary_4d ? primary : *other;
        const SceneRenderer& l3 = primary_4d ? *other : primary;
        display_.RecordDifference(cmd, extent, l4.output(), l3.output(),
                                  settings_.difference_full_scale);
        break;
      }
    }
    timer.End(cmd);
    timer.Begin(cmd, "panel");
    imgui_.Record(cmd);
    timer.End(cmd);
  });
}

PanelInfo Viewer::Impl::MakePanelInfo(const SceneRenderer& primary) const {
  const Tables& tables = primary.tables();
  double frame_ms = stats_.MedianFrameMs(kPanelWindow);
  return {.fps = frame_ms > 0.0 ? 1000.0 / frame_ms : 0.0,
          .frame_ms = frame_ms,
          .passes = last_passes_,
          .terrain_chunks = primary.frame_info().chunks,
          .terrain_triangles = primary.frame_info().triangles,
          .work = supply_.status(),
          .tables = tables.options().Describe() +
                    (supply_.IsWanted(tables) ? "" : " (previous atmosphere)"),
          .message = message_,
          .difference_ready = HasCurrentTables(LutVariant::k4D) && HasCurrentTables(LutVariant::k3D)};
}

// One frame: events, tables, input, panel, render, display. False once the window is closed.
bool Viewer::Impl::Step() {
  glfwPollEvents();
  if (window_.should_close()) return false;
  ::vk::Extent2D extent = window_.framebuffer_extent();
  if (extent.width == 0 || extent.height == 0) {  // minimized: nothing to draw into
    glfwWaitEvents();
    last_frame_end_ = Clock::now();
    return true;
  }
  if (extent != target_->extent()) Resize(extent);
  AdoptFinishedTables();
  double dt_s = std::chrono::duration<double>(Clock::now() - last_frame_end_).count();

  imgui_.NewFrame();
  Steer(input_.Read(dt_s, imgui_.wants_mouse(), imgui_.wants_keyboard()), dt_s);
  RendererOptions render = CurrentRenderOptions();
  // The last frame of a scripted run is saved: it is completed like `aerial render`'s.
  const bool last = options_.frames > 0 && frames_ + 1 == options_.frames;
  // Dynamic resolution lowers the scale of a moving view; a still one, and the last, is drawn whole.
  // So is the first, which has nothing to be still against: a view opened still is drawn once.
  const auto pose = std::make_tuple(options_.scene.camera, options_.scene.sun, render.terrain_error_px);
  const bool resting = !last_pose_ || last_pose_ == pose;
  last_pose_ = pose;
  if (resolution_ && (resting || last)) render.render_scale = 1.0;
  SceneRenderer* primary = stack_.Get(settings_.variant, render);
  if (!primary) primary = stack_.Get(Other(settings_.variant), render);
  PanelEvents events = panel_shown_ ? DrawPanel(settings_, MakePanelInfo(*primary)) : PanelEvents{};
  if (help_shown_) DrawKeyHelp();
  imgui_.EndFrame();
  if (events.sun_clock_moved) FollowSunClock();
  if (events.tables_changed) applied_knobs_ = settings_.knobs;
  RequestTables();
  // Got before recording: a renderer rebuilt for new options waits for the frames in flight.
  SceneRenderer* other = nullptr;
  if (settings_.view == DebugView::kDifference && HasCurrentTables(LutVariant::k4D) &&
      HasCurrentTables(LutVariant::k3D) && HasCurrentTables(settings_.variant)) {
    other = stack_.Get(Other(settings_.variant), render);
  }

  // The accumulator's mean takes the frame's size; the frames in flight may still show the old one.
  if (!accumulator_.Fits(primary->output().extent)) {
    ring_.WaitAll();
    accumulator_.Resize(primary->output().extent);
  }
  const vk::CommandBuffer& cmd = ring_.Begin();
  uint32_t slot = ring_.slot();
  CollectFinishedFrame(slot);
  AdaptExposure(slot, dt_s);
  if (!target_->Acquire(ring_)) {  // out of date: nothing is recorded for this frame
    Resize(window_.framebuffer_extent());
    return true;
  }
  // A still view is refined one jittered frame at a time; the last frame of a scripted run is the
  // complete mean or, short of it, a complete frame without jitter.
  DrawnView view{primary, options_.scene.camera, options_.scene.sun, render.terrain_error_px};
  const bool still = settled_view_ == view;
  const bool refine = still && !last && !accumulator_.complete() && settings_.view == DebugView::kFinal;
  const bool drawn = refine || !still || (last && !accumulator_.complete());
  if (drawn) {
    if (refine) options_.scene.camera.jitter_px = accumulator_.next_jitter();
    primary->Record(*cmd, options_.scene, slot, last);
    options_.scene.camera.jitter_px = {0.0, 0.0};
    recorded_[slot].push_back({primary, ""});
    shown_ = primary;
    if (refine) {
      // A jittered frame that left work for later is not yet the view's picture: start again.
      if (primary->frame_info().settled) accumulator_.Record(cmd, primary->output());
      else accumulator_.Reset();
    } else {
      accumulator_.Reset();
      if (primary->frame_info().settled) settled_view_ = view;
      else settled_view_.reset();
    }
  }
  slot_used_[slot] = true;
  if (other) {
    other->Record(*cmd, options_.scene, slot);
    recorded_[slot].push_back({other, " (" + ToString(other->tables().options().variant) + ")"});
  }
  // A frame presented again has been metered already.
  if (settings_.auto_exposure && (drawn || !exposure_metered_)) meter_.Record(cmd, slot, primary->output(), options_.white_balance);
  RecordDisplay(cmd, slot, *primary, other);
  if (last && options_.screenshot_panel) {
    window_picture_extent_ = target_->extent();
    window_picture_.emplace(context_, vk::BufferCreateInfo{.size = 4ull * window_picture_extent_.width * window_picture_extent_.height,
                                                           .usage = ::vk::BufferUsageFlagBits::eTransferDst,
                                                           .host_visible = true});
    target_->RecordCopyToBuffer(cmd, window_picture_->handle());
  }
  bool presented = target_->SubmitAndPresent(ring_);
  // Reads of the frame (screenshots, exports) are submitted after it, so they see it finished.
  std::vector<int> keys = window_.TakeKeyPresses();
  if (imgui_.wants_keyboard()) keys.clear();
  Act(events, keys, *primary);
  if (!presented) {
    ::vk::Extent2D now_extent = window_.framebuffer_extent();
    if (now_extent.width > 0 && now_extent.height > 0) Resize(now_extent);
  }
  Clock::time_point now = Clock::now();
  double frame_ms = std::chrono::duration<double, std::milli>(now - last_frame_end_).count();
  stats_.AddFrame(frame_ms, render.render_scale);
  if (resolution_ && !resting) settings_.render_scale = resolution_->Update(frame_ms, render.render_scale);
  last_frame_end_ = now;
  ++frames_;
  return true;
}

void Viewer::Impl::Run() {
  while ((options_.frames == 0 || frames_ < options_.frames) && Step()) {
  }
  ring_.WaitAll();
  target_->ShowSubmitted();
  // Exposed as `aerial render` exposes the same frame, so that the two can be compared.
  if (options_.screenshot_panel && window_picture_) {
    WriteWindowPicture();
  } else if (!options_.screenshot.empty() && shown_) {
    ImageRgbF frame = ShownFrame();
    WriteImage(options_.screenshot, frame,
               {.exposure = options_.exposure.MultiplierFor(frame, options_.white_balance),
                .white_balance = options_.white_balance});
  }
  if (!options_.stats.empty()) stats_.Write(options_.stats);
}

// The window's 8-bit sRGB texels, as the window target's format orders them, to an opaque RGBA PNG.
void Viewer::Impl::WriteWindowPicture() const {
  const bool bgra = target_->format() == ::vk::Format::eB8G8R8A8Srgb || target_->format() == ::vk::Format::eB8G8R8A8Unorm;
  size_t texels = size_t(window_picture_extent_.width) * window_picture_extent_.height;
  std::vector<uint8_t> rgba(4 * texels);
  const auto* bytes = reinterpret_cast<const uint8_t*>(window_picture_->mapped());
  for (size_t i = 0; i < texels; ++i) {
    rgba[4 * i + 0] = bytes[4 * i + (bgra ? 2 : 0)];
    rgba[4 * i + 1] = bytes[4 * i + 1];
    rgba[4 * i + 2] = bytes[4 * i + (bgra ? 0 : 2)];
    rgba[4 * i + 3] = 255;
  }
  WriteFileAtomically(options_.screenshot,
                      EncodePng(rgba, int(window_picture_extent_.width), int(window_picture_extent_.height)));
}

Viewer::Viewer(ViewerOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}
Viewer::~Viewer() = default;
void Viewer::Run() { impl_->Run(); }
bool Viewer::Step() { return impl_->Step(); }
ViewSettings& Viewer::settings() { return impl_->settings_; }
void Viewer::ApplyTableSettings() { impl_->applied_knobs_ = impl_->settings_.knobs; }
const SceneRenderer& Viewer::renderer() const { return *impl_->shown_; }
const std::vector<PassTime>& Viewer::last_passes() const { return impl_->last_passes_; }
TableWorkStatus Viewer::table_work() const { return impl_->supply_.status(); }
GLFWwindow* Viewer::window() const { return impl_->window(); }

void RunViewer(ViewerOptions options) { Viewer(std::move(options)).Run(); }

}  // namespace aerial::viewer
