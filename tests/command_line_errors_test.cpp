// The aerial command's messages for values the library refuses: the library names its API's
// fields (library_errors_test.cpp), and the command shows each under the option the user typed,
// with the value as typed, and no API name ("RenderOptions::...") leaks through.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "command_run.h"
#include "scratch_directory.h"

namespace aerial::testing {
namespace {

struct Refused {
  std::string arguments, message;
};

TEST(CommandLineErrors, NameTheOptionTheUserTyped) {
  ScratchDirectory dir("command-line-errors");
  const std::string png = " --out " + (dir / "sky.png").string();
  const std::string missing = (dir / "missing.toml").string();
  const std::vector<Refused> cases = {
      {"render --width 0" + png, "--width/--height = 0x720 is invalid; expected 1..16384 pixels per side"},
      {"render --render-scale 0.1" + png, "--render-scale = 0.1 is invalid; expected in [0.25, 1]"},
      {"render --terrain-error-px 0" + png, "--terrain-error-px = 0 is invalid; expected in [0.25, 64]"},
      {"render --froxels 16x8" + png, "--froxels = 16x8 is invalid; expected WxHxD"},
      {"render --froxel-far-m 50" + png, "--froxel-far-m = 50 is invalid; expected meters in (100, 1e6]"},
      {"render --scene " + missing + png, "--scene = " + missing + " is invalid"},
      {"render --atmosphere " + missing + png, "--atmosphere = " + missing + " is invalid"},
      {"export-vdb --out " + (dir / "froxels.exr").string(),
       "--out = " + (dir / "froxels.exr").string() + " is invalid; expected a .vdb file"},
      {"export-vdb --world-grid -1 --out " + (dir / "froxels.vdb").string(), "--world-grid = -1 is invalid"},
      // A mention of another field in the expectation is the option too.
      {"export-vdb --world-grid 1 --out " + (dir / "froxels.vdb").string(), "(or a shorter --froxel-far-m)"},
      {"probe --altitude-m -5 --view-zenith-deg 45 --sun-zenith-deg 30 --azimuth-deg 0",
       "--altitude-m = -5 is invalid"},
      {"probe --altitude-m 1 --view-zenith-deg 200 --sun-zenith-deg 30 --azimuth-deg 0",
       "--view-zenith-deg = 200 is invalid"},
      {"precompute --quiet --transmittance-size 4096,4096",
       "transmittance size (--transmittance-size) = 4096x4096 = 16777216 texels is invalid"},
  };
  for (const Refused& c : cases) {
    SCOPED_TRACE(c.arguments);
    CommandRun run = RunAerial(c.arguments);
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << "no \"" << c.message << "\" in:\n" << run.err;
    EXPECT_EQ(run.err.find("::"), std::string::npos) << run.err;
  }
}

}  // namespace
}  // namespace aerial::testing
