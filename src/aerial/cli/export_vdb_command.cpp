// aerial export-vdb: one frame's froxel volume, as the renderer computed it, to an OpenVDB file
// (src/aerial/export/froxel_export.h). Every input, the output path included, is checked before
// any GPU work; the file is written atomically.
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>

#include "aerial/cli/commands.h"
#include "aerial/cli/common_options.h"
#include "aerial/cli/memory_uses.h"
#include "aerial/cli/path_option.h"
#include "aerial/cli/scene_options.h"
#include "aerial/core/output_conflicts.h"
#include "aerial/error.h"
#include "aerial/renderer.h"
#include "aerial/vdb_export.h"

namespace aerial::cli {
namespace {

struct ExportVdbCommandOptions {
  TableOptions tables;
  SceneOptions scene;
  FroxelOptions froxels;
  VdbExportOptions vdb;
  std::string shadows = "on";
  std::filesystem::path out;
};

void RunExportVdb(const ExportVdbCommandOptions& options) {
  auto start = std::chrono::steady_clock::now();
  AtmosphereParameters atmosphere = options.tables.LoadAtmosphere();
  PrecomputeOptions precompute = options.tables.MakePrecomputeOptions();
  FroxelGrid grid = options.froxels.Make();
  VdbExportOptions vdb = options.vdb;
  vdb.shadows = ParseShadows(options.shadows);
  RendererOptions render{{.width = int(vdb.width), .height = int(vdb.height), .froxels = grid, .shadows = vdb.shadows}};
  render.Validate();
  Scene scene = options.scene.Load(atmosphere.bottom_radius_m, options.tables.MakeHostMemoryBudget());
  uint64_t most_voxels = CheckVdbExport(options.out, scene, atmosphere, grid, vdb);
  CheckOutputConflicts({{"--out", options.out}});
  Device device(options.tables.MakeDeviceOptions());
  std::vector<MemoryUse> uses = Combined(SceneMemoryUses(scene, options.scene.Source()),
                                         Combined(TableMemoryUses(precompute),
                                                  Combined(FrameMemoryUses(render), FroxelExportMemoryUses(grid))));
  uses = Combined(uses, vdb.world_grid_m ? WorldGridMemoryUses(*vdb.world_grid_m, most_voxels)
                                         : FrustumGridMemoryUses(grid, most_voxels));
  options.tables.MakeMemoryBudget(device.largest_heap_bytes()).Check(uses);
  Tables tables = Tables::LoadOrPrecompute(device, atmosphere, precompute, options.tables.MakeLoadOptions());
  size_t voxels = ExportFroxelVdb(options.out, tables, scene, grid, vdb);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("wrote %s: %zu voxels per grid (%s), %.2f s\n", Printable(options.out.native()).c_str(), voxels,
              vdb.world_grid_m ? "world grid" : "camera frustum", seconds);
}

}  // namespace

void AddExportVdbCommand(CLI::App& app) {
  auto options = std::make_shared<ExportVdbCommandOptions>();
  CLI::App* command =
      app.add_subcommand("export-vdb", "Write one frame's froxel volume to an OpenVDB file");
  options->scene.AddTo(*command);
  options->froxels.AddTo(*command);
  command->add_option("--width", options->vdb.width,
                      "Width of the image the froxels are for (its aspect shapes the frustum)");
  command->add_option("--height", options->vdb.height, "Height of that image");
  command->add_option("--world-grid", options->vdb.world_grid_m,
                      "Resample into a regular world-space grid of this voxel size (m), for Blender, "
                      "instead of the camera's frustum (OpenVDB's frustum transform, for Houdini)");
  command->add_option("--shadows", options->shadows,
                      "The sun's shadow map in the frame the froxels are captured from: on (default) or off");
  AddPathOption(*command, "--out", options->out, "Output file (.vdb)")->required();
  options->tables.AddTo(*command);
  command->callback([options] { RunExportVdb(*options); });
}

}  // namespace aerial::cli
