// `aerial export-vdb`: the froxel volume of one frame, written to OpenVDB and read back, holds
// exactly what the GPU computed; every froxel sits where the renderer puts it; the metadata
// survives; Debian's own OpenVDB Python binding reads the file; bad paths leave nothing behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "aerial/error.h"
#include "aerial/export/froxel_export.h"
#include "aerial/image/scratch_dir_test_util.h"
#include "aerial/api/impl.h"
#include "aerial/render/renderer.h"
#include "aerial/scene.h"
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

// The renderer's own placement of froxel (i, j, k), computed here from the frame block as
// shaders/frame/froxel.comp and shaders/include/frame.glsl do (ViewRayFromScreen,
// FroxelSliceDistance), independently of froxel_placement.cpp.
glm::dvec3 RendererFroxelPosition(const FrameUniforms& frame, int i, int j, int k) {
  const auto& m = frame.inverse_view_projection;
  int w = frame.froxel_size[0], h = frame.froxel_size[1], d = frame.froxel_size[2];
  double clip[4] = {2.0 * (i + 0.5) / w - 1.0, 2.0 * (j + 0.5) / h - 1.0, 0.5, 1.0};
  double world[4] = {0, 0, 0, 0};
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) world[row] += m[column * 4 + row] * clip[column];
  glm::dvec3 ray = glm::normalize(glm::dvec3(world[0], world[1], world[2]) / world[3]);
  double s = (k + 0.5) / d;
  double distance = frame.froxel_depth[0] * s * s;
  glm::dvec3 camera(frame.camera_scene_position[0], frame.camera_scene_position[1],
                    frame.camera_scene_position[2]);
  return camera + ray * distance;
}

// The shaders' read of the froxels at screen position (u, v) and a distance (SampleFroxels in
// shaders/include/froxel.glsl), written here from the GLSL and Vulkan's linear filtering with
// clamp-to-edge addressing, independently of FroxelTexels::Read (froxel_placement.cpp), which the
// world grid calls: texture coordinate (u, v, sqrt(distance / far)) times the size, less half a
// texel, weighs the two nearest texels on each axis, their indices clamped to the edge; below the
// first slice center, d_0 = far (0.5 / D)^2, the values blend toward the empty segment.
FroxelTexels::Sample ReadLikeTheShader(const FroxelTexels& texels, double u, double v, double distance) {
  const FroxelGrid& grid = texels.grid;
  const int size[3] = {grid.width, grid.height, grid.depth};
  const double coordinate[3] = {u * size[0] - 0.5, v * size[1] - 0.5,
                                std::sqrt(distance / grid.far_m) * size[2] - 0.5};
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
  double first = grid.far_m * (0.5 / grid.depth) * (0.5 / grid.depth);
  if (distance < first) {
    double t = distance / first;
    sample.rayleigh *= t;
    sample.mie *= t;
    sample.transmittance = 1.0 + (sample.transmittance - 1.0) * t;
  }
  return sample;
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

// Every value of the three froxel grids, read back through the OpenVDB library, equals the GPU
// volume bit for bit; the grids are dense W x H x D boxes at index (0, 0, 0).
TEST_F(VdbExport, RoundTripHoldsTheGpuVolumeExactly) {
  Scene scene = TestScene(tables());
  FroxelGrid grid = TestGrid();
  // The GPU volume as the test reads it from a renderer of its own, at the capture's size.
  Renderer renderer(tables(), scene, {.width = kTestSize.width, .height = kTestSize.height, .froxels = grid});
  renderer.Render(scene);
  const FroxelVolume& froxels = renderer.froxels();
  std::vector<float> gpu[3] = {vk::ReadImageFloats(tables().context(), froxels.rayleigh()),
                               vk::ReadImageFloats(tables().context(), froxels.mie()),
                               vk::ReadImageFloats(tables().context(), froxels.transmittance())};

  FroxelFrame frame = CaptureFroxels(tables(), scene, grid, kTestSize);
  WriteVdb(dir_ / "f.vdb", MakeFroxelSpaceVolume(frame));
  VdbFileData file = ReadVdb(dir_ / "f.vdb");

  const char* names[3] = {"rayleigh_inscatter", "mie_inscatter", "transmittance"};
  const int64_t count = int64_t(grid.width) * grid.height * grid.depth;
  for (int g = 0; g < 3; ++g) {
    const VdbGridData* data = file.Find(names[g]);
    ASSERT_NE(data, nullptr) << names[g];
    EXPECT_EQ(data->type, "vec3s");
    EXPECT_EQ(data->active_voxels, count) << names[g];
    EXPECT_EQ(data->min, (std::array<int32_t, 3>{0, 0, 0}));
    EXPECT_EQ(data->max, (std::array<int32_t, 3>{grid.width - 1, grid.height - 1, grid.depth - 1}));
    int64_t mismatches = 0, nonzero = 0;
    for (int k = 0; k < grid.depth; ++k)
      for (int j = 0; j < grid.height; ++j)
        for (int i = 0; i < grid.width; ++i) {
          size_t texel = ((size_t(k) * grid.height + j) * grid.width + i) * 4;
          int64_t offset = data->Offset(i, j, k);
          for (int c = 0; c < 3; ++c) {
            float read = data->values[offset * 3 + c];
            mismatches += std::memcmp(&read, &gpu[g][texel + c], sizeof(float)) != 0;
            nonzero += read != 0.0f;
          }
        }
    EXPECT_EQ(mismatches, 0) << names[g];
    EXPECT_GT(nonzero, count) << names[g] << ": a real volume, not zeros";
  }
  const VdbGridData* luminance = file.Find("inscatter_luminance");
  ASSERT_NE(luminance, nullptr);
  EXPECT_EQ(luminance->type, "float");
  EXPECT_EQ(luminance->active_voxels, count);
  for (int64_t n = 0; n < count; ++n) {
    float expected = float(InscatterLuminance(&gpu[0][n * 4], &gpu[1][n * 4]));
    ASSERT_EQ(luminance->values[n], expected) << "voxel " << n;
  }
}

// The viewer's V key writes the renderer's current froxels, as export-vdb would: same values,
// and the frame's own size in the metadata.
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
  const VdbGridData* rayleigh = file.Find("rayleigh_inscatter");
  ASSERT_NE(rayleigh, nullptr);
  std::vector<float> gpu = vk::ReadImageFloats(tables().context(), renderer.impl().renderer.froxels().rayleigh());
  FroxelGrid grid = TestGrid();
  EXPECT_EQ(rayleigh->values[3 * rayleigh->Offset(0, 0, 0)], gpu[0]);
  EXPECT_EQ(rayleigh->values[3 * rayleigh->Offset(grid.width - 1, grid.height - 1, grid.depth - 1)],
            gpu[gpu.size() - 4]);
  EXPECT_EQ(file.metadata.at("camera_aspect"), VdbMetaValue(kTestSize.aspect()));
}

// Every froxel center, as the file places it, is where the renderer puts it (1e-4 of its
// distance from the camera): by the froxel_position grid, and by the camera and slice metadata
// alone (what a DCC user's script would use).
TEST_F(VdbExport, EveryFroxelSitsAtTheRenderersWorldPosition) {
  FroxelFrame frame = Capture();
  WriteVdb(dir_ / "f.vdb", MakeFroxelSpaceVolume(frame));
  VdbFileData file = ReadVdb(dir_ / "f.vdb");
  const VdbGridData* position = file.Find("froxel_position");
  ASSERT_NE(position, nullptr);
  const VdbMetadata& meta = position->metadata;
  auto camera = Meta<std::array<double, 3>>(meta, "camera_position_m");
  auto forward = Meta<std::array<double, 3>>(meta, "camera_forward");
  auto up = Meta<std::array<double, 3>>(meta, "camera_up");
  auto right = Meta<std::array<double, 3>>(meta, "camera_right");
  double tan_half = std::tan(Meta<double>(meta, "camera_vertical_fov_deg") * M_PI / 360.0);
  double aspect = Meta<double>(meta, "camera_aspect");
  std::vector<double> slices;
  std::stringstream list(Meta<std::string>(meta, "froxel_slice_distance_m"));
  for (std::string item; std::getline(list, item, ',');) slices.push_back(std::stod(item));
  FroxelGrid grid = TestGrid();
  ASSERT_EQ(slices.size(), size_t(grid.depth));

  double worst_grid = 0.0, worst_metadata = 0.0;
  for (int k = 0; k < grid.depth; ++k)
    for (int j = 0; j < grid.height; ++j)
      for (int i = 0; i < grid.width; ++i) {
        glm::dvec3 expected = RendererFroxelPosition(frame.uniforms, i, j, k);
        double distance = glm::length(expected - glm::dvec3(camera[0], camera[1], camera[2]));
        int64_t offset = position->Offset(i, j, k);
        ASSERT_GE(offset, 0);
        glm::dvec3 stored(position->values[offset * 3], position->values[offset * 3 + 1],
                          position->values[offset * 3 + 2]);
        worst_grid = std::max(worst_grid, glm::length(stored - expected) / distance);
        // From the metadata: image point (u, v), v down, on the plane one unit ahead.
        double x = (2.0 * (i + 0.5) / grid.width - 1.0) * tan_half * aspect;
        double y = (1.0 - 2.0 * (j + 0.5) / grid.height) * tan_half;
        glm::dvec3 ray = glm::normalize(glm::dvec3(forward[0], forward[1], forward[2]) +
                                        x * glm::dvec3(right[0], right[1], right[2]) +
                                        y * glm::dvec3(up[0], up[1], up[2]));
        glm::dvec3 from_metadata = glm::dvec3(camera[0], camera[1], camera[2]) + ray * slices[k];
        worst_metadata = std::max(worst_metadata, glm::length(from_metadata - expected) / distance);
      }
  std::printf("worst relative placement error: froxel_position %.2e, metadata %.2e\n", worst_grid,
              worst_metadata);
  EXPECT_LT(worst_grid, 1e-4);
  EXPECT_LT(worst_metadata, 1e-4);
  // The froxel grids' transform is the identity: index space is froxel space.
  const VdbGridData* rayleigh = file.Find("rayleigh_inscatter");
  ASSERT_NE(rayleigh, nullptr);
  EXPECT_TRUE(rayleigh->linear_transform);
  EXPECT_EQ(rayleigh->index_to_world, (std::array<double, 12>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}));
}

// --world-grid: a linear transform (voxel (i, j, k) at voxel * (i, j, k)), and each active voxel
// holds the froxels read at its center the way the shaders read them (ReadLikeTheShader, from the
// test's own projection of the center); inside the frustum every voxel is active, outside none.
// Tolerance 1e-6 relative: the file holds float32 of the export's double read of the same float
// texels, so the two differ by the order of the sums and a float rounding (6e-8), two for the
// luminance, which the export takes from the rounded channels.
TEST_F(VdbExport, WorldGridSamplesTheFroxelsAtEachVoxelCenter) {
  FroxelFrame frame = Capture();
  const double voxel = 4000.0;
  WriteVdb(dir_ / "w.vdb", MakeWorldSpaceVolume(frame, voxel));
  VdbFileData file = ReadVdb(dir_ / "w.vdb");
  EXPECT_EQ(Meta<std::string>(file.metadata, "grid_space"), "world");
  EXPECT_EQ(Meta<double>(file.metadata, "world_voxel_size_m"), voxel);
  const VdbGridData* grids[3] = {file.Find("rayleigh_inscatter"), file.Find("mie_inscatter"),
                                 file.Find("transmittance")};
  const VdbGridData* luminance = file.Find("inscatter_luminance");
  ASSERT_TRUE(grids[0] && grids[1] && grids[2] && luminance);
  const VdbGridData* transmittance = grids[2];
  ASSERT_TRUE(transmittance->linear_transform);
  EXPECT_EQ(transmittance->index_to_world,
            (std::array<double, 12>{voxel, 0, 0, 0, 0, voxel, 0, 0, 0, 0, voxel, 0}));
  EXPECT_GT(transmittance->active_voxels, 1000);
  for (const VdbGridData* grid : {grids[0], grids[1], luminance}) {
    EXPECT_EQ(grid->active_voxels, transmittance->active_voxels) << grid->name;
    ASSERT_EQ(grid->min, transmittance->min) << grid->name;
    ASSERT_EQ(grid->max, transmittance->max) << grid->name;
  }

  // The screen position and distance of a world point, from the frame's view-projection.
  const auto& m = frame.uniforms.view_projection;
  glm::dvec3 camera(frame.uniforms.camera_scene_position[0], frame.uniforms.camera_scene_position[1],
                    frame.uniforms.camera_scene_position[2]);
  int64_t active = 0, wrong_activity = 0;
  double worst[4] = {0.0, 0.0, 0.0, 0.0};  // rayleigh, mie, transmittance, luminance
  auto relative_error = [](double read, double expected) {
    return std::abs(read - expected) / std::max(std::abs(expected), 1e-30);
  };
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
        int64_t offset = transmittance->Offset(x, y, z);
        bool is_active = offset >= 0 && transmittance->active[offset];
        wrong_activity += inside != is_active;
        if (!is_active || !inside) continue;
        ++active;
        FroxelTexels::Sample expected = ReadLikeTheShader(frame.texels, u, v, distance);
        const glm::dvec3* values[3] = {&expected.rayleigh, &expected.mie, &expected.transmittance};
        for (int g = 0; g < 3; ++g)
          for (int c = 0; c < 3; ++c)
            worst[g] = std::max(worst[g], relative_error(grids[g]->values[offset * 3 + c], (*values[g])[c]));
        glm::dvec3 inscatter = expected.rayleigh + expected.mie;  // Rec. 709 luma of the inscatter
        double luma = 0.2126 * inscatter.r + 0.7152 * inscatter.g + 0.0722 * inscatter.b;
        worst[3] = std::max(worst[3], relative_error(luminance->values[offset], luma));
      }
  std::printf("world grid: %" PRId64 " active voxels; worst relative error rayleigh %.2e, mie %.2e, "
              "transmittance %.2e, luminance %.2e\n",
              active, worst[0], worst[1], worst[2], worst[3]);
  EXPECT_EQ(wrong_activity, 0);
  EXPECT_EQ(active, transmittance->active_voxels);
  const char* names[4] = {"rayleigh", "mie", "transmittance", "luminance"};
  for (int g = 0; g < 4; ++g) EXPECT_LT(worst[g], 1e-6) << names[g];
}

// The CPU read mirrors the shader's: at a froxel center it returns that froxel's texel, and
// below the first slice it blends toward the empty segment.
TEST_F(VdbExport, CpuReadAtFroxelCentersGivesTheTexels) {
  FroxelFrame frame = Capture();
  const FroxelGrid& grid = frame.texels.grid;
  for (int k : {0, 5, grid.depth - 1})
    for (int j : {0, 3, grid.height - 1})
      for (int i : {0, 7, grid.width - 1}) {
        glm::dvec2 uv((i + 0.5) / grid.width, (j + 0.5) / grid.height);
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
  VdbVolume volume = MakeFroxelSpaceVolume(frame);
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
  EXPECT_EQ(Meta<std::string>(meta, "grid_space"), "froxel");
  EXPECT_EQ(Meta<std::string>(meta, "froxel_depth_distribution"), "quadratic");
  EXPECT_EQ(Meta<double>(meta, "froxel_far_m"), 128e3);
  using Int3 = std::array<int32_t, 3>;
  EXPECT_EQ(Meta<Int3>(meta, "froxel_resolution"), (Int3{16, 8, 12}));
  EXPECT_EQ(Meta<std::string>(meta, "atmosphere_hash"), Hex(AtmosphereParameters::Earth().Hash()));
}

// Debian's python3-openvdb, a reader that shares no code with aerial, finds the grids, their
// W x H x D boxes, and a value where aerial put it.
TEST_F(VdbExport, DebiansPythonOpenVdbReadsTheFile) {
  if (std::system("/usr/bin/python3 -c 'import pyopenvdb' 2>/dev/null") != 0)
    GTEST_SKIP() << "/usr/bin/python3 has no pyopenvdb (Debian's python3-openvdb)";
  FroxelFrame frame = Capture();
  WriteVdb(dir_ / "f.vdb", MakeFroxelSpaceVolume(frame));
  std::ofstream(dir_ / "read.py") << R"(
import json, sys, pyopenvdb as vdb
grids, metadata = vdb.readAll(sys.argv[1])
out = {"grids": {}, "metadata_keys": sorted(metadata.keys())}
for g in grids:
    lo, hi = g.evalActiveVoxelBoundingBox()
    out["grids"][g.name] = {"type": g.valueTypeName, "active": g.activeVoxelCount(),
                            "min": list(lo), "max": list(hi)}
rayleigh = [g for g in grids if g.name == "rayleigh_inscatter"][0]
out["rayleigh_3_2_5"] = list(rayleigh.getConstAccessor().getValue((3, 2, 5)))
print(json.dumps(out))
)";
  std::string command = "/usr/bin/python3 " + (dir_ / "read.py").string() + " " + (dir_ / "f.vdb").string() +
                        " > " + (dir_ / "out.json").string();
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::ifstream in(dir_ / "out.json");
  nlohmann::json json = nlohmann::json::parse(in);
  FroxelGrid grid = TestGrid();
  for (const char* name : {"rayleigh_inscatter", "mie_inscatter", "transmittance", "inscatter_luminance",
                           "froxel_position"}) {
    ASSERT_TRUE(json["grids"].contains(name)) << name;
    const auto& g = json["grids"][name];
    EXPECT_EQ(g["active"], grid.width * grid.height * grid.depth) << name;
    EXPECT_EQ(g["min"], (std::vector<int>{0, 0, 0})) << name;
    EXPECT_EQ(g["max"], (std::vector<int>{grid.width - 1, grid.height - 1, grid.depth - 1})) << name;
  }
  EXPECT_EQ(json["grids"]["rayleigh_inscatter"]["type"], "vec3s");
  EXPECT_EQ(json["grids"]["inscatter_luminance"]["type"], "float");
  size_t texel = ((size_t(5) * grid.height + 2) * grid.width + 3) * 4;
  for (int c = 0; c < 3; ++c) EXPECT_EQ(float(json["rayleigh_3_2_5"][c].get<double>()), frame.texels.rayleigh[texel + c]);
  auto keys = json["metadata_keys"].get<std::vector<std::string>>();
  for (const char* key : {"camera_position_m", "sun_direction", "lut", "atmosphere_hash", "units"})
    EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << key;
}

class VdbPaths : public ScratchDirTest {};

TEST_F(VdbPaths, UnwritableOrWrongPathsFailBeforeAnyWork) {
  EXPECT_THROW(CheckVdbOutputPath("/nonexistent-aerial-dir/x.vdb"), Error);
  EXPECT_FALSE(std::filesystem::exists("/nonexistent-aerial-dir"));
  try {
    CheckVdbOutputPath(dir_ / "x.exr");
    FAIL() << "a .exr name was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "--out");
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

}  // namespace
}  // namespace aerial::testing
