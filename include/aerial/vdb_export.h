#pragma once
// One frame's froxel volume as an OpenVDB file, to inspect in Houdini or Blender: the grids, their
// units and frame are in docs/vdb.md.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>

#include "aerial/atmosphere.h"
#include "aerial/froxel_grid.h"
#include "aerial/renderer.h"
#include "aerial/scene.h"
#include "aerial/tables.h"

namespace aerial {

struct VdbExportOptions {
  uint32_t width = 1280, height = 720;  // the image the froxels are for: its aspect shapes the frustum
  // Resample onto a regular world-space grid of this voxel size (m), instead of the camera's
  // frustum (OpenVDB's frustum transform).
  std::optional<double> world_grid_m;
  bool shadows = true;  // the sun's shadow map in the frame the volume is captured from
};

// Checks, before any GPU work, the output path (.vdb, an existing directory where a file can be
// created; errors name the VDB path), the world grid (voxel size in (0, far], at most 2^24 voxels
// over the frustum's bounding box; errors name VdbExportOptions::world_grid_m) or else the frustum grid (the
// camera's near plane in (0, far); errors name camera.near_m). Returns the most voxels the volume
// can have (the frustum grid's, or the world grid's voxels the froxels cover, sampled), for a
// memory estimate.
uint64_t CheckVdbExport(const std::filesystem::path& out, const Scene& scene, const AtmosphereParameters& atmosphere,
                        const FroxelGrid& grid, const VdbExportOptions& options);

// Renders the scene's frame once (SceneRenderer) and writes its froxel volume to out, atomically
// (a temporary file, then a rename). Returns the number of active voxels per grid.
size_t ExportFroxelVdb(const std::filesystem::path& out, const Tables& tables, const Scene& scene,
                       const FroxelGrid& grid, const VdbExportOptions& options);

// The froxel volume of the renderer's last frame (RenderOptions::mode kFroxel), which drew scene,
// in the frustum layout; call once that frame has finished. Returns the active voxels per grid.
size_t ExportFroxelVdb(const std::filesystem::path& out, const SceneRenderer& renderer, const Scene& scene);

}  // namespace aerial
