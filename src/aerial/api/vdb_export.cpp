// aerial::ExportFroxelVdb (include/aerial/vdb_export.h) over the froxel exporter.
#include "aerial/vdb_export.h"

#include "aerial/api/impl.h"
#include "aerial/export/camera_frustum.h"
#include "aerial/export/froxel_export.h"

namespace aerial {
namespace {

CaptureSize SizeOf(const VdbExportOptions& options) { return {int(options.width), int(options.height)}; }

}  // namespace

uint64_t CheckVdbExport(const std::filesystem::path& out, const Scene& scene, const AtmosphereParameters& atmosphere,
                        const FroxelGrid& grid, const VdbExportOptions& options) {
  CheckVdbOutputPath(out);
  if (options.world_grid_m) {
    FrameUniforms frame = CaptureFrameUniforms(scene, atmosphere.bottom_radius_m, grid, SizeOf(options));
    return uint64_t(CheckWorldGrid(*options.world_grid_m, FroxelPlacement(frame, grid)));
  }
  // Throws for a near plane beyond far.
  return uint64_t(grid.width) * grid.height * CameraFrustum(scene.camera, SizeOf(options).aspect(), grid).slices();
}

size_t ExportFroxelVdb(const std::filesystem::path& out, const Tables& tables, const Scene& scene,
                       const FroxelGrid& grid, const VdbExportOptions& options) {
  FroxelFrame frame = CaptureFroxels(ImplOf(tables).tables(), scene, grid, SizeOf(options), options.shadows);
  VdbVolume volume = options.world_grid_m ? MakeWorldSpaceVolume(frame, *options.world_grid_m)
                                          : MakeFrustumVolume(frame);
  WriteVdb(out, volume);
  return volume.voxels.size();
}

size_t ExportFroxelVdb(const std::filesystem::path& out, const SceneRenderer& renderer, const Scene& scene) {
  VdbVolume volume = MakeFrustumVolume(ReadFroxelFrame(ImplOf(renderer).renderer, scene));
  WriteVdb(out, volume);
  return volume.voxels.size();
}

}  // namespace aerial
