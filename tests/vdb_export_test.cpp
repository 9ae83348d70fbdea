// CTest label "sanitizer": the VDB export: run under the sanitizers too.
// `aerial export-vdb`: the froxel volume of one frame, written to OpenVDB and read back. The
// frustum grid's OpenVDB frustum transform puts each voxel where the camera saw it and the voxel
// holds the GPU's froxels read there; the world grid samples them at its voxel centers; neither
// has a voxel below the ground or beyond the froxels; `density` is a fog volume of the air's
// extinction, `transmittance` has background 1; the metadata survives; Debian's own OpenVDB
// Python binding sees all of it; bad paths leave nothing behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "aerial/error.h"
#include "aerial/export/camera_frustum.h"
#include "aerial/export/froxel_export.h"
#include "aerial/image/scratch_dir_test_util.h"
#include "aerial/api/impl.h"
#include "aerial/render/renderer.h"
#include "aerial/scene.h"
#include "aerial/scene/terrain.h"
#include "aerial/shader_abi/frame_geometry.h"
#include "aerial/version.h"
#include "aerial/viewer/froxel_export.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

// A small image of render's default 16:9 aspect.
constexpr CaptureSize kTestSize{.width = 64, .height = 36};

FroxelGrid TestGrid() {
  FroxelGrid grid;
  grid.width = 16;
  grid.height = 8;
  grid.depth = 12;
  return grid;
}

Scene TestScene(const AtmosphereTables& tables) {
  Scene scene = BuildPreset("noon", tables.atmosphere().bottom_radius_m);
  // Off the origin and turned, so that a mix-up of axes or of camera-relative and world
  // positions cannot pass.
  scene.camera.position = glm::dvec3(1234.0, -567.0, 350.0);
  scene.camera.yaw_deg = 35.0;
  scene.camera.pitch_deg = 8.0;
  return scene;
}

// The renderer's view ray through image point (u, v), computed here from the frame block as
// shaders/frame/froxel.comp and shaders/include/frame.glsl do (ViewRayFromScreen), independently
// of the exporter.
glm::dvec3 RendererRay(const FrameUniforms& frame, double u, double v) {
  const auto& m = frame.inverse_view_projection;
  double clip[4] = {2.0 * u - 1.0, 2.0 * v - 1.0, 0.5, 1.0};
  double world[4] = {0, 0, 0, 0};
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) world[row] += m[column * 4 + row] * clip[column];
  return glm::normalize(glm::dvec3(world[0], world[1], world[2]) / world[3]);
}

// The camera's frustum from the scene's camera parameters alone (yaw, pitch, vertical fov, the
// image's aspect): the point at view depth z (along the view axis) on the ray through image
// point (u, v), (0, 0) the top-left corner, u right, v down.
struct ExpectedFrustum {
  glm::dvec3 position, forward, right, up;
  double tan_half_fov, aspect;

  ExpectedFrustum(const Camera& camera, double image_aspect) {
    double yaw = glm::radians(camera.yaw_deg), pitch = glm::radians(camera.pitch_deg);
    position = camera.position;
    forward = {std::sin(yaw) * std::cos(pitch), std::cos(yaw) * std::cos(pitch), std::sin(pitch)};
    right = {std::cos(yaw), -std::sin(yaw), 0.0};  // horizontal: the image has no roll
    up = glm::cross(right, forward);
    tan_half_fov = std::tan(glm::radians(camera.vertical_fov_deg) / 2.0);
    aspect = image_aspect;
  }
  glm::dvec3 Point(double u, double v, double view_depth) const {
    return position + view_depth * (forward + (2.0 * u - 1.0) * tan_half_fov * aspect * right +
                                    (1.0 - 2.0 * v) * tan_half_fov * up);
  }
};

// The test scene's ground: the built-in terrain, from the scene's own height function.
bool BelowTerrain(const glm::dvec3& point, double planet_radius_m) {
  return HeightAboveTerrainM(point, planet_radius_m) < 0.0;
}

// The shaders' read of the froxels at screen position (u, v) and a distance (SampleFroxels in
// shaders/include/froxel.glsl), written here from the GLSL and Vulkan's linear filtering with
// clamp-to-edge addressing, independently of FroxelTexels::Read (froxel_placement.cpp), which the
// world grid calls: texture coordinate (axes.Coordinates(u, v), grid.DepthCoordinate(distance))
// times the size, less half a texel, weighs the two nearest texels on each axis, their indices
// clamped to the edge; below the first slice center, grid.SliceDistance(0.5), the values blend
// toward the empty segment. The screen and depth mappings themselves are FroxelAxis' and FroxelGrid's
// (tests/cpu_gpu_mapping_test.cpp holds them to the shaders').
FroxelTexels::Sample ReadLikeTheShader(const FroxelTexels& texels, double u, double v, double distance) {
  const FroxelGrid& grid = texels.grid;
  const int size[3] = {grid.width, grid.height, grid.depth};
  const glm::dvec2 xy = texels.axes.Coordinates({u, v});
  const double coordinate[3] = {xy.x * size[0] - 0.5, xy.y * size[1] - 0.5,
                                grid.DepthCoordinate(distance) * size[2] - 0.5};
  int low[3];
  double fraction[3];
  for (int axis = 0; axis < 3; ++axis) {
    low[axis] = int(std::floor(coordinate[axis]));
    fraction[axis] = coordinate[axis] - low[axis];
  }
  FroxelTexels::Sample sample{glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
  for (int dk = 0; dk < 2; ++dk)
    for (int dj = 0; dj < 2; ++dj)
      for (int di = 0; di < 2; ++di) {
        double weight = (di ? fraction[0] : 1.0 - fraction[0]) * (dj ? fraction[1] : 1.0 - fraction[1]) *
                        (dk ? fraction[2] : 1.0 - fraction[2]);
        int i = std::clamp(low[0] + di, 0, size[0] - 1), j = std::clamp(low[1] + dj, 0, size[1] - 1),
            k = std::clamp(low[2] + dk, 0, size[2] - 1);
        size_t texel = ((size_t(k) * grid.height + j) * grid.width + i) * 4;
        for (int c = 0; c < 3; ++c) {
          sample.rayleigh[c] += weight * texels.rayleigh[texel + c];
          sample.mie[c] += weight * texels.mie[texel + c];
          sample.transmittance[c] += weight * texels.transmittance[texel + c];
        }
      }
  double first = grid.SliceDistance(0.5);
  if (distance < first) {
    double t = distance / first;
    sample.rayleigh *= t;
    sample.mie *= t;
    sample.transmittance = 1.0 + (sample.transmittance - 1.0) * t;
  }
  return sample;
}

// The density of fog_density.h, written here from its equation: the Rec. 709 luma of the air's
// extinction coefficients (Rayleigh scattering, Mie extinction, ozone absorption, each times its
// density profile) at the point's altitude above the planet sphere, in 1/m; none above the
// atmosphere's top, sea level's below sea level.
double AirExtinction(const AtmosphereParameters& air, const glm::dvec3& point) {
  double altitude = glm::length(point - glm::dvec3(0.0, 0.0, -air.bottom_radius_m)) - air.bottom_radius_m;
  if (altitude > air.top_radius_m - air.bottom_radius_m) return 0.0;
  altitude = std::max(altitude, 0.0);
  glm::dvec3 sigma;
  for (int c = 0; c < 3; ++c)
    sigma[c] = air.rayleigh_scattering[c] * air.rayleigh_density.Density(altitude) +
               air.mie_extinction[c] * air.mie_density.Density(altitude) +
               air.absorption_extinction[c] * air.absorption_density.Density(altitude);
  return 0.2126 * sigma.r + 0.7152 * sigma.g + 0.0722 * sigma.b;
}

double RelativeError(double read, double expected) {
  return std::abs(read - expected) / std::max(std::abs(expected), 1e-30);
}

template <typename T>
T Meta(const VdbMetadata& metadata, const std::string& key) {
  auto it = metadata.find(key);
  if (it == metadata.end()) {
    ADD_FAILURE() << "missing metadata " << key;
    return T{};
  }
  const T* value = std::get_if<T>(&it->second);
  if (!value) {
    ADD_FAILURE() << "metadata " << key << " has another type";
    return T{};
  }
  return *value;
}

std::string Hex(uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "%016" PRIx64, value);
  return text;
}

class VdbExport : public GpuTest {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("aerial_vdb_test_" + std::to_string(::getpid()) + "_" + info->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::filesystem::remove_all(dir_);
    GpuTest::TearDown();
  }

  const AtmosphereTables& tables() const { return SmallTables(); }

  FroxelFrame Capture() const { return CaptureFroxels(tables(), TestScene(tables()), TestGrid(), kTestSize); }

  std::filesystem::path dir_;
};

// The GPU's froxels of a renderer of the test's own, read back.
FroxelTexels GpuTexels(const Renderer& renderer, const FroxelGrid& grid) {
  const vk::Context& context = renderer.tables().context();
  const FroxelVolume& froxels = renderer.froxels();
  return {grid, AxesOf(renderer.frame_uniforms()),
          vk::ReadImageFloats(context, froxels.rayleigh()), vk::ReadImageFloats(context, froxels.mie()),
          vk::ReadImageFloats(context, froxels.transmittance())};
}

// The frustum grid, read back through the OpenVDB library: each voxel of the W x H x D box,
// placed by the file's own frustum transform, is active where it lies within the froxels' far
// distance and above the terrain, and then holds the GPU's froxels (from a renderer of the
// test's own) read there the way the shaders read them (ReadLikeTheShader at the voxel column's
// image point and the voxel's distance) and the air's extinction there (AirExtinction).
// Tolerance 1e-6 relative: float32 of the export's double values from the same float texels, at a
// point that differs from the test's by the rounding of OpenVDB's map (~1e-15 relative).
// Every grid has its class and background: density a fog volume, transmittance background 1.
TEST_F(VdbExport, FrustumGridHoldsTheGpuFroxelsWhereEachVoxelSits) {
  Scene scene = TestScene(tables());
  FroxelGrid grid = TestGrid();
  Renderer renderer(tables(), scene, {.width = kTestSize.width, .height = kTestSize.height, .froxels = grid});
  renderer.Render(scene);
  FroxelTexels gpu = GpuTexels(renderer, grid);

  FroxelFrame frame = CaptureFroxels(tables(), scene, grid, kTestSize);
  WriteVdb(dir_ / "f.vdb", MakeFrustumVolume(frame));
  VdbFileData file = ReadVdb(dir_ / "f.vdb");

  const char* names[5] = {"rayleigh_inscatter", "mie_inscatter", "transmittance", "inscatter_luminance", "density"};
  const VdbGridData* grids[5];
  for (int g = 0; g < 5; ++g) {
    grids[g] = file.Find(names[g]);
    ASSERT_NE(grids[g], nullptr) << names[g];
    EXPECT_EQ(grids[g]->type, g < 3 ? "vec3s" : "float") << names[g];
    EXPECT_EQ(grids[g]->map_type, "NonlinearFrustumMap") << names[g];
    EXPECT_EQ(grids[g]->grid_class, g == 4 ? "fog volume" : "unknown") << names[g];
    float background = g == 2 ? 1.0f : 0.0f;  // transmittance: clear air
    for (int c = 0; c < grids[g]->components; ++c) EXPECT_EQ(grids[g]->background[c], background) << names[g];
  }
  const VdbGridData& transmittance = *grids[2];
  for (const VdbGridData* g : grids) {
    EXPECT_EQ(g->active_voxels, transmittance.active_voxels) << g->name;
    ASSERT_EQ(g->min, transmittance.min) << g->name;
    ASSERT_EQ(g->max, transmittance.max) << g->name;
  }

  const glm::dvec3 camera = scene.camera.position;
  const double radius = tables().atmosphere().bottom_radius_m;
  const int64_t slices = Meta<int64_t>(file.metadata, "frustum_slices");
  int64_t active = 0, beyond_far = 0, below_ground = 0, wrong_activity = 0, nonzero = 0;
  double worst[5] = {0, 0, 0, 0, 0};
  for (int k = 0; k < slices; ++k)
    for (int j = 0; j < grid.height; ++j)
      for (int i = 0; i < grid.width; ++i) {
        auto world = transmittance.IndexToWorld(i, j, k);  // OpenVDB's frustum map
        glm::dvec3 point(world[0], world[1], world[2]);
        double distance = glm::length(point - camera);
        bool beyond = distance > grid.far_m, below = !beyond && BelowTerrain(point, radius);
        beyond_far += beyond;
        below_ground += below;
        int64_t offset = transmittance.Offset(i, j, k);
        bool is_active = offset >= 0 && transmittance.active[offset];
        wrong_activity += is_active == (beyond || below);
        if (!is_active || beyond || below) continue;
        ++active;
        double u = (i + 0.5) / grid.width, v = (j + 0.5) / grid.height;
        FroxelTexels::Sample expected = ReadLikeTheShader(gpu, u, v, distance);
        const glm::dvec3* values[3] = {&expected.rayleigh, &expected.mie, &expected.transmittance};
        for (int g = 0; g < 3; ++g)
          for (int c = 0; c < 3; ++c) {
            float read = grids[g]->values[offset * 3 + c];
            worst[g] = std::max(worst[g], RelativeError(read, (*values[g])[c]));
            nonzero += read != 0.0f;
          }
        glm::dvec3 inscatter = expected.rayleigh + expected.mie;  // Rec. 709 luma of the inscatter
        double luma = 0.2126 * inscatter.r + 0.7152 * inscatter.g + 0.0722 * inscatter.b;
        worst[3] = std::max(worst[3], RelativeError(grids[3]->values[offset], luma));
        double density = AirExtinction(tables().atmosphere(), point);
        worst[4] = std::max(worst[4], RelativeError(grids[4]->values[offset], density));
      }
  std::printf("frustum grid: %" PRId64 " active voxels, %" PRId64 " beyond far, %" PRId64
              " below the ground; worst relative error rayleigh %.2e, mie %.2e, transmittance %.2e, "
              "luminance %.2e, density %.2e\n",
              active, beyond_far, below_ground, worst[0], worst[1], worst[2], worst[3], worst[4]);
  EXPECT_EQ(wrong_activity, 0);
  EXPECT_EQ(active, transmittance.active_voxels);
  EXPECT_GT(beyond_far, 0) << "the test scene must reach past the froxels' far sphere";
  EXPECT_GT(below_ground, 0) << "the test scene must look at the ground";
  EXPECT_GT(nonzero, 2 * active) << "a real volume, not zeros";
  for (int g = 0; g < 5; ++g) EXPECT_LT(worst[g], 1e-6) << names[g];
}

// The frustum transform, read back through the OpenVDB library, maps the index box's corners
// (-0.5 to W - 0.5, ...: the voxels' outer faces) to the corners of the frustum the camera's
// parameters imply (near plane at camera.near_m, far plane at the froxels' far distance, along
// the view axis), and each voxel center to the point at view depth near + (far - near) (k + 0.5) / S
// (S the file's frustum_slices) on the renderer's own ray through its froxel column's image point.
// Tolerances: 1e-9 of the distance from the camera for what the test computes from the
// same double parameters (OpenVDB's map rounds at ~1e-15; a voxel's width is 1e-2 or more of
// it); 1e-5 rad off the renderer's ray, whose matrices are float (~1e-6 rad; a voxel spans
// 0.13 rad here).
TEST_F(VdbExport, FrustumTransformPutsEachVoxelWhereTheCameraSawIt) {
  FroxelFrame frame = Capture();
  WriteVdb(dir_ / "f.vdb", MakeFrustumVolume(frame));
  VdbFileData file = ReadVdb(dir_ / "f.vdb");
  const VdbGridData* density = file.Find("density");
  ASSERT_NE(density, nullptr);
  EXPECT_FALSE(density->linear_transform);
  const FroxelGrid& grid = frame.texels.grid;
  const ExpectedFrustum expected(frame.camera, kTestSize.aspect());
  const double near = frame.camera.near_m, far = grid.far_m;
  const int64_t slices = Meta<int64_t>(file.metadata, "frustum_slices");

  double worst_corner = 0.0, worst_depth = 0.0, worst_angle = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    int x = corner & 1, y = (corner >> 1) & 1, z = (corner >> 2) & 1;
    auto world = density->IndexToWorld(x ? grid.width - 0.5 : -0.5, y ? grid.height - 0.5 : -0.5,
                                       z ? slices - 0.5 : -0.5);
    glm::dvec3 point = expected.Point(x, y, z ? far : near);
    worst_corner = std::max(worst_corner, glm::length(glm::dvec3(world[0], world[1], world[2]) - point) /
                                              glm::length(point - expected.position));
  }
  for (int k = 0; k < slices; ++k)
    for (int j = 0; j < grid.height; ++j)
      for (int i = 0; i < grid.width; ++i) {
        auto world = density->IndexToWorld(i, j, k);
        glm::dvec3 relative = glm::dvec3(world[0], world[1], world[2]) - expected.position;
        double view_depth = near + (far - near) * (k + 0.5) / slices;
        worst_depth = std::max(worst_depth, std::abs(glm::dot(relative, expected.forward) - view_depth) /
                                                glm::length(relative));
        glm::dvec3 ray = RendererRay(frame.uniforms, (i + 0.5) / grid.width, (j + 0.5) / grid.height);
        worst_angle = std::max(worst_angle, glm::length(glm::cross(glm::normalize(relative), ray)));
      }
  std::printf("frustum transform: worst relative corner error %.2e, view depth error %.2e, angle off "
              "the renderer's ray %.2e rad\n",
              worst_corner, worst_depth, worst_angle);
  EXPECT_LT(worst_corner, 1e-9);
  EXPECT_LT(worst_depth, 1e-9);
  EXPECT_LT(worst_angle, 1e-5);
}

// The density is the rate at which the renderer's transmittance falls: along each froxel's ray,
// the luma-weighted optical depth of its transmittance, 0.2126 (-ln T_R) + 0.7152 (-ln T_G) +
// 0.0722 (-ln T_B), equals the integral of the density from the camera (the luma is linear), here
// AirExtinction in 1024 steps along the renderer's own ray, over every froxel above the terrain.
// The froxels' transmittance is a ratio of two reads of the tabulated transmittance, so the two
// part by the tables' interpolation error: with these quarter-size tables, 0.31% at the median,
// 1.9% at the 90th percentile and 8.1% at worst (measured). The bounds leave 2.5-3x that.
// Leaving out the ozone fails them (measured: 18% at the 90th percentile); the unit or a channel
// would too. Mie scattering in place of Mie extinction would not (0.38% at the median: the haze is
// a small part of these rays' optical depth).
TEST_F(VdbExport, DensityIsTheRateTheTransmittanceFalls) {
  FroxelFrame frame = Capture();
  const AtmosphereParameters& air = tables().atmosphere();
  const FroxelGrid& grid = frame.texels.grid;
  const glm::dvec3 camera = frame.camera.position;
  std::vector<double> errors;
  for (int k = 0; k < grid.depth; ++k)
    for (int j = 0; j < grid.height; ++j)
      for (int i = 0; i < grid.width; ++i) {
        glm::dvec2 uv = frame.texels.axes.ScreenPosition({(i + 0.5) / grid.width, (j + 0.5) / grid.height});
        glm::dvec3 ray = RendererRay(frame.uniforms, uv.x, uv.y);
        double distance = grid.SliceDistance(k + 0.5);
        if (BelowTerrain(camera + ray * distance, air.bottom_radius_m)) continue;
        constexpr int kSteps = 1024;
        double depth = 0.0;
        for (int n = 0; n < kSteps; ++n) depth += AirExtinction(air, camera + ray * (distance * (n + 0.5) / kSteps));
        depth *= distance / kSteps;
        size_t texel = ((size_t(k) * grid.height + j) * grid.width + i) * 4;
        const float* t = &frame.texels.transmittance[texel];
        double from_transmittance = -(0.2126 * std::log(t[0]) + 0.7152 * std::log(t[1]) + 0.0722 * std::log(t[2]));
        errors.push_back(RelativeError(from_transmittance, depth));
      }
  ASSERT_GT(errors.size(), 100u);
  std::sort(errors.begin(), errors.end());
  double median = errors[errors.size() / 2], p90 = errors[errors.size() * 9 / 10], worst = errors.back();
  std::printf("optical depth from the transmittance against the integrated density over %zu froxels: "
              "median relative error %.2e, 90th percentile %.2e, worst %.2e\n",
              errors.size(), median, p90, worst);
  EXPECT_LT(median, 0.01);
  EXPECT_LT(p90, 0.05);
  EXPECT_LT(worst, 0.2);
}

// The viewer's V key writes the renderer's current froxels, as export-vdb would: the frustum
// volume of that frame, value for value, and the frame's own size in the metadata.
TEST_F(VdbExport, ViewerExportWritesTheCurrentFrame) {
  Scene scene = TestScene(tables());
  SceneRenderer renderer(SmallPublicTables(), scene,
                         {.width = kTestSize.width, .height = kTestSize.height, .froxels = TestGrid()});
  renderer.Render(scene);
  std::string message = viewer::ExportFroxelsToVdb(renderer, scene, dir_);
  std::vector<std::filesystem::path> written;
  for (const auto& entry : std::filesystem::directory_iterator(dir_)) written.push_back(entry.path());
  ASSERT_EQ(written.size(), 1u) << message;
  EXPECT_EQ(written[0].extension(), ".vdb");
  EXPECT_NE(message.find(written[0].string()), std::string::npos) << message;
  VdbFileData file = ReadVdb(written[0]);
  VdbVolume volume = MakeFrustumVolume(ReadFroxelFrame(ImplOf(renderer).renderer, scene));
  ASSERT_EQ(file.grids.size(), volume.grids.size());
  for (const VdbVolume::Grid& expected : volume.grids) {
    const VdbGridData* read = file.Find(expected.name);
    ASSERT_NE(read, nullptr) << expected.name;
    EXPECT_EQ(read->active_voxels, int64_t(volume.voxels.size())) << expected.name;
    int64_t mismatches = 0;
    for (size_t n = 0; n < volume.voxels.size(); ++n) {
      const auto& v = volume.voxels[n];
      int64_t offset = read->Offset(v[0], v[1], v[2]);
      ASSERT_GE(offset, 0);
      for (int c = 0; c < expected.components; ++c)
        mismatches += read->values[offset * expected.components + c] != expected.values[n * expected.components + c];
    }
    EXPECT_EQ(mismatches, 0) << expected.name;
  }
  EXPECT_EQ(file.metadata.at("camera_aspect"), VdbMetaValue(kTestSize.aspect()));
}

// --world-grid: a linear transform (voxel (i, j, k) at voxel * (i, j, k)), and each active voxel
// holds the froxels read at its center the way the shaders read them (ReadLikeTheShader, from the
// test's own projection of the center) and the air's extinction there (AirExtinction); a voxel
// is active exactly where its center lies inside the frustum
// and above the terrain. Tolerance 1e-6 relative: the file holds float32 of the export's double
// read of the same float texels, so the two differ by the order of the sums and a float rounding
// (6e-8), two for the luminance, which the export takes from the rounded channels.
TEST_F(VdbExport, WorldGridSamplesTheFroxelsAtEachVoxelCenterAboveTheGround) {
  FroxelFrame frame = Capture();
  const double voxel = 4000.0;
  WriteVdb(dir_ / "w.vdb", MakeWorldSpaceVolume(frame, voxel));
  VdbFileData file = ReadVdb(dir_ / "w.vdb");
  EXPECT_EQ(Meta<std::string>(file.metadata, "grid_space"), "world");
  EXPECT_EQ(Meta<double>(file.metadata, "world_voxel_size_m"), voxel);
  const char* names[5] = {"rayleigh_inscatter", "mie_inscatter", "transmittance", "inscatter_luminance", "density"};
  const VdbGridData* grids[5];
  for (int g = 0; g < 5; ++g) {
    grids[g] = file.Find(names[g]);
    ASSERT_NE(grids[g], nullptr) << names[g];
    EXPECT_EQ(grids[g]->grid_class, g == 4 ? "fog volume" : "unknown") << names[g];
    EXPECT_EQ(grids[g]->background[0], g == 2 ? 1.0f : 0.0f) << names[g];
  }
  const VdbGridData* transmittance = grids[2];
  ASSERT_TRUE(transmittance->linear_transform);
  EXPECT_EQ(transmittance->index_to_world,
            (std::array<double, 12>{voxel, 0, 0, 0, 0, voxel, 0, 0, 0, 0, voxel, 0}));
  EXPECT_GT(transmittance->active_voxels, 1000);
  for (const VdbGridData* grid : grids) {
    EXPECT_EQ(grid->active_voxels, transmittance->active_voxels) << grid->name;
    ASSERT_EQ(grid->min, transmittance->min) << grid->name;
    ASSERT_EQ(grid->max, transmittance->max) << grid->name;
  }

  // The screen position and distance of a world point, from the frame's view-projection.
  const auto& m = frame.uniforms.view_projection;
  glm::dvec3 camera(frame.uniforms.camera_scene_position[0], frame.uniforms.camera_scene_position[1],
                    frame.uniforms.camera_scene_position[2]);
  const double radius = tables().atmosphere().bottom_radius_m;
  int64_t active = 0, wrong_activity = 0, below_ground = 0;
  double worst[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
  for (int32_t z = transmittance->min[2] - 1; z <= transmittance->max[2] + 1; ++z)
    for (int32_t y = transmittance->min[1] - 1; y <= transmittance->max[1] + 1; ++y)
      for (int32_t x = transmittance->min[0] - 1; x <= transmittance->max[0] + 1; ++x) {
        auto world = transmittance->IndexToWorld(x, y, z);
        glm::dvec3 relative = glm::dvec3(world[0], world[1], world[2]) - camera;
        double clip[4] = {0, 0, 0, 0};
        for (int row = 0; row < 4; ++row)
          clip[row] = m[0 * 4 + row] * relative.x + m[1 * 4 + row] * relative.y +
                      m[2 * 4 + row] * relative.z + m[3 * 4 + row];
        double u = clip[0] / clip[3] * 0.5 + 0.5, v = clip[1] / clip[3] * 0.5 + 0.5;
        double distance = glm::length(relative);
        bool inside = clip[3] > 0 && u >= 0 && u <= 1 && v >= 0 && v <= 1 && distance <= frame.texels.grid.far_m;
        bool below = inside && BelowTerrain(glm::dvec3(world[0], world[1], world[2]), radius);
        below_ground += below;
        int64_t offset = transmittance->Offset(x, y, z);
        bool is_active = offset >= 0 && transmittance->active[offset];
        wrong_activity += is_active != (inside && !below);
        if (!is_active || !inside || below) continue;
        ++active;
        FroxelTexels::Sample expected = ReadLikeTheShader(frame.texels, u, v, distance);
        const glm::dvec3* values[3] = {&expected.rayleigh, &expected.mie, &expected.transmittance};
        for (int g = 0; g < 3; ++g)
          for (int c = 0; c < 3; ++c)
            worst[g] = std::max(worst[g], RelativeError(grids[g]->values[offset * 3 + c], (*values[g])[c]));
        glm::dvec3 inscatter = expected.rayleigh + expected.mie;  // Rec. 709 luma of the inscatter
        double luma = 0.2126 * inscatter.r + 0.7152 * inscatter.g + 0.0722 * inscatter.b;
        worst[3] = std::max(worst[3], RelativeError(grids[3]->values[offset], luma));
        double density = AirExtinction(tables().atmosphere(), glm::dvec3(world[0], world[1], world[2]));
        worst[4] = std::max(worst[4], RelativeError(grids[4]->values[offset], density));
      }
  std::printf("world grid: %" PRId64 " active voxels, %" PRId64 " in the frustum below the ground; worst "
              "relative error rayleigh %.2e, mie %.2e, transmittance %.2e, luminance %.2e, density %.2e\n",
              active, below_ground, worst[0], worst[1], worst[2], worst[3], worst[4]);
  EXPECT_EQ(wrong_activity, 0);
  EXPECT_EQ(active, transmittance->active_voxels);
  EXPECT_GT(below_ground, 0) << "the test scene must look at the ground";
  for (int g = 0; g < 5; ++g) EXPECT_LT(worst[g], 1e-6) << names[g];
}

// The CPU read mirrors the shader's: at a froxel center it returns that froxel's texel, and
// below the first slice it blends toward the empty segment.
TEST_F(VdbExport, CpuReadAtFroxelCentersGivesTheTexels) {
  FroxelFrame frame = Capture();
  const FroxelGrid& grid = frame.texels.grid;
  for (int k : {0, 5, grid.depth - 1})
    for (int j : {0, 3, grid.height - 1})
      for (int i : {0, 7, grid.width - 1}) {
        glm::dvec2 uv = frame.texels.axes.ScreenPosition({(i + 0.5) / grid.width, (j + 0.5) / grid.height});
        FroxelTexels::Sample sample = frame.texels.Read(uv, grid.SliceDistance(k + 0.5));
        size_t texel = ((size_t(k) * grid.height + j) * grid.width + i) * 4;
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(sample.rayleigh[c], frame.texels.rayleigh[texel + c],
                      1e-6 * std::abs(frame.texels.rayleigh[texel + c]) + 1e-12);
          EXPECT_NEAR(sample.transmittance[c], frame.texels.transmittance[texel + c], 1e-6);
        }
      }
  FroxelTexels::Sample at_camera = frame.texels.Read(glm::dvec2(0.5, 0.5), 0.0);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(at_camera.rayleigh[c], 0.0);
    EXPECT_EQ(at_camera.transmittance[c], 1.0);
  }
}

// What the file says about the frame reads back unchanged, on the file and on each grid.
TEST_F(VdbExport, MetadataRoundTrips) {
  FroxelFrame frame = Capture();
  VdbVolume volume = MakeFrustumVolume(frame);
  WriteVdb(dir_ / "f.vdb", volume);
  VdbFileData file = ReadVdb(dir_ / "f.vdb");
  for (const auto& [key, value] : volume.file_metadata) {
    auto it = file.metadata.find(key);
    ASSERT_NE(it, file.metadata.end()) << key;
    EXPECT_TRUE(it->second == value) << key;
  }
  for (const VdbVolume::Grid& written : volume.grids) {
    const VdbGridData* read = file.Find(written.name);
    ASSERT_NE(read, nullptr) << written.name;
    const VdbMetadata* maps[] = {&volume.grid_metadata, &written.metadata};
    for (const VdbMetadata* map : maps)
      for (const auto& [key, value] : *map) {
        auto it = read->metadata.find(key);
        ASSERT_NE(it, read->metadata.end()) << written.name << " " << key;
        EXPECT_TRUE(it->second == value) << written.name << " " << key;
      }
  }
  // And it says what it should.
  const VdbMetadata& meta = file.metadata;
  Scene scene = TestScene(tables());
  std::array<double, 3> position = Meta<std::array<double, 3>>(meta, "camera_position_m");
  EXPECT_EQ(position, (std::array<double, 3>{1234.0, -567.0, 350.0}));
  EXPECT_EQ(Meta<double>(meta, "camera_yaw_deg"), 35.0);
  EXPECT_EQ(Meta<double>(meta, "camera_pitch_deg"), 8.0);
  EXPECT_EQ(Meta<double>(meta, "camera_vertical_fov_deg"), scene.camera.vertical_fov_deg);
  EXPECT_EQ(Meta<double>(meta, "camera_near_m"), scene.camera.near_m);
  EXPECT_EQ(Meta<double>(meta, "camera_far_m"), 128e3);
  glm::dvec3 sun = scene.sun.Direction();
  using Double3 = std::array<double, 3>;
  EXPECT_EQ(Meta<Double3>(meta, "sun_direction"), (Double3{sun.x, sun.y, sun.z}));
  EXPECT_EQ(Meta<std::string>(meta, "lut"), "4d");
  EXPECT_EQ(Meta<std::string>(meta, "units"), "meters");
  EXPECT_EQ(Meta<std::string>(meta, "aerial_version"), AERIAL_VERSION);
  EXPECT_EQ(Meta<std::string>(meta, "grid_space"), "frustum");
  EXPECT_EQ(Meta<double>(meta, "frustum_near_m"), scene.camera.near_m);
  EXPECT_EQ(Meta<double>(meta, "frustum_far_m"), 128e3);
  EXPECT_EQ(Meta<std::string>(meta, "ground"), "terrain");
  EXPECT_EQ(Meta<std::string>(meta, "froxel_depth_distribution"), "quadratic");
  EXPECT_EQ(Meta<double>(meta, "froxel_far_m"), 128e3);
  // The rows gather at the horizon, 8 degrees of pitch and the dip of the horizon seen from 350 m
  // below the view axis; the ground there is near, the spread the default. 1e-4: 1.35 km from the
  // scene's origin the local vertical leans 2e-4 rad off the scene's z, which moves this view's
  // row by 4.4e-5; leaving out the dip (0.6 degrees) would move it by 1.1e-2.
  const double R = tables().atmosphere().bottom_radius_m, dip = std::acos(R / (R + 350.0));
  const double tan_half_fov = std::tan(scene.camera.vertical_fov_deg * M_PI / 360.0);
  EXPECT_NEAR(Meta<double>(meta, "froxel_row_focus"), 0.5 + std::tan(8.0 * M_PI / 180.0 + dip) / (2.0 * tan_half_fov),
              1e-4);
  EXPECT_NEAR(Meta<double>(meta, "froxel_row_spread"), kFroxelRowSpread, 1e-8);
  // The sun (azimuth 160 degrees) is 125 degrees from the view (yaw 35), behind the camera: the
  // columns are near even, a focus at the centre and a spread of screens (FroxelAxis's tests hold
  // what that spread does).
  EXPECT_EQ(Meta<double>(meta, "froxel_column_focus"), 0.5);
  EXPECT_GT(Meta<double>(meta, "froxel_column_spread"), 4.0);
  using Int3 = std::array<int32_t, 3>;
  EXPECT_EQ(Meta<Int3>(meta, "froxel_resolution"), (Int3{16, 8, 12}));
  EXPECT_EQ(Meta<std::string>(meta, "atmosphere_hash"), Hex(AtmosphereParameters::Earth().Hash()));
  // rgb tables: the channels are the atmosphere's wavelengths.
  EXPECT_EQ(Meta<std::string>(meta, "colour"), "rgb");
  EXPECT_EQ(Meta<std::string>(meta, "channels"), "the values at wavelengths_nm, in order");
  EXPECT_EQ(Meta<Double3>(meta, "wavelengths_nm"), (Double3{680.0, 550.0, 440.0}));
  EXPECT_EQ(meta.count("spectral_wavelengths_nm"), 0u);
}

// Spectral tables' channels are linear sRGB, not wavelengths: the file says so, lists the
// spectral sampling it was converted from, and has no `wavelengths_nm` that a reader could take
// for the channels' (nor does any grid's description point at one).
TEST_F(VdbExport, SpectralChannelsAreNamedLinearSrgb) {
  PrecomputeOptions options = PrecomputeOptions::Small();
  options.orders = 1;
  options.close_series = false;
  options.colour = ColourMode::kSpectral;
  const AtmosphereTables& spectral = CachedTables(options);
  VdbVolume volume = MakeFrustumVolume(CaptureFroxels(spectral, TestScene(spectral), TestGrid(), kTestSize));
  WriteVdb(dir_ / "s.vdb", volume);
  VdbFileData file = ReadVdb(dir_ / "s.vdb");
  EXPECT_EQ(Meta<std::string>(file.metadata, "colour"), "spectral");
  EXPECT_EQ(Meta<std::string>(file.metadata, "channels").rfind("linear sRGB (Rec. 709 primaries, D65 white)", 0), 0u);
  EXPECT_EQ(file.metadata.count("wavelengths_nm"), 0u);
  std::string sampling = Meta<std::string>(file.metadata, "spectral_wavelengths_nm");
  EXPECT_EQ(std::count(sampling.begin(), sampling.end(), ','), options.spectral_wavelengths - 1) << sampling;
  EXPECT_EQ(sampling.substr(0, sampling.find(',')), "407.708333") << sampling;  // 395 nm + half a 25.42 nm bin
  for (const char* name : {"rayleigh_inscatter", "mie_inscatter", "transmittance"}) {
    const VdbGridData* grid = file.Find(name);
    ASSERT_NE(grid, nullptr) << name;
    EXPECT_EQ(Meta<std::string>(grid->metadata, "description").find("wavelengths_nm"), std::string::npos) << name;
    EXPECT_EQ(Meta<std::string>(grid->metadata, "colour"), "spectral") << name;
  }
}

// Debian's python3-openvdb, a reader that shares no code with aerial, on a frustum file and a
// world file, each voxel where the binding's own transform puts it: `density` is a float fog
// volume, background 0, positive at every active voxel below the atmosphere's top and 0 above it;
// `transmittance` has background 1; the frustum file's transform is OpenVDB's frustum map and
// takes the index box's corners to the corners of the frustum the camera's parameters imply (1e-9
// of the distance: both sides compute in double from the same parameters, see
// FrustumTransformPutsEachVoxelWhereTheCameraSawIt); no active voxel of either file lies below
// the terrain.
TEST_F(VdbExport, DebiansPythonOpenVdbSeesFogVolumesInPlace) {
  if (std::system("/usr/bin/python3 -c 'import pyopenvdb' 2>/dev/null") != 0)
    GTEST_SKIP() << "/usr/bin/python3 has no pyopenvdb (Debian's python3-openvdb, in tools/setup.sh)";
  FroxelFrame frame = Capture();
  VdbVolume frustum_volume = MakeFrustumVolume(frame);
  WriteVdb(dir_ / "f.vdb", frustum_volume);
  WriteVdb(dir_ / "w.vdb", MakeWorldSpaceVolume(frame, 4000.0));
  std::ofstream(dir_ / "read.py") << R"(
import json, sys, pyopenvdb as vdb
def describe(path):
    grids, metadata = vdb.readAll(path)
    out = {"grids": {}, "metadata_keys": sorted(metadata.keys())}
    for g in grids:
        background = g.background
        out["grids"][g.name] = {"type": g.valueTypeName, "class": g.gridClass, "active": g.activeVoxelCount(),
                                "background": list(background) if isinstance(background, tuple) else [background],
                                "map": g.transform.typeName, "linear": g.transform.isLinear}
    density = [g for g in grids if g.name == "density"][0]
    out["density_voxels"] = [list(density.transform.indexToWorld(item.min)) + [item.value]
                             for item in density.citerOnValues()]
    return out, density.transform
frustum, transform = describe(sys.argv[1])
w, h, d = [int(n) for n in sys.argv[3:6]]
frustum["corners"] = [list(transform.indexToWorld((-0.5 + x * w, -0.5 + y * h, -0.5 + z * d)))
                      for z in (0, 1) for y in (0, 1) for x in (0, 1)]
world, _ = describe(sys.argv[2])
print(json.dumps({"frustum": frustum, "world": world}))
)";
  const FroxelGrid& grid = frame.texels.grid;
  std::string command = "/usr/bin/python3 " + (dir_ / "read.py").string() + " " + (dir_ / "f.vdb").string() + " " +
                        (dir_ / "w.vdb").string() + " " + std::to_string(grid.width) + " " +
                        std::to_string(grid.height) + " " +
                        std::to_string(std::get<int64_t>(frustum_volume.file_metadata.at("frustum_slices"))) + " > " +
                        (dir_ / "out.json").string();
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::ifstream in(dir_ / "out.json");
  nlohmann::json json = nlohmann::json::parse(in);

  const AtmosphereParameters& air = tables().atmosphere();
  for (const char* file : {"frustum", "world"}) {
    const auto& grids = json[file]["grids"];
    for (const char* name : {"rayleigh_inscatter", "mie_inscatter", "transmittance", "inscatter_luminance", "density"})
      ASSERT_TRUE(grids.contains(name)) << file << " " << name;
    EXPECT_EQ(grids["density"]["type"], "float") << file;
    EXPECT_EQ(grids["density"]["class"], "fog volume") << file;
    EXPECT_EQ(grids["density"]["background"], (std::vector<double>{0.0})) << file;
    EXPECT_EQ(grids["transmittance"]["type"], "vec3s") << file;
    EXPECT_EQ(grids["transmittance"]["background"], (std::vector<double>{1.0, 1.0, 1.0})) << file;
    EXPECT_EQ(grids["rayleigh_inscatter"]["class"], "unknown") << file;
    auto keys = json[file]["metadata_keys"].get<std::vector<std::string>>();
    for (const char* key : {"camera_position_m", "sun_direction", "lut", "atmosphere_hash", "units", "ground"})
      EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << file << " " << key;

    const auto& voxels = json[file]["density_voxels"];
    EXPECT_EQ(int64_t(voxels.size()), grids["density"]["active"].get<int64_t>()) << file;
    EXPECT_GT(voxels.size(), 500u) << file;
    int64_t in_air = 0, wrong_density = 0, below = 0;
    double lowest = 1e30;
    for (const auto& voxel : voxels) {
      glm::dvec3 point(voxel[0].get<double>(), voxel[1].get<double>(), voxel[2].get<double>());
      double value = voxel[3].get<double>();
      double altitude = glm::length(point - glm::dvec3(0.0, 0.0, -air.bottom_radius_m)) - air.bottom_radius_m;
      bool air_there = altitude <= air.top_radius_m - air.bottom_radius_m;
      in_air += air_there;
      wrong_density += air_there ? !(value > 0.0) : value != 0.0;
      below += BelowTerrain(point, air.bottom_radius_m);
      lowest = std::min(lowest, HeightAboveTerrainM(point, air.bottom_radius_m));
    }
    std::printf("pyopenvdb, %s file: %zu active voxels, %" PRId64 " below the atmosphere's top; lowest "
                "%.0f m above the terrain\n",
                file, voxels.size(), in_air, lowest);
    EXPECT_GT(in_air, 500) << file;
    EXPECT_EQ(wrong_density, 0) << file;
    EXPECT_EQ(below, 0) << file;
  }

  const auto& frustum = json["frustum"]["grids"]["density"];
  EXPECT_EQ(frustum["map"], "NonlinearFrustumMap");
  EXPECT_FALSE(frustum["linear"].get<bool>());
  EXPECT_TRUE(json["world"]["grids"]["density"]["linear"].get<bool>());
  const ExpectedFrustum expected(frame.camera, kTestSize.aspect());
  ASSERT_EQ(json["frustum"]["corners"].size(), 8u);
  double worst_corner = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    auto read = json["frustum"]["corners"][corner].get<std::vector<double>>();
    int x = corner & 1, y = (corner >> 1) & 1, z = (corner >> 2) & 1;
    glm::dvec3 point = expected.Point(x, y, z ? grid.far_m : frame.camera.near_m);
    worst_corner = std::max(worst_corner, glm::length(glm::dvec3(read[0], read[1], read[2]) - point) /
                                              glm::length(point - expected.position));
  }
  std::printf("pyopenvdb: frustum corners within %.2e of their distance from the camera\n", worst_corner);
  EXPECT_LT(worst_corner, 1e-9);
}

class VdbPaths : public ScratchDirTest {};

TEST_F(VdbPaths, UnwritableOrWrongPathsFailBeforeAnyWork) {
  EXPECT_THROW(CheckVdbOutputPath("/nonexistent-aerial-dir/x.vdb"), Error);
  EXPECT_FALSE(std::filesystem::exists("/nonexistent-aerial-dir"));
  try {
    CheckVdbOutputPath(dir_ / "x.exr");
    FAIL() << "a .exr name was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "VDB path");
  }
  CheckVdbOutputPath(dir_ / "x.VDB");  // the extension in any case
  EXPECT_TRUE(Entries().empty()) << "the check leaves no probe file";
}

// A write that fails (the parent is a regular file) throws naming the path and leaves neither the
// file nor a temporary.
TEST_F(VdbPaths, FailedWriteLeavesNoFile) {
  std::ofstream(dir_ / "blocker") << "a file, not a directory";
  VdbVolume volume;
  volume.voxels = {{0, 0, 0}};
  volume.grids = {{.name = "density", .components = 1, .values = {1.0f}}};
  try {
    WriteVdb(dir_ / "blocker" / "x.vdb", volume);
    FAIL() << "wrote under a regular file";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("blocker"), std::string::npos) << e.what();
  }
  EXPECT_EQ(Entries(), std::vector<std::string>{"blocker"});
  // And a good write leaves exactly the file.
  WriteVdb(dir_ / "ok.vdb", volume);
  EXPECT_EQ(Entries(), (std::vector<std::string>{"blocker", "ok.vdb"}));
  VdbFileData read = ReadVdb(dir_ / "ok.vdb");
  ASSERT_EQ(read.grids.size(), 1u);
  EXPECT_EQ(read.grids[0].active_voxels, 1);
}

// A voxel equal to the background (0) is still written: the froxel grids stay dense.
TEST_F(VdbPaths, ZeroValuedVoxelsStayActive) {
  VdbVolume volume;
  for (int i = 0; i < 4; ++i) volume.voxels.push_back({i, 0, 0});
  volume.grids = {{.name = "zeros", .components = 3, .values = std::vector<float>(12, 0.0f)}};
  WriteVdb(dir_ / "z.vdb", volume);
  VdbFileData read = ReadVdb(dir_ / "z.vdb");
  ASSERT_EQ(read.grids.size(), 1u);
  EXPECT_EQ(read.grids[0].active_voxels, 4);
}

// The frustum grid needs its near plane in front of the froxels' far distance (OpenVDB's
// frustum has taper near / far in (0, 1)); the error names the scene file's key.
TEST_F(VdbPaths, FrustumNeedsTheNearPlaneBeforeTheFarOne) {
  Camera camera;
  camera.near_m = 1000.0;
  FroxelGrid grid;
  grid.far_m = 500.0;
  try {
    CameraFrustum frustum(camera, 16.0 / 9.0, grid);
    FAIL() << "a near plane beyond far was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "camera.near_m");
    EXPECT_EQ(e.value(), "1000");
  }
  grid.far_m = 2000.0;
  EXPECT_NO_THROW(CameraFrustum(camera, 16.0 / 9.0, grid));
}

// A frustum transform OpenVDB cannot build is refused before anything is written, with the
// field named: a taper outside (0, 1], a singular second map.
TEST_F(VdbPaths, BadFrustumTransformsWriteNothing) {
  VdbVolume volume;
  volume.voxels = {{0, 0, 0}};
  volume.grids = {{.name = "density", .components = 1, .values = {1.0f}}};
  volume.frustum = VdbFrustum{.index_min = {-0.5, -0.5, -0.5}, .index_max = {1.5, 1.5, 1.5}, .taper = 0.0};
  try {
    WriteVdb(dir_ / "x.vdb", volume);
    FAIL() << "taper 0 was written";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "VDB frustum taper");
  }
  volume.frustum->taper = 0.5;  // the second map is still all zeros
  EXPECT_THROW(WriteVdb(dir_ / "x.vdb", volume), Error);
  EXPECT_TRUE(Entries().empty());
}

}  // namespace
}  // namespace aerial::testing
