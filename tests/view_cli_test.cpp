// `aerial view` as scripts run it, under Xvfb: it opens its window, renders, exits 0 without a
// validation message (CTest sets AERIAL_VALIDATION=1), writes its screenshot and statistics, and
// its frame is `aerial render`'s for the same scene, camera and size. (Bad paths, which fail
// before the window opens, are in cli_test.cpp.)
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "aerial/core/atomic_file.h"
#include "aerial/image/image_writer.h"
#include "aerial/validation/image_metrics.h"
#include "command_run.h"
#include "xvfb_display.h"

// The PNG decoder, only for this file's checks of the window's picture.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace aerial::testing {
namespace {

const std::string kXvfb = "xvfb-run -a -s \"-screen 0 640x480x24\"";
const std::string kSmall = " --small-tables --quiet --width 160 --height 90";

std::filesystem::path ScratchDir() {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / ("aerial-view-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(ViewCli, RendersFramesLikeRenderAndWritesStats) {
  if (std::string why = MissingXServer("xvfb-run"); !why.empty()) GTEST_SKIP() << why;
  std::filesystem::path dir = ScratchDir();
  CommandRun view = RunAerial("view" + kSmall + " --frames 5 --screenshot " + (dir / "view.exr").string() +
                                  " --stats " + (dir / "stats.json").string() + " --camera-path " +
                                  AERIAL_SOURCE_DIR "/examples/paths/corridor.toml",
                              kXvfb);
  ASSERT_EQ(view.exit_code, 0) << view.err;
  EXPECT_EQ(view.err.find("validation"), std::string::npos) << view.err;

  // The path starts at the noon preset's view; the 5th frame is at path time 4/30 s, 2/15 of the
  // way to the second keyframe. Render that same pose, one sample per pixel as the viewer draws.
  CommandRun render = RunAerial("render" + kSmall + " --supersample 1 --camera-position-m 0,80,46 --camera-yaw-deg 1.0666666666666667" +
                                " --camera-pitch-deg 3.7333333333333334 --out " + (dir / "render.exr").string());
  ASSERT_EQ(render.exit_code, 0) << render.err;
  ImageRgbF a = ReadExr(dir / "view.exr"), b = ReadExr(dir / "render.exr");
  ASSERT_EQ(a.width, 160);
  ASSERT_EQ(a.height, 90);
  ASSERT_EQ(b.width, a.width);
  // The same Renderer, tables, scene, camera and size: the frames are the same computation, so
  // only the last float bits of the camera pose (interpolated vs parsed) may differ.
  double rmse = validation::EnergyWeightedRelativeRmse(a, b);
  std::printf("view vs render: relative RMSE %.2e\n", rmse);
  EXPECT_LT(rmse, 1e-4);

  std::ifstream file(dir / "stats.json");
  auto stats = nlohmann::json::parse(file);
  EXPECT_EQ(stats["frames"], 5);
  for (const char* key : {"median_frame_ms", "p95_frame_ms", "fps_median", "median_gpu_frame_ms"})
    EXPECT_GT(stats[key].get<double>(), 0.0) << key;
  for (const char* pass : {"froxel build", "opaque raster", "sky", "transparent raster", "present", "panel"})
    EXPECT_TRUE(stats["passes"].contains(pass)) << pass;
  std::filesystem::remove_all(dir);
}

// The window's picture is drawn at half the size and upscaled by the display pass; the screenshot
// holds the frame at the asked size, as `aerial render --render-scale 0.5` writes it.
TEST(ViewCli, RenderScaleKeepsTheWindowSize) {
  if (std::string why = MissingXServer("xvfb-run"); !why.empty()) GTEST_SKIP() << why;
  std::filesystem::path dir = ScratchDir();
  CommandRun view = RunAerial("view" + kSmall + " --render-scale 0.5 --frames 3 --screenshot " +
                                  (dir / "view.exr").string(),
                              kXvfb);
  ASSERT_EQ(view.exit_code, 0) << view.err;
  CommandRun render =
      RunAerial("render" + kSmall + " --supersample 1 --render-scale 0.5 --out " + (dir / "render.exr").string());
  ASSERT_EQ(render.exit_code, 0) << render.err;
  ImageRgbF a = ReadExr(dir / "view.exr"), b = ReadExr(dir / "render.exr");
  EXPECT_EQ(a.width, 160);
  EXPECT_EQ(a.height, 90);
  EXPECT_LT(validation::EnergyWeightedRelativeRmse(a, b), 1e-4);  // the same computation, as in the test above
  std::filesystem::remove_all(dir);
}

// A still view is refined by four jittered frames into `aerial render`'s default 2x2 supersampled
// frame (frame_accumulator.h), which render draws with the same jitters; a screenshot saves it.
// They differ by the order of the sums alone (the viewer's running mean on the GPU, render's on
// the CPU): measured 6.2e-8 relative RMSE, where the frame of one sample per pixel is 5.1e-2 from
// render's. Any other difference of the frames (a jitter, the level of detail, the exposure of the
// EXR) would be orders of magnitude above the bound.
TEST(ViewCli, AStillViewIsAntialiasedAsRenderAntialiases) {
  if (std::string why = MissingXServer("xvfb-run"); !why.empty()) GTEST_SKIP() << why;
  std::filesystem::path dir = ScratchDir();
  CommandRun view = RunAerial("view" + kSmall + " --frames 16 --screenshot " + (dir / "view.exr").string(), kXvfb);
  ASSERT_EQ(view.exit_code, 0) << view.err;
  EXPECT_EQ(view.err.find("validation"), std::string::npos) << view.err;
  CommandRun twice = RunAerial("render" + kSmall + " --out " + (dir / "twice.exr").string());
  ASSERT_EQ(twice.exit_code, 0) << twice.err;
  CommandRun once = RunAerial("render" + kSmall + " --supersample 1 --out " + (dir / "once.exr").string());
  ASSERT_EQ(once.exit_code, 0) << once.err;
  ImageRgbF still = ReadExr(dir / "view.exr"), supersampled = ReadExr(dir / "twice.exr"), single = ReadExr(dir / "once.exr");
  double antialiased = validation::EnergyWeightedRelativeRmse(still, supersampled);
  double aliased = validation::EnergyWeightedRelativeRmse(single, supersampled);
  std::printf("still view against render's 2x2 frame: %.2e (one sample per pixel: %.2e)\n", antialiased, aliased);
  EXPECT_LT(antialiased, 1e-5);
  EXPECT_GT(aliased, 0.02);
  std::filesystem::remove_all(dir);
}

// Under dynamic resolution (an unreachable --target-ms) the moving frames step down, but the last
// frame of a scripted run is drawn whole, as `aerial render` draws its pose: 26 frames of the
// corridor, the last at path time 25/30 s.
TEST(ViewCli, TheLastFrameIsWholeUnderDynamicResolution) {
  if (std::string why = MissingXServer("xvfb-run"); !why.empty()) GTEST_SKIP() << why;
  std::filesystem::path dir = ScratchDir();
  CommandRun view = RunAerial("view" + kSmall + " --frames 26 --target-ms 0.01 --screenshot " +
                                  (dir / "view.exr").string() + " --stats " + (dir / "stats.json").string() +
                                  " --camera-path " AERIAL_SOURCE_DIR "/examples/paths/corridor.toml",
                              kXvfb);
  ASSERT_EQ(view.exit_code, 0) << view.err;
  std::ifstream file(dir / "stats.json");
  EXPECT_LT(nlohmann::json::parse(file)["median_render_scale"].get<double>(), 1.0);
  CommandRun render = RunAerial("render" + kSmall + " --supersample 1 --camera-position-m 0,500,130 --camera-yaw-deg " +
                                "6.666666666666667 --camera-pitch-deg 2.3333333333333335 --out " +
                                (dir / "render.exr").string());
  ASSERT_EQ(render.exit_code, 0) << render.err;
  // The same computation, as in the first test.
  EXPECT_LT(validation::EnergyWeightedRelativeRmse(ReadExr(dir / "view.exr"), ReadExr(dir / "render.exr")), 1e-4);
  std::filesystem::remove_all(dir);
}

// --white-balance reaches the viewer's pictures as it reaches render's PNG: the spectral sun is not
// white, so balancing it changes the picture. Before, the viewer ignored the option and both
// screenshots were byte for byte the same.
TEST(ViewCli, WhiteBalanceIsHonoured) {
  if (std::string why = MissingXServer("xvfb-run"); !why.empty()) GTEST_SKIP() << why;
  std::filesystem::path dir = ScratchDir();
  std::string pictures[2];
  for (int on = 0; on < 2; ++on) {
    std::filesystem::path png = dir / (on ? "on.png" : "off.png");
    CommandRun view = RunAerial("view" + kSmall + " --frames 1 --white-balance " + (on ? "on" : "off") +
                                    " --screenshot " + png.string(),
                                kXvfb);
    ASSERT_EQ(view.exit_code, 0) << view.err;
    std::ifstream in(png, std::ios::binary);
    pictures[on].assign(std::istreambuf_iterator<char>(in), {});
    ASSERT_FALSE(pictures[on].empty());
  }
  EXPECT_NE(pictures[0], pictures[1]);
  std::filesystem::remove_all(dir);
}

struct Rgba8 {
  int width = 0, height = 0;
  std::vector<uint8_t> texels;
  // The mean absolute difference of the colour channels from other's over the w x h block at
  // (x0, y0), in [0, 255].
  double BlockDifference(const Rgba8& other, int x0, int y0, int w, int h) const {
    double sum = 0.0;
    for (int y = y0; y < y0 + h; ++y)
      for (int x = x0; x < x0 + w; ++x)
        for (int c = 0; c < 3; ++c) {
          size_t i = 4 * (size_t(y) * width + x) + c;
          sum += std::abs(int(texels[i]) - int(other.texels[i]));
        }
    return sum / (3.0 * w * h);
  }
};

Rgba8 ReadPng(const std::filesystem::path& path) {
  const std::vector<std::byte> file = ReadFile(path);
  Rgba8 image;
  int channels = 0;
  stbi_uc* decoded = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(file.data()), int(file.size()),
                                           &image.width, &image.height, &channels, 4);
  if (decoded) image.texels.assign(decoded, decoded + 4 * size_t(image.width) * image.height);
  stbi_image_free(decoded);
  return image;
}

// --screenshot-panel saves the window as shown: a PNG of the window's size whose left part is the
// panel (420 px wide at (10, 10), Dear ImGui's first size) and whose right part is the picture the
// renderer's frame, saved without the flag, shows (exposed by the window's meter instead of
// render's, so alike, not equal).
TEST(ViewCli, ScreenshotWithThePanelIsTheWindowsPicture) {
  if (std::string why = MissingXServer("xvfb-run"); !why.empty()) GTEST_SKIP() << why;
  std::filesystem::path dir = ScratchDir();
  const std::string xvfb = "xvfb-run -a -s \"-screen 0 800x600x24\"";
  const std::string view = "view --small-tables --quiet --width 640 --height 360 --frames 2 --screenshot ";
  CommandRun with = RunAerial(view + (dir / "panel.png").string() + " --screenshot-panel", xvfb);
  ASSERT_EQ(with.exit_code, 0) << with.err;
  EXPECT_EQ(with.err.find("validation"), std::string::npos) << with.err;
  CommandRun without = RunAerial(view + (dir / "frame.png").string(), xvfb);
  ASSERT_EQ(without.exit_code, 0) << without.err;
  Rgba8 panel = ReadPng(dir / "panel.png"), frame = ReadPng(dir / "frame.png");
  ASSERT_EQ(panel.width, 640);
  ASSERT_EQ(panel.height, 360);
  ASSERT_EQ(frame.width, 640);
  ASSERT_EQ(frame.height, 360);
  double over_panel = panel.BlockDifference(frame, 20, 20, 380, 320);
  double sky = panel.BlockDifference(frame, 460, 20, 160, 80), ground = panel.BlockDifference(frame, 460, 240, 160, 100);
  std::printf("mean |difference| from the frame: %.1f over the panel, %.1f and %.1f beside it (sky, ground)\n",
              over_panel, sky, ground);
  // Measured 61 over the panel and 14 beside it. The panel is its dark, blue-grey window over the
  // picture; beside it, only the exposure differs, while swapped red and blue (a BGRA window read
  // as RGBA) moved the blue sky by 64.
  EXPECT_GT(over_panel, 35.0);
  EXPECT_LT(sky, 25.0);
  EXPECT_LT(ground, 25.0);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace aerial::testing
