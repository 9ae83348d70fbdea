#pragma once
// Golden images: a rendered image against the EXR stored for it, or, on request, that EXR
// rewritten from the image.
#include <gtest/gtest.h>

#include <filesystem>

#include "aerial/image.h"

namespace aerial::testing {

// Whether AERIAL_UPDATE_GOLDEN is set: golden images are rewritten instead of compared.
bool GoldenUpdateRequested();

// The energy-weighted relative RMSE (aerial/validation/image_metrics.h) of image against the golden
// EXR is below max_rmse. With update, writes the image over the golden (atomically, WriteImage)
// and fails, naming the file to review and commit: comparing an image with the golden just written from it passes whatever the
// renderer drew.
::testing::AssertionResult MatchesGolden(const ImageRgbF& image, const std::filesystem::path& golden,
                                         double max_rmse, bool update = GoldenUpdateRequested());

}  // namespace aerial::testing
