#pragma once
// How a camera fills the frame's uniform block (aerial/shader_abi/frame_block.h): below render/
// and froxel/, which both use it.
#include "aerial/froxel_grid.h"
#include "aerial/froxels.h"
#include "aerial/shader_abi/frame_block.h"

namespace aerial {

// The block for a camera (aerial/froxels.h) on a planet of radius planet_radius_m, with a froxel
// grid. Shaders see camera-relative positions; the planet's center is at (0, 0, -R).
FrameUniforms MakeFrameUniforms(const FrameCamera& camera, double planet_radius_m, const FroxelGrid& grid);

}  // namespace aerial
