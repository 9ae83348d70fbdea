// MatchesGolden: an update writes the golden and fails, so that a rewritten golden is never
// compared with the image it was written from; without it, the stored file decides.
#include "golden_image.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "aerial/image/image_writer.h"
#include "aerial/image/scratch_dir_test_util.h"

namespace aerial::testing {
namespace {

ImageRgbF SmallImage(float scale) {
  ImageRgbF image{3, 2, std::vector<float>(3 * 2 * 4)};
  for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = scale * float(i + 1);
  return image;
}

class GoldenImage : public ScratchDirTest {};

TEST_F(GoldenImage, UpdateWritesTheFileAndFailsNamingIt) {
  std::filesystem::path golden = dir_ / "view.exr";
  ::testing::AssertionResult result = MatchesGolden(SmallImage(1.0f), golden, 0.01, /*update=*/true);
  EXPECT_FALSE(result);
  EXPECT_NE(std::string(result.message()).find(golden.string()), std::string::npos) << result.message();
  EXPECT_EQ(ReadExr(golden).rgba, SmallImage(1.0f).rgba);
  EXPECT_EQ(Entries(), std::vector<std::string>{"view.exr"}) << "no temporary left";
  // The next run, without the variable, compares with what was written.
  EXPECT_TRUE(MatchesGolden(SmallImage(1.0f), golden, 0.01, /*update=*/false));
}

TEST_F(GoldenImage, ComparisonFailsAboveTheBoundOrWithoutAGolden) {
  std::filesystem::path golden = dir_ / "view.exr";
  EXPECT_FALSE(MatchesGolden(SmallImage(1.0f), golden, 0.01, /*update=*/false)) << "no golden";
  WriteImage(golden, SmallImage(1.0f), {});
  EXPECT_TRUE(MatchesGolden(SmallImage(1.005f), golden, 0.01, /*update=*/false));  // 0.5% off
  EXPECT_FALSE(MatchesGolden(SmallImage(1.02f), golden, 0.01, /*update=*/false));   // 2% off
  ImageRgbF wider{4, 2, std::vector<float>(4 * 2 * 4, 1.0f)};
  EXPECT_FALSE(MatchesGolden(wider, golden, 0.01, /*update=*/false)) << "another size";
}

}  // namespace
}  // namespace aerial::testing
