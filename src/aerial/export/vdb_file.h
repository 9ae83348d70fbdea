#pragma once
// OpenVDB files, behind plain structs: the only code that includes OpenVDB is vdb_file.cpp (its
// headers are heavy to compile), so the exporter and the tests build VdbVolume values and read
// VdbGridData back without seeing OpenVDB types.
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace aerial {

// OpenVDB metadata has no arrays, so a list goes in as a string.
using VdbMetaValue = std::variant<std::string, double, int64_t, bool, std::array<double, 3>,
                                  std::array<int32_t, 3>>;
using VdbMetadata = std::map<std::string, VdbMetaValue>;

// Several grids over one set of active voxels and one linear transform: the world position of
// voxel index (i, j, k)'s center is origin_m + voxel_size_m * (i, j, k).
struct VdbVolume {
  struct Grid {
    std::string name;
    int components = 3;         // 3: a Vec3SGrid, 1: a FloatGrid
    std::vector<float> values;  // components floats per entry of `voxels`, in the same order
    VdbMetadata metadata;       // this grid's own, after the volume's shared grid_metadata
  };
  std::vector<std::array<int32_t, 3>> voxels;  // the active voxels (each is written, even if 0)
  double voxel_size_m = 1.0;
  std::array<double, 3> origin_m{};
  std::vector<Grid> grids;
  VdbMetadata grid_metadata;  // copied onto every grid (DCC tools show grid metadata)
  VdbMetadata file_metadata;  // the file's own metadata
};

// Checks the volume (sizes, names, finite transform), then writes it atomically: to a temporary
// in the same directory, synced, then renamed over path (core/atomic_file.h). Background 0,
// float32 values, nothing pruned. Throws aerial::Error naming the path on failure; no partial
// file remains.
void WriteVdb(const std::filesystem::path& path, const VdbVolume& volume);

// One grid read back, for tests and tools: its active voxels densely over their bounding box.
struct VdbGridData {
  std::string name;
  std::string type;  // OpenVDB's type name: "vec3s", "float", ...
  int components = 0;
  int64_t active_voxels = 0;
  std::array<int32_t, 3> min{}, max{};  // active bounding box, inclusive (index space)
  std::vector<float> values;            // components per voxel of the box, x fastest
  std::vector<uint8_t> active;          // per voxel of the box
  bool linear_transform = false;
  std::array<double, 12> index_to_world{};  // 3x4 row-major affine, when linear_transform
  VdbMetadata metadata;

  std::array<double, 3> IndexToWorld(double i, double j, double k) const;
  // Index of voxel (i, j, k) in the box, or -1 outside it.
  int64_t Offset(int32_t i, int32_t j, int32_t k) const;
};

struct VdbFileData {
  std::vector<VdbGridData> grids;
  VdbMetadata metadata;
  const VdbGridData* Find(const std::string& name) const;
};

// Reads every grid of a float or Vec3S type. Throws aerial::Error naming the path.
VdbFileData ReadVdb(const std::filesystem::path& path);

}  // namespace aerial
