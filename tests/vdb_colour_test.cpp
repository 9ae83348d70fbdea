// export-vdb for path tracers: the per-channel `scattering` and `absorption` grids hold the air's
// own coefficients at each voxel (1/m, from the atmosphere's parameters, written here from their
// definition), sum to the `density` grid's extinction, and differ by channel as Rayleigh's
// wavelength dependence makes them; the frustum grid's first voxel lies where the froxels' first
// slice does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

#include "aerial/export/camera_frustum.h"
#include "aerial/export/froxel_export.h"
#include "aerial/scene.h"
#include "aerial/scene/camera.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

// The air's scattering and absorption coefficients per channel at a point (1/m): Rayleigh and Mie
// scattering, and Mie's absorption (its extinction less its scattering) and ozone's, each times
// its density profile at the altitude above the planet sphere; none above the atmosphere's top,
// sea level's below sea level.
void ExpectedCoefficients(const AtmosphereParameters& air, const glm::dvec3& point, glm::dvec3& scattering,
                          glm::dvec3& absorption) {
  double altitude = glm::length(point - glm::dvec3(0.0, 0.0, -air.bottom_radius_m)) - air.bottom_radius_m;
  scattering = absorption = glm::dvec3(0.0);
  if (altitude > air.top_radius_m - air.bottom_radius_m) return;
  altitude = std::max(altitude, 0.0);
  const double rayleigh = air.rayleigh_density.Density(altitude), mie = air.mie_density.Density(altitude),
               ozone = air.absorption_density.Density(altitude);
  for (int c = 0; c < 3; ++c) {
    scattering[c] = air.rayleigh_scattering[c] * rayleigh + air.mie_scattering[c] * mie;
    absorption[c] = (air.mie_extinction[c] - air.mie_scattering[c]) * mie + air.absorption_extinction[c] * ozone;
  }
}

class VdbColour : public GpuTest {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    dir_ = std::filesystem::temp_directory_path() / ("aerial_vdb_colour_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::filesystem::remove_all(dir_);
    GpuTest::TearDown();
  }
  std::filesystem::path dir_;
};

// Read back through OpenVDB from a world grid (the layout Blender takes): at every active voxel
// the coefficients of the voxel's centre within 1e-6 relative (float32 of the same double
// arithmetic), their sum's Rec. 709 luma the density grid's, and at sea level blue scattering
// more than 3 times red (Rayleigh's 1/lambda^4: (680/440)^4 = 5.7, less Mie's grey part).
TEST_F(VdbColour, ScatteringAndAbsorptionAreTheAirsCoefficientsPerChannel) {
  const AtmosphereTables& tables = SmallTables();
  Scene scene = BuildPreset("noon", tables.atmosphere().bottom_radius_m);
  FroxelGrid grid;
  grid.width = 16;
  grid.height = 8;
  grid.depth = 12;
  grid.far_m = 20e3;
  FroxelFrame frame = CaptureFroxels(tables, scene, grid, {.width = 64, .height = 36});
  WriteVdb(dir_ / "w.vdb", MakeWorldSpaceVolume(frame, 250.0));
  VdbFileData file = ReadVdb(dir_ / "w.vdb");
  const VdbGridData* scattering = file.Find("scattering");
  const VdbGridData* absorption = file.Find("absorption");
  const VdbGridData* density = file.Find("density");
  ASSERT_NE(scattering, nullptr);
  ASSERT_NE(absorption, nullptr);
  ASSERT_NE(density, nullptr);
  EXPECT_EQ(scattering->type, "vec3s");
  EXPECT_EQ(absorption->type, "vec3s");
  EXPECT_EQ(std::get<std::string>(scattering->metadata.at("value_units")), "1/m");
  ASSERT_EQ(scattering->active_voxels, density->active_voxels);
  ASSERT_GT(scattering->active_voxels, 1000);

  const AtmosphereParameters& air = frame.atmosphere;  // in the channels' terms
  double worst = 0.0, worst_sum = 0.0, lowest = 1e30, blue_over_red = 0.0;
  for (int32_t k = scattering->min[2]; k <= scattering->max[2]; ++k)
    for (int32_t j = scattering->min[1]; j <= scattering->max[1]; ++j)
      for (int32_t i = scattering->min[0]; i <= scattering->max[0]; ++i) {
        const int64_t offset = scattering->Offset(i, j, k);
        if (!scattering->active[offset]) continue;
        const auto world = scattering->IndexToWorld(i, j, k);
        const glm::dvec3 point(world[0], world[1], world[2]);
        glm::dvec3 expected_scattering, expected_absorption;
        ExpectedCoefficients(air, point, expected_scattering, expected_absorption);
        glm::dvec3 read_scattering, read_absorption;
        for (int c = 0; c < 3; ++c) {
          read_scattering[c] = scattering->values[offset * 3 + c];
          read_absorption[c] = absorption->values[offset * 3 + c];
          worst = std::max({worst, std::abs(read_scattering[c] / expected_scattering[c] - 1.0),
                            std::abs(read_absorption[c] / expected_absorption[c] - 1.0)});
        }
        const glm::dvec3 sum = read_scattering + read_absorption;
        worst_sum = std::max(worst_sum,
                             std::abs((0.2126 * sum.r + 0.7152 * sum.g + 0.0722 * sum.b) / density->values[offset] - 1.0));
        const double altitude = glm::length(point - glm::dvec3(0, 0, -air.bottom_radius_m)) - air.bottom_radius_m;
        if (altitude < lowest) {
          lowest = altitude;
          blue_over_red = read_scattering.b / read_scattering.r;
        }
      }
  std::printf("scattering/absorption: worst relative error %.2e, luma of their sum against density %.2e; "
              "blue/red scattering %.2f at %.0f m\n",
              worst, worst_sum, blue_over_red, lowest);
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(worst_sum, 1e-5);
  EXPECT_LT(lowest, 500.0);
  EXPECT_GT(blue_over_red, 3.0);
  EXPECT_LT(blue_over_red, 6.0);
}

// The frustum grid's depth is where the froxels' is: for render's default 32 x 32 x 32 froxels
// to 128 km and a 0.5 m near plane, the first voxel's centre (read back through OpenVDB's own
// frustum map) lies at view depth 31.25 m, the first froxel slice's distance, within 0.05 m (the
// slices are a whole number: 2082 of 61.48 m put it 0.01 m nearer). Linear slices as many as the
// froxels' put it 2 km out.
TEST_F(VdbColour, FrustumFirstVoxelSitsAtTheFirstFroxelSlice) {
  Camera camera;
  camera.position = {100.0, -200.0, 30.0};
  camera.yaw_deg = 20.0;
  camera.pitch_deg = 4.0;
  const FroxelGrid grid;  // 32 x 32 x 32 to 128 km
  const CameraFrustum frustum(camera, 16.0 / 9.0, grid);
  VdbVolume volume;
  volume.frustum = frustum.Map();
  for (int32_t k : {0, 1}) volume.voxels.push_back({15, 16, k});
  volume.grids = {{.name = "density", .components = 1, .values = {1.0f, 1.0f}}};
  WriteVdb(dir_ / "f.vdb", volume);
  VdbFileData file = ReadVdb(dir_ / "f.vdb");
  ASSERT_EQ(file.grids.size(), 1u);
  const double first_slice = grid.SliceDistance(0.5);
  EXPECT_DOUBLE_EQ(first_slice, 31.25);
  const glm::dvec3 forward = Forward(camera);
  for (int32_t k : {0, 1}) {
    const auto world = file.grids[0].IndexToWorld(15.0, 16.0, k);
    const double view_depth = glm::dot(glm::dvec3(world[0], world[1], world[2]) - camera.position, forward);
    std::printf("frustum slice %d: view depth %.3f m (first froxel slice %.3f m), %d slices\n", k, view_depth,
                first_slice, frustum.slices());
    // The second one slice, 2 (31.25 - 0.5) m deep, farther.
    const double expected = k == 0 ? first_slice : camera.near_m + 3.0 * (first_slice - camera.near_m);
    EXPECT_NEAR(view_depth, expected, k == 0 ? 0.05 : 0.1);
  }
  EXPECT_EQ(frustum.slices(), 2082);
}

}  // namespace
}  // namespace aerial::testing
