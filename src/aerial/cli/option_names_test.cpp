#include "aerial/cli/option_names.h"

#include <gtest/gtest.h>

namespace aerial::cli {
namespace {

TEST(OptionNames, TheLibrarysFieldIsShownUnderItsOption) {
  const Error shown = WithOptionNames(Error("RenderOptions::render_scale", "0.1", "in [0.25, 1]", "a frame"));
  EXPECT_EQ(shown.field(), "--render-scale");
  EXPECT_EQ(shown.value(), "0.1");
  EXPECT_EQ(shown.allowed(), "in [0.25, 1]");
  EXPECT_EQ(shown.where(), "a frame");
  EXPECT_EQ(OptionName("scene file"), "--scene");
  EXPECT_EQ(OptionName("camera.fov_deg"), "camera.fov_deg") << "no option sets it";
}

// A qualified field in the expectation is renamed where it stands as a whole name; words that
// happen to spell an unqualified field ("a scene file") are the text's own and stay.
TEST(OptionNames, OnlyWholeQualifiedNamesInTheExpectationAreRenamed) {
  const Error shown = WithOptionNames(
      Error("VdbExportOptions::world_grid_m", "1",
            "10 m or more (or a shorter FroxelGrid::far_m), FroxelGrid::far_mm, MyFroxelGrid::far_m, in a scene file"));
  EXPECT_EQ(shown.field(), "--world-grid");
  EXPECT_EQ(shown.allowed(),
            "10 m or more (or a shorter --froxel-far-m), FroxelGrid::far_mm, MyFroxelGrid::far_m, in a scene file");
}

}  // namespace
}  // namespace aerial::cli
