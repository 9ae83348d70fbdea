// The aerial command as users run it: bad input gives a clear message naming the field and a
// non-zero exit, and the probe prints the JSON keys other tools script against.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "run_aerial.h"

namespace aerial::testing {
namespace {

const std::string kProbe =
    "probe --small-tables --quiet --altitude-m 1 --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0";

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

struct BadInput {
  std::string arguments;
  std::string must_mention;
};

void PrintTo(const BadInput& input, std::ostream* out) { *out << input.arguments; }

class CliRejects : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliRejects, WithMessageAndNonZeroExit) {
  std::filesystem::remove("/tmp/aerial-cli-test.png");
  CommandRun run = RunAerial(GetParam().arguments);
  EXPECT_FALSE(std::filesystem::exists("/tmp/aerial-cli-test.png")) << "no partial output";
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
        BadInput{"probe --altitude-m 0 --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0 --lut 5d", "--lut"},
        BadInput{"probe --altitude-m 0 --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0 --atmosphere /nonexistent/earth.toml", "/nonexistent/earth.toml"},
        BadInput{"precompute --orders 0", "--orders"},
        BadInput{"precompute --small-tables --quiet --out /proc/aerial-cannot-write", "/proc/aerial-cannot-write"},
        BadInput{"precompute --atmosphere " AERIAL_SOURCE_DIR "/tests/data/bad_mie_g.toml", "mie.phase_g"},
        BadInput{"precompute --atmosphere " AERIAL_SOURCE_DIR "/tests/data/unknown_key.toml", "rayleigh.scatterring"},
        BadInput{"render --preset no-such-preset --out /tmp/aerial-cli-test.png", "no-such-preset"},
        BadInput{"render --width 0 --height 10 --out /tmp/aerial-cli-test.png", "--width"},
        BadInput{"render --width 100000 --height 10 --out /tmp/aerial-cli-test.png", "--width"},
        BadInput{"render --froxels 32x32 --out /tmp/aerial-cli-test.png", "--froxels"},
        BadInput{"render --out /nonexistent-aerial-dir/x.png", "/nonexistent-aerial-dir"},
        BadInput{"render --out /tmp/aerial-cli-test.jpg", "--out"},
        BadInput{"render --scene " AERIAL_SOURCE_DIR "/tests/data/bad_scene.toml --out /tmp/aerial-cli-test.png", "camera.fov_deg"},
        BadInput{"bench --quick --out /proc/aerial-bench-out", "/proc/aerial-bench-out"},
        BadInput{"no-such-command", "no-such-command"}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return "case" + std::to_string(info.index); });

}  // namespace
}  // namespace aerial::testing
