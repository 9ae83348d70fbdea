#pragma once
// Filling the per-frame block (FrameUniforms, shader_abi/frame_block.h) from a scene: camera,
// sun, froxel grid.
#include "aerial/froxel_grid.h"
#include "aerial/scene.h"
#include "aerial/shader_abi/camera_frame_block.h"

namespace aerial {

FrameUniforms MakeFrameUniforms(const Scene& scene, double planet_radius_m, int width, int height,
                                const FroxelGrid& froxels);

}  // namespace aerial
