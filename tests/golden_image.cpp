#include "golden_image.h"

#include <cstdio>
#include <cstdlib>

#include "aerial/error.h"
#include "aerial/image/image_writer.h"
#include "aerial/validation/image_metrics.h"

namespace aerial::testing {

bool GoldenUpdateRequested() { return std::getenv("AERIAL_UPDATE_GOLDEN") != nullptr; }

::testing::AssertionResult MatchesGolden(const ImageRgbF& image, const std::filesystem::path& golden,
                                         double max_rmse, bool update) {
  if (update) {
    WriteImage(golden, image, {});
    return ::testing::AssertionFailure()
           << "AERIAL_UPDATE_GOLDEN is set: wrote " << golden.string()
           << "; review it, commit it, and run again without AERIAL_UPDATE_GOLDEN";
  }
  ImageRgbF expected;
  try {
    expected = ReadExr(golden);
  } catch (const Error& e) {
    return ::testing::AssertionFailure() << e.what() << " (AERIAL_UPDATE_GOLDEN=1 writes it)";
  }
  if (expected.width != image.width || expected.height != image.height)
    return ::testing::AssertionFailure() << golden.string() << " is " << expected.width << "x"
                                         << expected.height << ", the image " << image.width << "x"
                                         << image.height;
  double rmse = validation::EnergyWeightedRelativeRmse(image, expected);
  std::printf("%s: relative RMSE %.3g%% against the golden image\n", golden.filename().c_str(), 100 * rmse);
  if (rmse < max_rmse) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << golden.string() << ": relative RMSE " << rmse << ", bound " << max_rmse;
}

}  // namespace aerial::testing
