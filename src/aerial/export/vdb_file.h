#pragma once
// OpenVDB files, behind plain structs: the only code that includes OpenVDB is vdb_file.cpp (its
// headers are heavy to compile), so the exporter and the tests build VdbVolume values and read
// VdbGridData back without seeing OpenVDB types.
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace aerial {

// OpenVDB metadata has no arrays, so a list goes in as a string.
using VdbMetaValue = std::variant<std::string, double, int64_t, bool, std::array<double, 3>,
                                  std::array<int32_t, 3>>;
using VdbMetadata = std::map<std::string, VdbMetaValue>;

// OpenVDB's grid classes that aerial writes: a fog volume is a density (Houdini and Blender
// render it as smoke); anything else is unknown to them.
enum class VdbGridClass { kUnknown, kFogVolume };

// openvdb::math::NonlinearFrustumMap(BBoxd(index_min, index_max), taper, depth, AffineMap): the
// index box goes to a unit frustum looking down +z, its near face 1 wide (x) and
// (index_max - index_min).y / (index_max - index_min).x high (y) at z = 0, its far face 1 / taper
// times that at z = depth; second_map takes that frustum to the world.
struct VdbFrustum {
  std::array<double, 3> index_min{}, index_max{};
  double taper = 1.0;  // near-face width / far-face width, in (0, 1]
  double depth = 1.0;  // near to far, in near-face widths
  std::array<double, 12> second_map{};  // 3x4 row-major affine: world = M (x, y, z, 1)
};

// Several grids over one set of active voxels and one transform. Without `frustum`, a linear one:
// the world position of voxel index (i, j, k)'s center is origin_m + voxel_size_m * (i, j, k).
struct VdbVolume {
  struct Grid {
    std::string name;
    int components = 3;         // 3: a Vec3SGrid, 1: a FloatGrid
    std::vector<float> values;  // components floats per entry of `voxels`, in the same order
    VdbMetadata metadata;       // this grid's own, after the volume's shared grid_metadata
    float background = 0.0f;    // the value of every inactive voxel (each component)
    VdbGridClass grid_class = VdbGridClass::kUnknown;
  };
  std::vector<std::array<int32_t, 3>> voxels;  // the active voxels (each is written, even if 0)
  double voxel_size_m = 1.0;
  std::array<double, 3> origin_m{};
  std::optional<VdbFrustum> frustum;  // when set, the transform (voxel_size_m, origin_m unused)
  std::vector<Grid> grids;
  VdbMetadata grid_metadata;  // copied onto every grid (DCC tools show grid metadata)
  VdbMetadata file_metadata;  // the file's own metadata
};

// Checks the volume (sizes, names, finite transform), then writes it atomically: to a temporary
// in the same directory, synced, then renamed over path (core/atomic_file.h). Float32 values,
// each grid's background and class, nothing pruned. Throws aerial::Error naming the path on
// failure; no partial file remains.
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
  std::array<float, 3> background{};    // 1 component for a float grid
  std::string grid_class;               // OpenVDB's name: "unknown", "fog volume", ...
  std::string map_type;                 // OpenVDB's: "NonlinearFrustumMap", "UniformScaleTranslateMap", ...
  bool linear_transform = false;
  std::array<double, 12> index_to_world{};  // 3x4 row-major affine, when linear_transform
  VdbMetadata metadata;

  // Through the grid's own OpenVDB transform (any map, the frustum's included).
  std::array<double, 3> IndexToWorld(double i, double j, double k) const { return to_world(i, j, k); }
  std::function<std::array<double, 3>(double, double, double)> to_world;
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
