#pragma once
// The F12 / P key: the picture the window shows (linear radiance, without the panel and whatever
// the debug view) as a PNG (tone mapped as the window is) and an EXR, in the working
// directory, named after the local time: aerial-view-20250101-120000.{png,exr}.
#include <filesystem>
#include <string>

#include "aerial/image.h"

namespace aerial::viewer {

// png: the PNG's exposure and white balance. Returns the message the viewer prints and shows in
// its panel; throws Error if a write fails.
std::string SaveScreenshots(const ImageRgbF& frame, const ToneMapOptions& png,
                            const std::filesystem::path& directory = ".");

}  // namespace aerial::viewer
