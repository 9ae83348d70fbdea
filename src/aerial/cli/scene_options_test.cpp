#include "aerial/cli/scene_options.h"

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

namespace aerial::cli {
namespace {

RendererOptions Parsed(const std::string& arguments) {
  CLI::App app;
  FrameOptions frame;
  frame.AddTo(app, "Image");
  app.parse(arguments, false);
  return frame.MakeRenderOptions();
}

// --terrain-selection picks where the terrain's chunks and shadow casters are selected; by default
// the renderer decides by the device (kAuto), and a value it does not know is refused by name.
TEST(FrameOptions, TerrainSelectionChoosesTheSelector) {
  EXPECT_EQ(Parsed("").terrain_selector, TerrainSelector::kAuto);
  EXPECT_EQ(Parsed("--terrain-selection cpu").terrain_selector, TerrainSelector::kCpu);
  EXPECT_EQ(Parsed("--terrain-selection gpu").terrain_selector, TerrainSelector::kGpu);
  try {
    Parsed("--terrain-selection gpus");
    FAIL() << "an unknown selection was taken";
  } catch (const CLI::ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("--terrain-selection"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace aerial::cli
