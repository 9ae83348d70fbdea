// Sizes beyond what the machine can compute in reasonable time, or hold in memory, fail at once
// with a message naming the option, instead of running for minutes or ending in
// ErrorOutOfDeviceMemory.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "command_run.h"

namespace aerial::testing {
namespace {

namespace fs = std::filesystem;

// The run and how long it took, in seconds.
std::pair<CommandRun, double> TimedRun(const std::string& arguments) {
  auto start = std::chrono::steady_clock::now();
  CommandRun run = RunAerial(arguments);
  return {run, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
}

// Failing before any work takes the time to create a Vulkan context (0.1 s here, validation on);
// 10 s leaves room for a loaded machine and is far below what the work takes (a 16384x16384
// render ended in ErrorOutOfDeviceMemory after ~1 min; 4096x4096 tables ran for over 5 min).
constexpr double kBeforeAnyWorkS = 10.0;

void ExpectRejected(const std::string& arguments, const std::vector<std::string>& mentions) {
  SCOPED_TRACE(arguments);
  auto [run, seconds] = TimedRun(arguments);
  EXPECT_EQ(run.exit_code, 1) << run.err;
  for (const std::string& text : mentions) EXPECT_NE(run.err.find(text), std::string::npos) << text << "\n" << run.err;
  EXPECT_LT(seconds, kBeforeAnyWorkS);
}

TEST(ResourceLimits, TablesBeyondTheTexelCapsFailBeforeAnyWork) {
  ExpectRejected("precompute --quiet --transmittance-size 4096,4096 --irradiance-size 4096,4096",
                 {"transmittance size (--transmittance-size) = 4096x4096 = 16777216 texels",
                  "at most 1048576 texels"});
  ExpectRejected("precompute --quiet --irradiance-size 4096,4096",
                 {"irradiance size (--irradiance-size) = 4096x4096", "at most 16384 texels"});
  ExpectRejected("probe --quiet --scattering-size 256,512,64,8 --altitude-m 1 --view-zenith-deg 45 "
                 "--sun-zenith-deg 30 --azimuth-deg 0",
                 {"scattering size (--scattering-size) = 256x512x64x8", "at most 4194304 texels"});
}

}  // namespace
}  // namespace aerial::testing
