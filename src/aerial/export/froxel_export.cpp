#include "aerial/export/froxel_export.h"

#include <algorithm>
#include <cctype>
#include <cinttypes>
#include <cmath>
#include <cstdio>

#include "aerial/core/atomic_file.h"
#include "aerial/error.h"
#include "aerial/render/renderer.h"
#include "aerial/scene/camera.h"
#include "aerial/version.h"

namespace aerial {
namespace {

std::array<double, 3> ToArray(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

std::string Hex(uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "%016" PRIx64, value);
  return text;
}

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

// What the file says about the frame, on the file and on every grid.
VdbMetadata FrameMetadata(const FroxelFrame& frame, const std::string& grid_space) {
  const FroxelGrid& grid = frame.texels.grid;
  std::string slices;
  for (int k = 0; k < grid.depth; ++k) {
    if (k > 0) slices += ',';
    slices += Number(grid.SliceDistance(k + 0.5));
  }
  return {
      {"aerial_version", std::string(AERIAL_VERSION)},
      {"units", std::string("meters")},
      {"coordinate_frame",
       std::string("aerial scene frame: x east, y north, z up (right-handed, Z-up), meters; "
                   "planet center at (0, 0, -planet_radius_m)")},
      {"grid_space", grid_space},
      {"camera_position_m", ToArray(frame.camera.position)},
      {"camera_forward", ToArray(Forward(frame.camera))},
      {"camera_up", ToArray(Up(frame.camera))},
      {"camera_right", ToArray(Right(frame.camera))},
      {"camera_yaw_deg", frame.camera.yaw_deg},
      {"camera_pitch_deg", frame.camera.pitch_deg},
      {"camera_vertical_fov_deg", frame.camera.vertical_fov_deg},
      {"camera_aspect", frame.size.aspect()},
      {"camera_near_m", frame.camera.near_m},
      {"camera_far_m", grid.far_m},
      {"sun_direction", ToArray(frame.sun.Direction())},
      {"sun_zenith_deg", frame.sun.zenith_deg},
      {"sun_azimuth_deg", frame.sun.azimuth_deg},
      {"lut", ToString(frame.lut)},
      {"atmosphere_hash", Hex(frame.atmosphere_hash)},
      {"table_options_hash", Hex(frame.table_options_hash)},
      {"wavelengths_nm", frame.wavelengths_nm},
      {"planet_radius_m", frame.planet_radius_m},
      {"froxel_resolution", std::array<int32_t, 3>{grid.width, grid.height, grid.depth}},
      {"froxel_depth_distribution", std::string("quadratic")},
      {"froxel_far_m", grid.far_m},
      {"froxel_slice_distance_m", slices},
      {"froxel_mapping",
       std::string("froxel (i, j, k) is the point at distance froxel_far_m * ((k + 0.5) / D)^2 "
                   "from the camera along the view ray through the image point "
                   "((i + 0.5) / W, (j + 0.5) / H), (0, 0) the top-left corner")},
  };
}

struct GridText {
  const char* name;
  const char* units;
  const char* description;
};

constexpr GridText kRayleigh{"rayleigh_inscatter", "W/m^2/nm",
                             "Rayleigh inscatter from the camera to the point, without phase: times "
                             "the Rayleigh phase function (1/sr) it is radiance (W/m^2/sr/nm); "
                             "channels are wavelengths_nm"};
constexpr GridText kMie{"mie_inscatter", "W/m^2/nm",
                        "Mie inscatter from the camera to the point, without phase: times the Mie "
                        "phase function (1/sr) it is radiance (W/m^2/sr/nm); channels are "
                        "wavelengths_nm"};
constexpr GridText kTransmittance{"transmittance", "1",
                                  "transmittance from the camera to the point; channels are "
                                  "wavelengths_nm"};
constexpr GridText kLuminance{"inscatter_luminance", "W/m^2/nm",
                              "0.2126 R + 0.7152 G + 0.0722 B of rayleigh_inscatter + "
                              "mie_inscatter (phase taken as 1): a scalar to look at the volume "
                              "with, not a photometric quantity"};
constexpr GridText kPosition{"froxel_position", "m",
                             "world position (scene frame) of the froxel's center, where the "
                             "renderer puts it"};

VdbVolume::Grid MakeGrid(const GridText& text, int components, size_t voxels) {
  VdbVolume::Grid grid{.name = text.name, .components = components};
  grid.values.reserve(voxels * components);
  grid.metadata = {{"value_units", std::string(text.units)},
                   {"description", std::string(text.description)}};
  return grid;
}

}  // namespace

double InscatterLuminance(const float* rayleigh, const float* mie) {
  return 0.2126 * (double(rayleigh[0]) + mie[0]) + 0.7152 * (double(rayleigh[1]) + mie[1]) +
         0.0722 * (double(rayleigh[2]) + mie[2]);
}

FrameUniforms CaptureFrameUniforms(const Scene& scene, double planet_radius_m, const FroxelGrid& grid,
                                   CaptureSize size) {
  return MakeFrameUniforms(scene, planet_radius_m, size.width, size.height, grid);
}

FroxelFrame ReadFroxelFrame(const Renderer& renderer, const Scene& scene) {
  const AtmosphereTables& tables = renderer.tables();
  FroxelFrame frame;
  frame.texels = renderer.froxels().Read(tables.context());
  frame.uniforms = renderer.frame_uniforms();
  frame.size = {.width = renderer.options().width, .height = renderer.options().height};
  frame.camera = scene.camera;
  frame.sun = scene.sun;
  frame.lut = tables.options().variant;
  frame.atmosphere_hash = tables.atmosphere().Hash();
  frame.table_options_hash = tables.options().Hash();
  frame.wavelengths_nm = tables.atmosphere().wavelengths_nm;
  frame.planet_radius_m = tables.atmosphere().bottom_radius_m;
  return frame;
}

FroxelFrame CaptureFroxels(const AtmosphereTables& tables, const Scene& scene, const FroxelGrid& grid,
                           CaptureSize size, bool shadows) {
  Renderer renderer(tables, scene,
                    {.width = size.width, .height = size.height, .froxels = grid,
                     .mode = AerialMode::kFroxel, .shadows = shadows});
  renderer.Render(scene);
  return ReadFroxelFrame(renderer, scene);
}

void CheckVdbOutputPath(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".vdb") throw Error("--out", path.string(), "a .vdb file");
  std::filesystem::path parent = path.parent_path().empty() ? "." : path.parent_path();
  std::error_code error;
  if (!std::filesystem::is_directory(parent, error))
    throw Error("--out", path.string(), "a file in an existing directory (" + parent.string() +
                                            " does not exist or is not a directory)");
  CheckWritable(path);
}

namespace {

struct WorldBox {
  std::array<int32_t, 3> min, max;
  int64_t count;  // above kMaxWorldGridVoxels: too many (the box is then not filled in)
};

// The voxels whose centers (voxel_m * index) span the covered volume's box.
WorldBox WorldGridBox(double voxel_m, const std::array<glm::dvec3, 2>& bounds) {
  WorldBox box{};
  box.count = 1;
  for (int axis = 0; axis < 3; ++axis) {
    double lo = std::floor(bounds[0][axis] / voxel_m), hi = std::ceil(bounds[1][axis] / voxel_m);
    // Checked in doubles first: a tiny voxel must not overflow the int32 coordinates.
    if (hi - lo + 1 > double(kMaxWorldGridVoxels)) {
      box.count = kMaxWorldGridVoxels + 1;
      return box;
    }
    box.min[axis] = int32_t(lo);
    box.max[axis] = int32_t(hi);
    box.count *= int64_t(hi - lo + 1);
    if (box.count > kMaxWorldGridVoxels) return box;
  }
  return box;
}

}  // namespace

void CheckWorldGrid(double voxel_m, const FroxelPlacement& placement) {
  const double far_m = placement.grid().far_m;
  if (!(voxel_m > 0.0 && voxel_m <= far_m))
    throw Error("--world-grid", Number(voxel_m),
                "a voxel size in meters in (0, " + Number(far_m) + "] (the froxel far distance)");
  std::array<glm::dvec3, 2> bounds = placement.Bounds();
  if (WorldGridBox(voxel_m, bounds).count > kMaxWorldGridVoxels) {
    // The smallest voxel (to 1 m) that fits: the count falls as the voxel grows, up to the
    // rounding of the box to whole voxels, which the bisection tolerates.
    double too_small = voxel_m, fits = far_m;
    while (fits - too_small > 1.0) {
      double middle = 0.5 * (too_small + fits);
      (WorldGridBox(middle, bounds).count > kMaxWorldGridVoxels ? too_small : fits) = middle;
    }
    glm::dvec3 extent = bounds[1] - bounds[0];
    char allowed[256];
    std::snprintf(allowed, sizeof allowed,
                  "a voxel size in meters giving at most %" PRId64
                  " voxels over this frustum's %.0f x %.0f x %.0f m box: %.0f m or more here "
                  "(or a shorter --froxel-far-m)",
                  kMaxWorldGridVoxels, extent.x, extent.y, extent.z, std::ceil(fits));
    throw Error("--world-grid", Number(voxel_m), allowed);
  }
}

VdbVolume MakeFroxelSpaceVolume(const FroxelFrame& frame) {
  const FroxelTexels& texels = frame.texels;
  const FroxelGrid& grid = texels.grid;
  FroxelPlacement placement = frame.placement();
  size_t count = size_t(grid.width) * grid.height * grid.depth;
  VdbVolume volume;
  volume.voxels.reserve(count);
  VdbVolume::Grid rayleigh = MakeGrid(kRayleigh, 3, count), mie = MakeGrid(kMie, 3, count),
                  transmittance = MakeGrid(kTransmittance, 3, count),
                  luminance = MakeGrid(kLuminance, 1, count), position = MakeGrid(kPosition, 3, count);
  for (int k = 0; k < grid.depth; ++k) {
    for (int j = 0; j < grid.height; ++j) {
      for (int i = 0; i < grid.width; ++i) {
        size_t texel = ((size_t(k) * grid.height + j) * grid.width + i) * 4;
        volume.voxels.push_back({i, j, k});
        for (int c = 0; c < 3; ++c) {
          rayleigh.values.push_back(texels.rayleigh[texel + c]);
          mie.values.push_back(texels.mie[texel + c]);
          transmittance.values.push_back(texels.transmittance[texel + c]);
        }
        luminance.values.push_back(
            float(InscatterLuminance(&texels.rayleigh[texel], &texels.mie[texel])));
        glm::dvec3 center = placement.FroxelCenter(i, j, k);
        for (int c = 0; c < 3; ++c) position.values.push_back(float(center[c]));
      }
    }
  }
  volume.grids = {std::move(rayleigh), std::move(mie), std::move(transmittance),
                  std::move(luminance), std::move(position)};
  volume.voxel_size_m = 1.0;  // identity: index space is froxel space
  volume.grid_metadata = FrameMetadata(frame, "froxel");
  volume.grid_metadata["index_space"] =
      std::string("froxel: voxel (i, j, k) is froxel (i, j, k), i right, j down the image, k away "
                  "from the camera; the transform is the identity, see froxel_position and "
                  "froxel_mapping for where each froxel is");
  volume.file_metadata = volume.grid_metadata;
  return volume;
}

VdbVolume MakeWorldSpaceVolume(const FroxelFrame& frame, double voxel_m) {
  FroxelPlacement placement = frame.placement();
  CheckWorldGrid(voxel_m, placement);
  WorldBox box = WorldGridBox(voxel_m, placement.Bounds());
  VdbVolume volume;
  VdbVolume::Grid rayleigh = MakeGrid(kRayleigh, 3, 0), mie = MakeGrid(kMie, 3, 0),
                  transmittance = MakeGrid(kTransmittance, 3, 0), luminance = MakeGrid(kLuminance, 1, 0);
  for (int32_t z = box.min[2]; z <= box.max[2]; ++z) {
    for (int32_t y = box.min[1]; y <= box.max[1]; ++y) {
      for (int32_t x = box.min[0]; x <= box.max[0]; ++x) {
        glm::dvec3 center = glm::dvec3(x, y, z) * voxel_m;
        std::optional<FroxelPlacement::ScreenPoint> point = placement.ToScreen(center);
        if (!point || !placement.Covers(*point)) continue;
        FroxelTexels::Sample sample = frame.texels.Read(point->uv, point->distance);
        volume.voxels.push_back({x, y, z});
        float r[3], m[3];
        for (int c = 0; c < 3; ++c) {
          r[c] = float(sample.rayleigh[c]);
          m[c] = float(sample.mie[c]);
          rayleigh.values.push_back(r[c]);
          mie.values.push_back(m[c]);
          transmittance.values.push_back(float(sample.transmittance[c]));
        }
        luminance.values.push_back(float(InscatterLuminance(r, m)));
      }
    }
  }
  volume.grids = {std::move(rayleigh), std::move(mie), std::move(transmittance), std::move(luminance)};
  volume.voxel_size_m = voxel_m;
  volume.origin_m = {0.0, 0.0, 0.0};  // voxel (i, j, k)'s center is at voxel_m * (i, j, k)
  volume.grid_metadata = FrameMetadata(frame, "world");
  volume.grid_metadata["world_voxel_size_m"] = voxel_m;
  volume.grid_metadata["index_space"] =
      std::string("world: voxel (i, j, k)'s center is at world_voxel_size_m * (i, j, k) in the "
                  "scene frame; voxels outside the froxel frustum are inactive");
  volume.file_metadata = volume.grid_metadata;
  return volume;
}

}  // namespace aerial
