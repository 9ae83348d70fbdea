#pragma once
// The V key: the current frame's froxel volume to an OpenVDB file. This is the viewer's one hook
// for the VDB exporter, which lives on another branch; until it is merged the hook only says so.
#include <string>

#include "aerial/render/renderer.h"

namespace aerial::viewer {

// Exports renderer.froxels() (with renderer.frame_uniforms() for the grid's placement); returns
// the message the viewer prints and shows in its panel.
std::string ExportFroxelsToVdb(const Renderer& renderer);

}  // namespace aerial::viewer
