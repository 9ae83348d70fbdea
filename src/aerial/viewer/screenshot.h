#pragma once
// The F12 / P key: the renderer's last frame (linear radiance, without the panel and whatever the
// debug view) as a PNG (tone mapped as the window is) and an EXR, in the working
// directory, named after the local time: aerial-view-20250101-120000.{png,exr}.
#include <filesystem>
#include <string>

#include "aerial/image.h"
#include "aerial/renderer.h"

namespace aerial::viewer {

// png: the PNG's exposure and white balance. Returns the message the viewer prints and shows in
// its panel; throws Error if a write fails.
std::string SaveScreenshots(const SceneRenderer& renderer, const ToneMapOptions& png,
                            const std::filesystem::path& directory = ".");

}  // namespace aerial::viewer
