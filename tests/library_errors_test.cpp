// The library as a program that embeds it calls it: its errors name the API's own fields (the
// option, the struct's member, the function's input) with the bad value, never an option of the
// aerial command, which that program does not have. (The command's own messages, under its
// options, are checked in command_line_errors_test.cpp.)
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "aerial/aerial.h"
#include "aerial/view_geometry.h"
#include "scratch_directory.h"

namespace aerial::testing {
namespace {

struct Call {
  std::string field, value;
  std::function<void()> call;
};

TEST(LibraryErrors, NameTheApisOwnFieldsNotACommandLinesOptions) {
  ScratchDirectory dir("library-errors");
  const AtmosphereParameters earth = AtmosphereParameters::Earth();
  const Scene scene = BuildPreset("noon", earth.bottom_radius_m);
  const FroxelGrid grid;
  PrecomputeOptions huge_transmittance = PrecomputeOptions::Default();
  huge_transmittance.resolution.transmittance_mu = huge_transmittance.resolution.transmittance_r = 4096;
  const std::vector<Call> calls = {
      {"RenderOptions::width/height", "0x720", [] { RenderOptions{.width = 0}.Validate(); }},
      {"RenderOptions::render_scale", "0.1", [] { RenderOptions{.render_scale = 0.1}.Validate(); }},
      {"RenderOptions::terrain_error_px", "0", [] { RenderOptions{.terrain_error_px = 0.0}.Validate(); }},
      {"FroxelGrid::width/height/depth", "16x8", [] { FroxelGrid::Parse("16x8"); }},
      {"FroxelGrid::width/height/depth", "1x32x32", [] { FroxelGrid{.width = 1}.Validate(); }},
      {"FroxelGrid::far_m", "50.0", [] { FroxelGrid{.far_m = 50.0}.Validate(); }},
      {"preset name", "dusk", [&] { BuildPreset("dusk", earth.bottom_radius_m); }},
      {"scene file", (dir / "missing.toml").string(),
       [&] { LoadSceneFile(dir / "missing.toml", earth.bottom_radius_m); }},
      {"atmosphere file", (dir / "missing.toml").string(), [&] { LoadAtmosphereFile(dir / "missing.toml"); }},
      {"VDB path", (dir / "froxels.exr").string(),
       [&] { CheckVdbExport(dir / "froxels.exr", scene, earth, grid, {}); }},
      {"VdbExportOptions::world_grid_m", "-1",
       [&] { CheckVdbExport(dir / "froxels.vdb", scene, earth, grid, {.world_grid_m = -1.0}); }},
      {"ViewAngles::altitude_m", "-5", [&] { ValidateViewAngles({.altitude_m = -5.0}, earth); }},
      {"ViewAngles::view_zenith_deg", "200", [&] { ValidateViewAngles({.view_zenith_deg = 200.0}, earth); }},
      {"ViewAngles::sun_zenith_deg", "-1", [&] { ValidateViewAngles({.sun_zenith_deg = -1.0}, earth); }},
      {"ViewAngles::azimuth_deg", "400", [&] { ValidateViewAngles({.azimuth_deg = 400.0}, earth); }},
      {"TableResolution::transmittance_mu/r", "4096x4096 = 16777216 texels", [&] { huge_transmittance.Validate(); }},
  };
  for (const Call& c : calls) {
    SCOPED_TRACE(c.field);
    try {
      c.call();
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.field(), c.field) << e.what();
      EXPECT_EQ(e.value(), c.value) << e.what();
      EXPECT_EQ(std::string(e.what()).find("--"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace aerial::testing
