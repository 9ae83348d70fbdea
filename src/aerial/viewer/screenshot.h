#pragma once
// The F12 / P key: the renderer's last frame (linear radiance, without the panel and whatever the
// debug view) as a PNG (tone mapped with the viewer's exposure) and an EXR, in the working
// directory, named after the local time: aerial-view-20250101-120000.{png,exr}.
#include <filesystem>
#include <string>

#include "aerial/renderer.h"

namespace aerial::viewer {

// Returns the message the viewer prints and shows in its panel; throws Error if a write fails.
std::string SaveScreenshots(const SceneRenderer& renderer, double exposure,
                            const std::filesystem::path& directory = ".");

}  // namespace aerial::viewer
