// CTest label "sanitizer": the command end to end: run under the sanitizers too.
// The aerial command as users run it: bad input gives a clear message naming the field and a
// non-zero exit, and the probe prints the JSON keys other tools script against. (The viewer's
// runs under Xvfb are in view_cli_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "aerial/device.h"
#include "aerial/export/vdb_file.h"
#include "aerial/spectrum/spectral_sampling.h"
#include "aerial/version.h"
#include "command_run.h"

namespace aerial::testing {
namespace {

// rgb tables: the probe prints their three wavelengths (spectral ones, the default, print twelve).
const std::string kProbe =
    "probe --small-tables --quiet --colour rgb --altitude-m 1 --view-zenith-deg 45 --sun-zenith-deg 30 "
    "--azimuth-deg 0";

TEST(Cli, ProbePrintsEveryKeyForEachWavelength) {
  CommandRun run = RunAerial(kProbe + " --distance-m 10000");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto json = nlohmann::json::parse(run.out);
  ASSERT_EQ(json["wavelengths_nm"].size(), 3u);
  for (const char* key : {"sky_radiance", "transmittance", "sun_irradiance", "sky_irradiance",
                          "solar_radiance", "radiance_to_point", "transmittance_to_point"}) {
    ASSERT_TRUE(json.contains(key)) << key;
    ASSERT_EQ(json[key].size(), 3u) << key;
    for (double v : json[key]) EXPECT_TRUE(std::isfinite(v) && v >= 0.0) << key;
  }
}

// The reference also prints its Monte Carlo standard errors (of the orders >= 2): positive, and with
// its default 131,072 paths at most a few tenths of a percent of the value on this daylight ray
// (2% is far above any converged estimate and far below a missing 1/sqrt(n)). The tables print none.
TEST(Cli, ProbeReferencePrintsItsStandardErrors) {
  CommandRun run = RunAerial(kProbe + " --distance-m 10000 --reference");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto json = nlohmann::json::parse(run.out);
  for (const char* quantity : {"sky_radiance", "sky_irradiance", "radiance_to_point"}) {
    std::string key = std::string(quantity) + "_std_error";
    ASSERT_TRUE(json.contains(key)) << key;
    ASSERT_EQ(json[key].size(), 3u) << key;
    for (int c = 0; c < 3; ++c) {
      double error = json[key][c], value = json[quantity][c];
      EXPECT_GT(error, 0.0) << key << " " << c;
      EXPECT_LT(error, 0.02 * value) << key << " " << c;
    }
  }
  CommandRun tables = RunAerial(kProbe);
  ASSERT_EQ(tables.exit_code, 0) << tables.err;
  EXPECT_FALSE(nlohmann::json::parse(tables.out).contains("sky_radiance_std_error"));
}

// Without --colour the probe reads spectral tables, as every command does: its quantities are
// given at the tables' twelve wavelengths, ascending, and their linear sRGB beside them.
TEST(Cli, ProbeDefaultsToSpectral) {
  CommandRun run = RunAerial("probe --small-tables --quiet --altitude-m 1 --view-zenith-deg 45 --sun-zenith-deg 30 "
                             "--azimuth-deg 0");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["colour"], "spectral");
  EXPECT_EQ(json["channels"], "wavelengths_nm");
  ASSERT_EQ(json["wavelengths_nm"].size(), 12u);
  for (size_t i = 1; i < 12; ++i) EXPECT_GT(json["wavelengths_nm"][i].get<double>(), json["wavelengths_nm"][i - 1].get<double>());
  for (const char* key : {"sky_radiance", "transmittance", "sun_irradiance", "sky_irradiance", "solar_radiance"}) {
    ASSERT_EQ(json[key].size(), 12u) << key;
    ASSERT_EQ(json["linear_srgb"][key].size(), 3u) << key;
  }
}

// The spectral probe's values at each wavelength, from the tables (each group of three
// wavelengths' own tables) and from the CPU reference, single scattering (a quadrature: quick):
// - the two agree wavelength by wavelength within 2%: the small tables' interpolation is 1% off
//   at worst here (the sky irradiance), and a group out of order is off by a factor of 1.4 or
//   more, as the sky's radiance falls by 5x from the first wavelength to the last;
// - on this daylight ray the transmittance grows with the wavelength (Rayleigh's 1/lambda^4
//   outweighs ozone's Chappuis band);
// - the tables' spectrum, converted as the spectral precompute converts it, is their linear sRGB:
//   at one order, in float32, the precompute folds the same groups' tables linearly, so only float
//   rounding is left (1.1e-5 at most, in red, whose weights cancel), where the reference's weights
//   for 12 wavelengths (SpectralSampling::Midpoint) are 5-58% off.
TEST(Cli, SpectralProbeGivesTheSpectrumAndItsColour) {
  const std::string probe = "probe --small-tables --quiet --colour spectral --orders 1 --series-tail off "
                            "--precision float32 --altitude-m 1 --view-zenith-deg 45 --sun-zenith-deg 30 "
                            "--azimuth-deg 0 --distance-m 10000";
  const char* keys[] = {"sky_radiance", "transmittance", "sun_irradiance", "sky_irradiance",
                        "solar_radiance", "radiance_to_point", "transmittance_to_point"};
  std::map<std::string, nlohmann::json> runs;
  for (const std::string& source : {std::string("tables"), std::string("reference")}) {
    CommandRun run = RunAerial(probe + (source == "reference" ? " --reference" : ""));
    ASSERT_EQ(run.exit_code, 0) << source << run.err;
    const nlohmann::json json = runs[source] = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["source"], source);
    ASSERT_EQ(json["wavelengths_nm"].size(), 12u) << source;
    for (const char* key : keys) {
      ASSERT_EQ(json[key].size(), 12u) << source << " " << key;
      for (double v : json[key]) EXPECT_TRUE(std::isfinite(v) && v > 0.0) << source << " " << key;
      EXPECT_EQ(json["linear_srgb"][key].size(), 3u) << source << " " << key;
    }
    for (size_t i = 1; i < 12; ++i)
      EXPECT_GT(json["transmittance"][i].get<double>(), json["transmittance"][i - 1].get<double>()) << source << i;
  }
  const nlohmann::json& tables = runs["tables"];
  const nlohmann::json& reference = runs["reference"];
  for (const char* key : keys)
    for (size_t i = 0; i < 12; ++i)
      EXPECT_NEAR(tables[key][i].get<double>() / reference[key][i].get<double>(), 1.0, 0.02) << key << " " << i;
  const spectrum::SpectralSampling sampling = spectrum::SpectralSampling::ForTables(12);
  for (const char* key : {"sky_radiance", "sky_irradiance"}) {
    const Spectrum converted = sampling.LinearSrgb(tables[key].get<std::vector<double>>());
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(converted[c] / tables["linear_srgb"][key][c].get<double>(), 1.0, 1e-4) << key << " " << c;
  }
}

// Steps along the frustum grid's columns (k: farther from the camera) where a value moves against
// `direction`: +1, it may only grow (inscatter accumulates); -1, it may only fall (transmittance).
int StepsAgainst(const VdbGridData& grid, int direction) {
  int against = 0;
  for (int32_t j = grid.min[1]; j <= grid.max[1]; ++j)
    for (int32_t i = grid.min[0]; i <= grid.max[0]; ++i) {
      const float* previous = nullptr;
      for (int32_t k = grid.min[2]; k <= grid.max[2]; ++k) {
        const int64_t at = grid.Offset(i, j, k);
        if (!grid.active[at]) continue;
        const float* value = &grid.values[at * grid.components];
        for (int c = 0; previous && c < grid.components; ++c) against += direction * (value[c] - previous[c]) < 0.0f;
        previous = value;
      }
    }
  return against;
}

// export-vdb writes a file the OpenVDB library reads (aerial/export/vdb_file.h), on the camera's
// frustum and on a world grid: the grids aerial writes, with as many active voxels as the command
// says, of the froxel volume asked for, holding finite inscatter (some of it positive), a
// transmittance in (0, 1] and a non-negative density; in the frustum, inscatter grows and
// transmittance falls away from the camera.
TEST(Cli, ExportVdbWritesTheFroxelVolume) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / ("aerial-cli-vdb-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const std::string extra : {"", " --world-grid 8000"}) {
    std::filesystem::path out = dir / "f.vdb";
    CommandRun run = RunAerial("export-vdb --small-tables --quiet --froxels 8x4x6" + extra + " --out " + out.string());
    ASSERT_EQ(run.exit_code, 0) << extra << "\n" << run.err;
    const size_t said = run.out.find(": ");  // "wrote PATH: N voxels per grid (...)"
    size_t voxels = 0;
    ASSERT_NE(said, std::string::npos) << run.out;
    ASSERT_EQ(std::sscanf(run.out.c_str() + said, ": %zu voxels per grid", &voxels), 1) << run.out;
    VdbFileData file = ReadVdb(out);
    EXPECT_EQ(std::get<std::string>(file.metadata.at("grid_space")), extra.empty() ? "frustum" : "world");
    using Int3 = std::array<int32_t, 3>;
    EXPECT_EQ(std::get<Int3>(file.metadata.at("froxel_resolution")), (Int3{8, 4, 6}));
    for (const char* name : {"rayleigh_inscatter", "mie_inscatter", "transmittance", "inscatter_luminance", "density"}) {
      const VdbGridData* grid = file.Find(name);
      ASSERT_NE(grid, nullptr) << name << extra;
      EXPECT_EQ(grid->linear_transform, !extra.empty()) << name << " " << grid->map_type;
      EXPECT_EQ(size_t(grid->active_voxels), voxels) << name << extra;
      const std::string grid_name = name;
      float largest = 0.0f;
      int bad = 0;
      for (size_t v = 0; v < grid->active.size(); ++v) {
        if (!grid->active[v]) continue;
        for (int c = 0; c < grid->components; ++c) {
          float value = grid->values[v * grid->components + c];
          largest = std::max(largest, value);
          bad += !std::isfinite(value) || value < 0.0f || (grid_name == "transmittance" && !(value > 0.0f && value <= 1.0f));
        }
      }
      EXPECT_EQ(bad, 0) << name << extra;
      EXPECT_GT(largest, 0.0f) << name << extra;
    }
    if (extra.empty()) {
      EXPECT_EQ(StepsAgainst(*file.Find("rayleigh_inscatter"), +1), 0);
      EXPECT_EQ(StepsAgainst(*file.Find("transmittance"), -1), 0);
    } else {
      EXPECT_EQ(file.grids.front().index_to_world[0], 8000.0);
    }
    std::vector<std::string> leftovers;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path() != out) leftovers.push_back(entry.path().string());
    EXPECT_TRUE(leftovers.empty()) << "a temporary was left: " << leftovers.front();
    std::filesystem::remove(out);
  }
  std::filesystem::remove_all(dir);
}

// render --timings prints the compute passes' GPU times and the frame's wall-clock time. A CPU
// rasterizer (lavapipe) draws a raster pass's draws when the pass ends, after the timestamps
// around them, so there the raster passes are left out and the output says why; a GPU lists them.
TEST(Cli, RenderTimingsLeaveOutWhatTheDeviceCannotTime) {
  std::filesystem::path out = std::filesystem::temp_directory_path() / ("aerial-cli-timings-" + std::to_string(::getpid()) + ".png");
  CommandRun run = RunAerial("render --small-tables --quiet --width 64 --height 36 --timings --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::filesystem::remove(out);
  EXPECT_NE(run.out.find("wrote " + out.string()), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("froxel build"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("ms wall clock"), std::string::npos) << run.out;
  const bool cpu = Device().name().find("llvmpipe") != std::string::npos;
  const bool explained = run.out.find("rasterizes a pass's draws at its end") != std::string::npos;
  EXPECT_EQ(explained, cpu) << run.out;
  for (const char* raster : {"opaque raster", "transparent raster"})
    EXPECT_EQ(run.out.find(raster) == std::string::npos, cpu) << raster << "\n" << run.out;
}

// Without a Vulkan driver the message says so and how to install one, instead of the loader's
// "vkCreateInstance: ErrorIncompatibleDriver".
TEST(Cli, NoVulkanDriverSaysHowToInstallOne) {
  CommandRun run = RunAerial(kProbe, "env VK_ICD_FILENAMES=/nonexistent.json VK_DRIVER_FILES=/nonexistent.json");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("Vulkan driver = none found"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("apt install mesa-vulkan-drivers"), std::string::npos) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
}

// --version prints the package's version, whose major is 2: 2.0 took names out of 1.x's headers
// and renamed the GLSL's macros (docs/api.md), and find_package(aerial 2.0) asks for it.
TEST(Cli, VersionIsTheSecondMajor) {
  CommandRun run = RunAerial("--version");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, std::string(AERIAL_VERSION) + "\n");
  EXPECT_EQ(AERIAL_VERSION_MAJOR, 2);
  EXPECT_EQ(run.out.substr(0, 2), "2.") << run.out;
}

// The exit statuses --help's footer promises: 2 for a command line that does not parse, 1 for a
// value that parses but is refused when the command runs, 0 for --help. (CLI11's own codes, 106
// and 109, leaked out before.)
TEST(Cli, UsageErrorsExitTwoAndRunTimeErrorsOne) {
  const std::string out = " --out /tmp/aerial-cli-exit-test.png";
  for (const std::string& usage : {std::string("no-such-command"), "render --no-such-option" + out, "render --aerial nope" + out,
                                   "render --preset nope" + out, "render --width" + out, std::string("render")}) {
    CommandRun run = RunAerial(usage);
    EXPECT_EQ(run.exit_code, 2) << usage << "\n" << run.err;
  }
  CommandRun refused = RunAerial("render --exposure 0" + out);
  EXPECT_EQ(refused.exit_code, 1) << refused.err;
  CommandRun help = RunAerial("render --help");
  EXPECT_EQ(help.exit_code, 0) << help.err;
  // The options a user sets most come first, the tables' last, with their defaults.
  size_t preset = help.out.find("--preset"), width = help.out.find("--width INT=1280"),
         tables = help.out.find("Tables, device and memory:"), lut = help.out.find("--lut");
  EXPECT_LT(preset, width) << help.out;
  EXPECT_LT(width, tables) << help.out;
  EXPECT_LT(tables, lut) << help.out;
  EXPECT_NE(lut, std::string::npos) << help.out;
}

struct BadInput {
  std::string arguments;
  std::string must_mention;
};

void PrintTo(const BadInput& input, std::ostream* out) { *out << input.arguments; }

class CliRejects : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliRejects, WithMessageAndNonZeroExit) {
  for (const char* output : {"/tmp/aerial-cli-test.png", "/tmp/aerial-cli-test.vdb"})
    std::filesystem::remove(output);
  CommandRun run = RunAerial(GetParam().arguments);
  for (const char* output : {"/tmp/aerial-cli-test.png", "/tmp/aerial-cli-test.vdb"})
    EXPECT_FALSE(std::filesystem::exists(output)) << "no partial output";
  EXPECT_NE(run.exit_code, 0) << GetParam().arguments;
  EXPECT_NE(run.err.find(GetParam().must_mention), std::string::npos)
      << "stderr does not mention \"" << GetParam().must_mention << "\":\n" << run.err;
  EXPECT_TRUE(run.out.empty() || run.out.find('{') == std::string::npos) << "no JSON on failure";
}

INSTANTIATE_TEST_SUITE_P(
    BadValues, CliRejects,
    ::testing::Values(
        BadInput{"probe --altitude-m -5 --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0", "--altitude-m"},
        BadInput{"probe --altitude-m 70000 --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0", "--altitude-m"},
        BadInput{"probe --altitude-m 0 --view-zenith-deg 200 --sun-zenith-deg 30 --azimuth-deg 0", "--view-zenith-deg"},
        BadInput{"probe --altitude-m 0 --view-zenith-deg 45 --sun-zenith-deg -1 --azimuth-deg 0", "--sun-zenith-deg"},
        BadInput{"probe --altitude-m 0 --view-zenith-deg 45 --sun-zenith-deg 30", "--azimuth-deg"},
        BadInput{"probe --altitude-m 0 --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0 --distance-m -3", "--distance-m"},
        BadInput{"probe --altitude-m 0 --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0 --distance-m 1e300", "--distance-m = 1e300"},
        BadInput{"render --exposure 1e300 --out /tmp/aerial-cli-test.png", "--exposure = 1e300"},
        BadInput{"render --exposure 0 --out /tmp/aerial-cli-test.png", "--exposure"},
        BadInput{"export-vdb --froxel-far-m 1e300 --out /tmp/aerial-cli-test.vdb", "--froxel-far-m = 1e300"},
        BadInput{"render --shadows yes --out /tmp/aerial-cli-test.png", "--shadows = yes is invalid; expected on or off"},
        BadInput{"export-vdb --shadows 1 --out /tmp/aerial-cli-test.vdb", "--shadows = 1 is invalid; expected on or off"},
        BadInput{"view --shadows ON --frames 1", "--shadows = ON is invalid; expected on or off"},
        BadInput{"bench --quick --shadows none --out /tmp/aerial-cli-test-bench", "--shadows = none is invalid; expected on or off"},
        BadInput{"probe --altitude-m 0 --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0 --lut 5d", "--lut"},
        BadInput{"probe --altitude-m 0 --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0 --atmosphere /nonexistent/earth.toml", "/nonexistent/earth.toml"},
        BadInput{"precompute --orders 0", "--orders"},
        BadInput{"precompute --precision float64", "--precision"},
        BadInput{"precompute --colour spectral --wavelengths 9", "wavelengths = 9 is invalid; expected a multiple of 6"},
        BadInput{"precompute --half --precision float32", "--precision = float32 with --half is invalid"},
        BadInput{"precompute --small-tables --quiet --cache-dir /proc/aerial-cannot-write", "/proc/aerial-cannot-write"},
        BadInput{"precompute --atmosphere " AERIAL_SOURCE_DIR "/tests/data/bad_mie_g.toml", "mie.phase_g"},
        BadInput{"precompute --atmosphere " AERIAL_SOURCE_DIR "/tests/data/unknown_key.toml", "rayleigh.scatterring"},
        // Finite doubles beyond float: they must not give null in the JSON and exit status 0.
        BadInput{"probe --small-tables --quiet --altitude-m 1 --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0 "
                 "--atmosphere " AERIAL_SOURCE_DIR "/tests/data/huge_solar_irradiance.toml",
                 "solar_irradiance[0] = 1e+300 is invalid"},
        BadInput{"probe --small-tables --quiet --altitude-m 1 --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0 "
                 "--atmosphere " AERIAL_SOURCE_DIR "/tests/data/huge_rayleigh.toml",
                 "rayleigh.scattering[1] = 1e+300 is invalid"},
        BadInput{"render --small-tables --scene " AERIAL_SOURCE_DIR "/tests/data/huge_near.toml --out /tmp/aerial-cli-test.png",
                 "camera.near_m = 1e+30 is invalid"},
        BadInput{"render --small-tables --scene " AERIAL_SOURCE_DIR "/tests/data/huge_mesh_scale.toml --out /tmp/aerial-cli-test.png",
                 "mesh[0].scale = 1e+300 (places a vertex"},
        BadInput{"render --preset no-such-preset --out /tmp/aerial-cli-test.png", "no-such-preset"},
        BadInput{"render --width 0 --height 10 --out /tmp/aerial-cli-test.png", "--width"},
        BadInput{"render --width 100000 --height 10 --out /tmp/aerial-cli-test.png", "--width"},
        BadInput{"render --froxels 32x32 --out /tmp/aerial-cli-test.png", "--froxels"},
        BadInput{"render --render-scale 0.1 --out /tmp/aerial-cli-test.png", "--render-scale"},
        BadInput{"view --render-scale 1.5", "--render-scale"},
        BadInput{"render --terrain-error-px 0 --out /tmp/aerial-cli-test.png", "--terrain-error-px"},
        BadInput{"render --terrain coarse --out /tmp/aerial-cli-test.png", "--terrain"},
        BadInput{"render --out /nonexistent-aerial-dir/x.png", "/nonexistent-aerial-dir"},
        BadInput{"render --out /tmp/aerial-cli-test.jpg", "--out"},
        BadInput{"render --scene " AERIAL_SOURCE_DIR "/tests/data/bad_scene.toml --out /tmp/aerial-cli-test.png", "camera.fov_deg"},
        BadInput{"export-vdb --froxels 16x8 --out /tmp/aerial-cli-test.vdb", "--froxels"},
        BadInput{"export-vdb --froxels 16x8x1 --out /tmp/aerial-cli-test.vdb", "--froxels"},
        BadInput{"export-vdb --world-grid 0 --out /tmp/aerial-cli-test.vdb", "--world-grid"},
        BadInput{"export-vdb --world-grid -100 --out /tmp/aerial-cli-test.vdb", "--world-grid"},
        BadInput{"export-vdb --world-grid 1 --out /tmp/aerial-cli-test.vdb", "--world-grid"},
        BadInput{"export-vdb --world-grid abc --out /tmp/aerial-cli-test.vdb", "--world-grid"},
        BadInput{"export-vdb --froxel-far-m 50 --out /tmp/aerial-cli-test.vdb", "--froxel-far-m"},
        BadInput{"render --froxel-far-m 5e6 --out /tmp/aerial-cli-test.png", "--froxel-far-m"},
        BadInput{"export-vdb --out /tmp/aerial-cli-test.exr", "--out"},
        BadInput{"export-vdb --out /nonexistent-aerial-dir/x.vdb", "/nonexistent-aerial-dir"},
        BadInput{"export-vdb --preset no-such-preset --out /tmp/aerial-cli-test.vdb", "no-such-preset"},
        BadInput{"export-vdb --camera-fov-deg 500 --out /tmp/aerial-cli-test.vdb", "--camera-fov-deg"},
        // The output path and --world-grid are checked before the GPU is touched: with a device
        // that does not exist, the message is still about them.
        BadInput{"export-vdb --device no-such-gpu --out /nonexistent-aerial-dir/x.vdb", "/nonexistent-aerial-dir"},
        BadInput{"export-vdb --device no-such-gpu --world-grid 1 --out /tmp/aerial-cli-test.vdb", "--world-grid"},
        // The viewer checks its paths and files before opening a window, so these need no display.
        BadInput{"view --frames 2 --screenshot /nonexistent-aerial-dir/x.png", "--screenshot"},
        BadInput{"view --frames 2 --screenshot /tmp/aerial-cli-test.jpg", "--screenshot"},
        BadInput{"view --screenshot /tmp/aerial-cli-test.png", "--frames"},
        BadInput{"view --frames 0", "--frames"},
        BadInput{"view --frames 2 --screenshot /tmp/aerial-cli-test.exr --screenshot-panel", "--screenshot-panel"},
        BadInput{"view --frames 2 --screenshot-panel", "--screenshot-panel"},
        BadInput{"view --camera-path /nonexistent-aerial-dir/path.toml", "--camera-path"},
        BadInput{"view --camera-path " AERIAL_SOURCE_DIR "/tests/data/bad_camera_path.toml", "keyframe[1].pitch_deg"},
        BadInput{"bench --quick --out /proc/aerial-bench-out", "/proc/aerial-bench-out"},
        BadInput{"no-such-command", "no-such-command"}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return "case" + std::to_string(info.index); });

}  // namespace
}  // namespace aerial::testing
