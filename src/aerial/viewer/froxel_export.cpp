#include "aerial/viewer/froxel_export.h"

#include <ctime>

#include "aerial/error.h"
#include "aerial/vdb_export.h"

namespace aerial::viewer {

std::string ExportFroxelsToVdb(const SceneRenderer& renderer, const Scene& scene,
                               const std::filesystem::path& directory) {
  if (renderer.options().mode != AerialMode::kFroxel)
    return "VDB export: the froxel volume is only built in froxel mode";
  std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char name[64];
  std::strftime(name, sizeof name, "aerial-froxels-%Y%m%d-%H%M%S.vdb", &local);
  std::filesystem::path path = directory / name;
  try {
    ExportFroxelVdb(path, renderer, scene);
  } catch (const Error& e) {
    return std::string("VDB export: ") + e.what();
  }
  return "Exported the froxel volume to " + path.string();
}

}  // namespace aerial::viewer
