// The viewer's live loop, driven frame by frame under a private X server: a resize recreates the
// swapchain and the renderer, frame settings rebuild the renderer, an atmosphere change is
// computed on the worker while frames keep coming, the 3D/4D switch and every debug view run, and
// the validation layers (on, as everywhere in the tests) report nothing.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <functional>
#include <map>
#include <optional>

#include "aerial/scene.h"
#include "aerial/viewer/camera_path.h"
#include "aerial/viewer/dynamic_resolution.h"
#include "aerial/viewer/viewer.h"
#include "xvfb_display.h"

// Xlib last: its macros (None, Bool, Status) would rename what the headers above declare.
#include <X11/Xlib.h>
#include <X11/Xutil.h>

namespace aerial::testing {
namespace {

// Steps until done() or max_steps frames; returns how many frames it took (max_steps + 1: never).
int StepUntil(viewer::Viewer& viewer, const std::function<bool()>& done, int max_steps,
              int* busy_frames = nullptr) {
  for (int step = 0; step < max_steps; ++step) {
    if (done()) return step;
    if (busy_frames) *busy_frames += viewer.table_work().busy;
    EXPECT_TRUE(viewer.Step());
  }
  return done() ? max_steps : max_steps + 1;
}

// The viewer keeps frames in flight: a frame's GPU times arrive a few frames later, so a check
// of the passes of the frames after a change first steps this many frames.
constexpr int kFramesUntilTimed = 3;

void StepFrames(viewer::Viewer& viewer, int frames) {
  for (int i = 0; i < frames; ++i) ASSERT_TRUE(viewer.Step());
}

bool HasPass(const viewer::Viewer& viewer, const std::string& fragment) {
  for (const PassTime& pass : viewer.last_passes())
    if (pass.pass.find(fragment) != std::string::npos) return true;
  return false;
}

// A 160x90 window on the noon preset with small tables of both variants, validation on.
viewer::ViewerOptions SmallViewerOptions() {
  viewer::ViewerOptions options;
  options.atmosphere = AtmosphereParameters::Earth();
  options.tables = {{LutVariant::k4D, PrecomputeOptions::Small(LutVariant::k4D)},
                    {LutVariant::k3D, PrecomputeOptions::Small(LutVariant::k3D)}};
  options.device = {.validation = true};
  options.render = {{.width = 160, .height = 90}};
  options.scene = BuildPreset("noon", options.atmosphere.bottom_radius_m);
  return options;
}

// Each test opens its windows on a private X server (skipped, with the reason, where there is
// none) and ends with no new Vulkan validation message once its viewer is gone.
class ViewerSession : public ::testing::Test {
 protected:
  void SetUp() override {
    if (std::string why = MissingXServer("Xvfb"); !why.empty()) GTEST_SKIP() << why;
    x_.emplace();
    ASSERT_FALSE(x_->display().empty()) << x_->error();
    messages_before_ = Device::ValidationMessageCount();
  }
  void TearDown() override {
    if (x_) {
      EXPECT_EQ(Device::ValidationMessageCount(), messages_before_);
    }
  }

 private:
  std::optional<XvfbDisplay> x_;  // outlives the test's windows
  int messages_before_ = 0;
};

TEST_F(ViewerSession, ResizesSwitchesAndRecomputesWithoutValidationMessages) {
  viewer::Viewer viewer(SmallViewerOptions());
  StepFrames(viewer, kFramesUntilTimed);
  EXPECT_EQ(viewer.renderer().options().width, 160);
  EXPECT_TRUE(HasPass(viewer, "present"));

  glfwSetWindowSize(viewer.window(), 200, 120);
  EXPECT_LE(StepUntil(viewer, [&] { return viewer.renderer().options().width == 200 &&
                                           viewer.renderer().options().height == 120; }, 20), 20);

  viewer.settings().mode = AerialMode::kPerPixel;
  viewer.settings().froxels = FroxelGrid::Parse("16x16x16");
  StepFrames(viewer, kFramesUntilTimed);
  EXPECT_EQ(viewer.renderer().options().mode, AerialMode::kPerPixel);
  EXPECT_FALSE(HasPass(viewer, "froxel build"));
  viewer.settings().mode = AerialMode::kFroxel;
  for (viewer::DebugView view : {viewer::DebugView::kRayleigh, viewer::DebugView::kMie,
                                 viewer::DebugView::kTransmittance, viewer::DebugView::kFroxelSlice}) {
    viewer.settings().view = view;
    StepFrames(viewer, kFramesUntilTimed);
    EXPECT_TRUE(HasPass(viewer, "debug view"));
    EXPECT_EQ(viewer.renderer().options().froxels.depth, 16);
  }

  // The difference view asks the worker for the other variant's tables and shows the picture
  // until they come.
  viewer.settings().view = viewer::DebugView::kDifference;
  ASSERT_TRUE(viewer.Step());
  EXPECT_LE(StepUntil(viewer, [&] { return HasPass(viewer, "(3d)"); }, 2000), 2000);

  // A precompute of the small tables takes hundreds of milliseconds, a 200x120 frame tens: the
  // window must keep drawing while the worker computes.
  viewer.settings().view = viewer::DebugView::kFinal;
  viewer.settings().knobs.mie_g = 0.7;
  viewer.ApplyTableSettings();
  int busy_frames = 0;
  EXPECT_LE(StepUntil(viewer, [&] { return viewer.renderer().tables().atmosphere().mie_phase_g == 0.7; },
                      2000, &busy_frames),
            2000);
  std::printf("frames drawn while the worker computed: %d\n", busy_frames);
  EXPECT_GT(busy_frames, 0);

  // The 3D tables of the first atmosphere (from the difference view) show until those of the
  // new one arrive.
  viewer.settings().variant = LutVariant::k3D;
  ASSERT_TRUE(viewer.Step());
  EXPECT_EQ(viewer.renderer().tables().options().variant, LutVariant::k3D);
  EXPECT_LE(StepUntil(viewer, [&] { return viewer.renderer().tables().atmosphere().mie_phase_g == 0.7; }, 2000),
            2000);

  viewer.settings().view = viewer::DebugView::kDifference;
  EXPECT_LE(StepUntil(viewer, [&] { return HasPass(viewer, "(4d)"); }, 2000), 2000);
}

// A still view is drawn until its frame left nothing for later (FrameInfo::settled), refined by
// four jittered frames (frame_accumulator.h), then only presented again: its frames time the
// display pass and no pass of the renderer. A change of the view (here the terrain's error bound,
// applied without a new renderer) draws again.
TEST_F(ViewerSession, AStillViewIsPresentedWithoutRedrawing) {
  viewer::Viewer viewer(SmallViewerOptions());
  StepFrames(viewer, kFramesUntilTimed);
  EXPECT_TRUE(HasPass(viewer, "opaque raster")) << "the first frames draw";
  EXPECT_LE(StepUntil(viewer, [&] { return !HasPass(viewer, "opaque raster"); }, 20), 20);
  EXPECT_TRUE(viewer.renderer().frame_info().settled);
  EXPECT_TRUE(HasPass(viewer, "present"));
  StepFrames(viewer, kFramesUntilTimed);
  EXPECT_FALSE(HasPass(viewer, "opaque raster")) << "a still view stays presented";
  viewer.settings().terrain_error_px = 3.0f;
  StepFrames(viewer, kFramesUntilTimed);
  EXPECT_TRUE(HasPass(viewer, "opaque raster")) << "a changed view draws again";
}

// Under dynamic resolution a moving view starts at the controller's floor and stays there while
// the target is out of reach, and once it stops it is drawn at scale 1, as `aerial render` draws
// it (and then refined, frame_accumulator.h).
TEST_F(ViewerSession, DynamicResolutionLowersAMovingViewAndDrawsAStillOneWhole) {
  viewer::ViewerOptions options = SmallViewerOptions();
  options.target_ms = 0.01;  // never met
  options.camera_path = viewer::CameraPath::Load(AERIAL_SOURCE_DIR "/examples/paths/corridor.toml",
                                                 options.atmosphere.bottom_radius_m);
  const int path_frames = int(options.camera_path->duration_s() * 30.0);  // 1/30 s of path a frame
  viewer::Viewer viewer(std::move(options));
  StepFrames(viewer, 2 * viewer::DynamicResolution::kSettleFrames);
  EXPECT_EQ(viewer.renderer().options().render_scale, viewer::DynamicResolution::kMinScale);
  StepFrames(viewer, path_frames - 2 * viewer::DynamicResolution::kSettleFrames + 2);
  EXPECT_EQ(viewer.renderer().options().render_scale, 1.0) << "the path has ended: a still view";
  StepFrames(viewer, kFramesUntilTimed);
  EXPECT_EQ(viewer.renderer().options().render_scale, 1.0);
}

// A target within easy reach: the moving view climbs from the floor to scale 1 once the frames
// since the start have settled.
TEST_F(ViewerSession, DynamicResolutionClimbsWhenTheTargetAllows) {
  viewer::ViewerOptions options = SmallViewerOptions();
  options.target_ms = 1000.0;
  options.camera_path = viewer::CameraPath::Load(AERIAL_SOURCE_DIR "/examples/paths/corridor.toml",
                                                 options.atmosphere.bottom_radius_m);
  viewer::Viewer viewer(std::move(options));
  StepFrames(viewer, 1);
  EXPECT_EQ(viewer.renderer().options().render_scale, 1.0) << "the first frame is drawn whole";
  StepFrames(viewer, 1);
  EXPECT_EQ(viewer.renderer().options().render_scale, viewer::DynamicResolution::kMinScale) << "starts at the floor";
  int steps = 0;
  for (int i = 0; i < 2 * viewer::DynamicResolution::kSettleFrames; ++i) {
    const double scale = viewer.renderer().options().render_scale;
    ASSERT_TRUE(viewer.Step());
    if (viewer.renderer().options().render_scale == scale) continue;
    ++steps;
    // The frames in flight finished before the targets were remade; their GPU times are kept.
    EXPECT_TRUE(HasPass(viewer, "opaque raster")) << "the last finished frame's passes, at scale " << scale;
  }
  EXPECT_GE(steps, 1);
  EXPECT_EQ(viewer.renderer().options().render_scale, 1.0);
}

// What the X server shows of the one top-level window of this size, as 8-bit RGB read through
// the server's own masks: empty if there is no such window.
std::vector<uint8_t> ShownRgb(int width, int height) {
  Display* display = XOpenDisplay(nullptr);
  if (!display) return {};
  std::vector<uint8_t> rgb;
  ::Window root, parent, *children = nullptr;
  unsigned count = 0;
  XQueryTree(display, DefaultRootWindow(display), &root, &parent, &children, &count);
  for (unsigned i = 0; i < count && rgb.empty(); ++i) {
    XWindowAttributes a;
    if (!XGetWindowAttributes(display, children[i], &a) || a.map_state != IsViewable || a.width != width ||
        a.height != height)
      continue;
    XImage* image = XGetImage(display, children[i], 0, 0, width, height, AllPlanes, ZPixmap);
    if (!image) continue;
    auto channel = [](unsigned long pixel, unsigned long mask) {
      int shift = 0;
      while (mask && !(mask & 1)) mask >>= 1, ++shift;
      return uint8_t((pixel >> shift) & mask);
    };
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        unsigned long pixel = XGetPixel(image, x, y);
        rgb.insert(rgb.end(), {channel(pixel, image->red_mask), channel(pixel, image->green_mask),
                               channel(pixel, image->blue_mask)});
      }
    XDestroyImage(image);
  }
  if (children) XFree(children);
  XCloseDisplay(display);
  return rgb;
}

// aerial's X11 presenter (the default on a CPU device) and Mesa's swapchain put the same picture
// on the window: a still view after its antialiasing frames, read back from the X server. Red and
// blue swapped, or rows misplaced, would differ from the swapchain's picture in most pixels. Both
// then follow a resize without a validation message.
TEST_F(ViewerSession, TheX11PresenterShowsWhatTheSwapchainShows) {
  std::map<viewer::PresentMode, std::vector<uint8_t>> shown;
  for (viewer::PresentMode mode : {viewer::PresentMode::kX11, viewer::PresentMode::kSwapchain}) {
    viewer::ViewerOptions options = SmallViewerOptions();
    options.present = mode;
    options.frames = 12;  // the still view's antialiasing is complete before the last frames
    options.target_ms = 0.0;  // the scale stays 1, whatever the frames cost
    options.exposure = {.mode = Exposure::Mode::kEv100, .value = 14.0};  // auto exposure adapts by the clock
    viewer::Viewer viewer(std::move(options));
    viewer.Run();
    shown[mode] = ShownRgb(160, 90);
    glfwSetWindowSize(viewer.window(), 200, 120);
    EXPECT_LE(StepUntil(viewer, [&] { return viewer.renderer().options().width == 200; }, 20), 20);
  }
  const std::vector<uint8_t>& x11 = shown[viewer::PresentMode::kX11];
  const std::vector<uint8_t>& swapchain = shown[viewer::PresentMode::kSwapchain];
  ASSERT_EQ(x11.size(), 3u * 160 * 90);
  ASSERT_EQ(swapchain.size(), x11.size());
  size_t differing = 0;
  double blue_minus_red = 0.0;  // over the top rows, the noon sky
  for (size_t p = 0; p < x11.size() / 3; ++p) {
    differing += x11[3 * p] != swapchain[3 * p] || x11[3 * p + 1] != swapchain[3 * p + 1] ||
                 x11[3 * p + 2] != swapchain[3 * p + 2];
    if (p < 160 * 10) blue_minus_red += (int(x11[3 * p + 2]) - int(x11[3 * p])) / (160.0 * 10);
  }
  EXPECT_EQ(differing, 0u);
  EXPECT_GT(blue_minus_red, 20.0) << "a blue sky, not an empty window";
}

}  // namespace
}  // namespace aerial::testing
