#pragma once
// The V key: the current frame's froxel volume to an OpenVDB file in the working directory, on
// the camera's frustum, as `aerial export-vdb` writes it (src/aerial/export/froxel_export.h).
#include <filesystem>
#include <string>

#include "aerial/renderer.h"

namespace aerial::viewer {

// Exports the froxels of the renderer's last frame of `scene` to
// directory/aerial-froxels-<date>-<time>.vdb; returns the message the viewer prints and shows in
// its panel (also on failure, which does not stop the viewer).
std::string ExportFroxelsToVdb(const SceneRenderer& renderer, const Scene& scene,
                               const std::filesystem::path& directory = ".");

}  // namespace aerial::viewer
