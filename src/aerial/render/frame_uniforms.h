#pragma once
// Filling the per-frame block (FrameUniforms, shader_abi/frame_block.h) from a scene: camera,
// sun, froxel grid.
#include "aerial/scene.h"
#include "aerial/shader_abi/frame_block.h"
#include "aerial/froxel_grid.h"

namespace aerial {

FrameUniforms MakeFrameUniforms(const Scene& scene, double planet_radius_m, int width, int height,
                                const FroxelGrid& froxels);

}  // namespace aerial
