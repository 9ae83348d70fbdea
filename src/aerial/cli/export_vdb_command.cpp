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
#include "aerial/cli/scene_options.h"
#include "aerial/export/froxel_export.h"
#include "aerial/render/renderer.h"

namespace aerial::cli {
namespace {

struct ExportVdbCommandOptions {
  TableOptions tables;
  SceneOptions scene;
  FroxelOptions froxels;
  CaptureSize size;
  std::optional<double> world_grid_m;
  std::string shadows = "on";
  std::filesystem::path out;
};

void RunExportVdb(const ExportVdbCommandOptions& options) {
  auto start = std::chrono::steady_clock::now();
  CheckVdbOutputPath(options.out);
  AtmosphereParameters atmosphere = options.tables.LoadAtmosphere();
  PrecomputeOptions precompute = options.tables.MakePrecomputeOptions();
  FroxelGrid grid = options.froxels.Make();
  RenderOptions render{.width = options.size.width, .height = options.size.height, .froxels = grid,
                       .shadows = ParseShadows(options.shadows)};
  render.Validate();
  Scene scene = options.scene.Load(atmosphere.bottom_radius_m);
  if (options.world_grid_m) {
    FroxelPlacement placement(CaptureFrameUniforms(scene, atmosphere.bottom_radius_m, grid, options.size), grid);
    CheckWorldGrid(*options.world_grid_m, placement);
  }
  auto context = options.tables.MakeContext();
  options.tables.MakeMemoryBudget(*context).Check(
      Combined(TableMemoryUses(precompute), Combined(FrameMemoryUses(render), FroxelExportMemoryUses(grid))));
  LoadedTables loaded = LoadOrPrecompute(*context, atmosphere, precompute, options.tables.MakeStoreOptions());
  FroxelFrame frame = CaptureFroxels(*loaded.tables, scene, grid, options.size, render.shadows);
  VdbVolume volume = options.world_grid_m ? MakeWorldSpaceVolume(frame, *options.world_grid_m)
                                          : MakeFroxelSpaceVolume(frame);
  WriteVdb(options.out, volume);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("wrote %s: %zu voxels per grid (%s), %.2f s\n", options.out.c_str(),
              volume.voxels.size(), options.world_grid_m ? "world grid" : "froxel space", seconds);
}

}  // namespace

void AddExportVdbCommand(CLI::App& app) {
  auto options = std::make_shared<ExportVdbCommandOptions>();
  CLI::App* command =
      app.add_subcommand("export-vdb", "Write one frame's froxel volume to an OpenVDB file");
  options->tables.AddTo(*command);
  options->scene.AddTo(*command);
  options->froxels.AddTo(*command);
  command->add_option("--width", options->size.width,
                      "Width of the image the froxels are for (its aspect shapes the frustum)");
  command->add_option("--height", options->size.height, "Height of that image");
  command->add_option("--world-grid", options->world_grid_m,
                      "Resample into a regular world-space grid of this voxel size (m) instead of "
                      "writing the froxels in their own index space");
  command->add_option("--shadows", options->shadows,
                      "The sun's shadow map in the frame the froxels are captured from: on (default) or off");
  command->add_option("--out", options->out, "Output file (.vdb)")->required();
  command->callback([options] { RunExportVdb(*options); });
}

}  // namespace aerial::cli
