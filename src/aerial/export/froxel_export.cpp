#include "aerial/export/froxel_export.h"

#include <algorithm>
#include <cctype>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <optional>

#include "aerial/core/atomic_file.h"
#include "aerial/error.h"
#include "aerial/export/camera_frustum.h"
#include "aerial/export/fog_density.h"
#include "aerial/export/ground.h"
#include "aerial/export/volume_grids.h"
#include "aerial/precompute/spectral_precompute.h"
#include "aerial/render/renderer.h"
#include "aerial/scene/camera.h"
#include "aerial/spectrum/spectral_sampling.h"
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

// What the R, G and B channels of the three-channel grids hold.
std::string ChannelsText(const FroxelFrame& frame) {
  if (frame.colour == ColourMode::kSpectral)
    return "linear sRGB (Rec. 709 primaries, D65 white), converted from spectral_wavelengths_nm with the "
           "CIE 1931 2-degree observer; Y is the y-bar-weighted mean spectral value";
  return "the values at wavelengths_nm, in order";
}

// The wavelengths the channels come from: the atmosphere's three, or the spectral sampling's.
std::pair<const std::string, VdbMetaValue> WavelengthsMetadata(const FroxelFrame& frame) {
  if (frame.colour != ColourMode::kSpectral) return {"wavelengths_nm", frame.atmosphere.wavelengths_nm};
  const spectrum::SpectralSampling sampling = spectrum::SpectralSampling::ForTables(frame.spectral_wavelengths);
  std::string list;
  for (double nm : sampling.wavelengths_nm()) {
    if (!list.empty()) list += ',';
    list += Number(nm);
  }
  return {"spectral_wavelengths_nm", list};
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
      {"colour", std::string(frame.colour == ColourMode::kSpectral ? "spectral" : "rgb")},
      {"channels", ChannelsText(frame)},
      WavelengthsMetadata(frame),
      {"planet_radius_m", frame.atmosphere.bottom_radius_m},
      {"froxel_resolution", std::array<int32_t, 3>{grid.width, grid.height, grid.depth}},
      {"froxel_depth_distribution", std::string("quadratic")},
      {"froxel_far_m", grid.far_m},
      {"froxel_slice_distance_m", slices},
      {"froxel_mapping",
       std::string("froxel (i, j, k) is the point at distance froxel_far_m * ((k + 0.5) / D)^2 "
                   "from the camera along the view ray through the image point (x_i, y_j), (0, 0) the top-left "
                   "corner, its columns gathered at the sun's glow and its rows at the horizon: "
                   "x_i = f + s sinh((i + 0.5) / W * (asinh((1 - f) / s) + asinh(f / s)) - asinh(f / s)), f "
                   "froxel_column_focus, s froxel_column_spread; y_j the same with H, froxel_row_focus and "
                   "froxel_row_spread")},
      {"froxel_column_focus", frame.texels.axes.columns.focus},
      {"froxel_column_spread", frame.texels.axes.columns.spread},
      {"froxel_row_focus", frame.texels.axes.rows.focus},
      {"froxel_row_spread", frame.texels.axes.rows.spread},
      {"ground", std::string(frame.terrain ? "terrain" : "planet sphere (sea level)")},
  };
}

}  // namespace

FrameUniforms CaptureFrameUniforms(const Scene& scene, double planet_radius_m, const FroxelGrid& grid,
                                   CaptureSize size) {
  return MakeFrameUniforms(scene, planet_radius_m, size.width, size.height, grid);
}

FroxelFrame ReadFroxelFrame(const Renderer& renderer, const Scene& scene) {
  const AtmosphereTables& tables = renderer.tables();
  FroxelFrame frame;
  frame.texels = renderer.froxels().Read(tables.context(), renderer.frame_uniforms());
  frame.uniforms = renderer.frame_uniforms();
  frame.size = {.width = renderer.options().width, .height = renderer.options().height};
  frame.camera = scene.camera;
  frame.sun = scene.sun;
  frame.lut = tables.options().variant;
  frame.atmosphere = ShaderAtmosphere(tables.atmosphere(), tables.options());
  frame.atmosphere_hash = tables.atmosphere().Hash();
  frame.table_options_hash = tables.options().Hash();
  frame.colour = tables.options().colour;
  frame.spectral_wavelengths = tables.options().spectral_wavelengths;
  frame.terrain = scene.terrain;
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
  if (extension != ".vdb") throw Error("VDB path", path.string(), "a .vdb file");
  CheckOutputFile(path, "VDB path");
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

// The voxels of box whose centers the froxels cover (the ones a world volume can hold), from a
// sample of at most about 2^18 of them: the frustum fills a fifth of its box or less, and the
// box alone overestimated a 3.1 million voxel volume at 16.6 million.
int64_t CoveredVoxels(double voxel_m, const WorldBox& box, const FroxelPlacement& placement) {
  int32_t step = std::max(1, int32_t(std::ceil(std::cbrt(double(box.count) / double(1 << 18)))));
  int64_t sampled = 0, covered = 0;
  for (int32_t z = box.min[2]; z <= box.max[2]; z += step) {
    for (int32_t y = box.min[1]; y <= box.max[1]; y += step) {
      for (int32_t x = box.min[0]; x <= box.max[0]; x += step) {
        std::optional<FroxelPlacement::ScreenPoint> point = placement.ToScreen(glm::dvec3(x, y, z) * voxel_m);
        ++sampled;
        covered += point && placement.Covers(*point);
      }
    }
  }
  return int64_t(std::ceil(double(box.count) * double(covered) / double(sampled)));
}

}  // namespace

int64_t CheckWorldGrid(double voxel_m, const FroxelPlacement& placement) {
  const double far_m = placement.grid().far_m;
  if (!(voxel_m > 0.0 && voxel_m <= far_m))
    throw Error("VdbExportOptions::world_grid_m", Number(voxel_m),
                "a voxel size in meters in (0, " + Number(far_m) + "] (the froxel far distance)");
  std::array<glm::dvec3, 2> bounds = placement.Bounds();
  WorldBox box = WorldGridBox(voxel_m, bounds);
  if (box.count > kMaxWorldGridVoxels) {
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
                  "(or a shorter FroxelGrid::far_m)",
                  kMaxWorldGridVoxels, extent.x, extent.y, extent.z, std::ceil(fits));
    throw Error("VdbExportOptions::world_grid_m", Number(voxel_m), allowed);
  }
  return CoveredVoxels(voxel_m, box, placement);
}

VdbVolume MakeFrustumVolume(const FroxelFrame& frame) {
  const FroxelTexels& texels = frame.texels;
  const FroxelGrid& grid = texels.grid;
  const CameraFrustum frustum(frame.camera, frame.size.aspect(), grid);
  const Ground ground(frame.terrain, frame.atmosphere.bottom_radius_m);
  VdbVolume volume;
  VolumeGrids grids(size_t(grid.width) * grid.height * frustum.slices());
  for (int k = 0; k < frustum.slices(); ++k) {
    for (int j = 0; j < grid.height; ++j) {
      for (int i = 0; i < grid.width; ++i) {
        const glm::dvec3 center = frustum.VoxelCenter(i, j, k);
        const double distance = glm::length(center - frame.camera.position);
        if (distance > grid.far_m || ground.Below(center)) continue;
        volume.voxels.push_back({i, j, k});
        grids.Add(texels.Read(frustum.ScreenPoint(i, j), distance), AirCoefficientsAt(frame.atmosphere, center));
      }
    }
  }
  volume.grids = std::move(grids).Take();
  volume.frustum = frustum.Map();
  volume.grid_metadata = FrameMetadata(frame, "frustum");
  volume.grid_metadata["frustum_near_m"] = frame.camera.near_m;
  volume.grid_metadata["frustum_far_m"] = grid.far_m;
  volume.grid_metadata["frustum_slices"] = int64_t(frustum.slices());
  volume.grid_metadata["index_space"] =
      std::string("frustum: OpenVDB's NonlinearFrustumMap; voxel (i, j, k) is the point at view depth "
                  "frustum_near_m + (frustum_far_m - frustum_near_m) * (k + 0.5) / frustum_slices on the view ray "
                  "through the image point ((i + 0.5) / W, (j + 0.5) / H), (0, 0) the top-left "
                  "corner: the froxels' columns, their values read at each voxel's distance; voxels "
                  "farther than froxel_far_m from the camera or below the ground are inactive");
  volume.file_metadata = volume.grid_metadata;
  return volume;
}

VdbVolume MakeWorldSpaceVolume(const FroxelFrame& frame, double voxel_m) {
  FroxelPlacement placement = frame.placement();
  CheckWorldGrid(voxel_m, placement);
  WorldBox box = WorldGridBox(voxel_m, placement.Bounds());
  const Ground ground(frame.terrain, frame.atmosphere.bottom_radius_m);
  VdbVolume volume;
  VolumeGrids grids(0);
  for (int32_t z = box.min[2]; z <= box.max[2]; ++z) {
    for (int32_t y = box.min[1]; y <= box.max[1]; ++y) {
      for (int32_t x = box.min[0]; x <= box.max[0]; ++x) {
        glm::dvec3 center = glm::dvec3(x, y, z) * voxel_m;
        std::optional<FroxelPlacement::ScreenPoint> point = placement.ToScreen(center);
        if (!point || !placement.Covers(*point) || ground.Below(center)) continue;
        volume.voxels.push_back({x, y, z});
        grids.Add(frame.texels.Read(point->uv, point->distance), AirCoefficientsAt(frame.atmosphere, center));
      }
    }
  }
  volume.grids = std::move(grids).Take();
  volume.voxel_size_m = voxel_m;
  volume.origin_m = {0.0, 0.0, 0.0};  // voxel (i, j, k)'s center is at voxel_m * (i, j, k)
  volume.grid_metadata = FrameMetadata(frame, "world");
  volume.grid_metadata["world_voxel_size_m"] = voxel_m;
  volume.grid_metadata["index_space"] =
      std::string("world: voxel (i, j, k)'s center is at world_voxel_size_m * (i, j, k) in the "
                  "scene frame; voxels outside the froxel frustum or below the ground are inactive");
  volume.file_metadata = volume.grid_metadata;
  return volume;
}

}  // namespace aerial
