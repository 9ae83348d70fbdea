#pragma once
// The commands' memory estimates (core/memory_budget.h), each part under the option that sizes
// it, so that an over-budget error names what to change.
#include <vector>

#include "aerial/core/memory_budget.h"
#include "aerial/render/renderer_options.h"
#include "aerial/scene.h"
#include "aerial/table_options.h"

namespace aerial::cli {

// Per table option (--transmittance-size, --irradiance-size, --scattering-size): the tables, the
// precompute's scratch tables (counted even when the cache spares the precompute) and the two
// host copies a cache write or read makes.
std::vector<MemoryUse> TableMemoryUses(const PrecomputeOptions& options);

// One frame of `renderers` renderers of these options: targets and read-back under
// --width/--height, the froxel volume under --froxels, the terrain's chunk slots under --terrain,
// the shadow map under --shadows.
std::vector<MemoryUse> FrameMemoryUses(const RendererOptions& render, int renderers = 1);

// export-vdb's host copies of the froxels: read back (48 bytes a froxel, twice while copying),
// the volume and OpenVDB's grids (64 bytes each) and the encoded file with a string stream's
// growth (about 128): 320 bytes a froxel.
std::vector<MemoryUse> FroxelExportMemoryUses(const FroxelGrid& grid);

// A --world-grid volume of voxel_m and at most voxels voxels (CheckVdbExport): 320 bytes a voxel,
// as for a froxel, on top of the froxels read back.
std::vector<MemoryUse> WorldGridMemoryUses(double voxel_m, uint64_t voxels);

// The frustum grid's volume of `voxels` voxels (CheckVdbExport: linear slices as thin as the
// froxels' first), at 320 bytes a voxel, on top of the froxels read back.
std::vector<MemoryUse> FrustumGridMemoryUses(const FroxelGrid& grid, uint64_t voxels);

// The scene's meshes (the built-in ones and its glTF models), under --scene (source: the file, or
// the preset's name): its own copy, and each of `renderers` renderers' GPU buffers and their
// upload copies, by the vectors' capacity.
std::vector<MemoryUse> SceneMemoryUses(const Scene& scene, const std::string& source, int renderers = 1);

// The viewer's window: up to 4 swapchain images of 4 bytes a pixel.
std::vector<MemoryUse> SwapchainMemoryUses(const RenderOptions& window);

// a, then b.
std::vector<MemoryUse> Combined(std::vector<MemoryUse> a, const std::vector<MemoryUse>& b);

}  // namespace aerial::cli
