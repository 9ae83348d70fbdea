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

#include "aerial/vk/context.h"
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

TEST(ResourceLimits, OverTheDefaultBudgetFailsBeforeAnyWork) {
  ExpectRejected("render --width 16384 --height 16384 --out /tmp/aerial-budget-test.png",
                 {"--width/--height = 16384x16384 is invalid",
                  "--width/--height 16384x16384: render targets, read-back and encoded image 21505.0 MiB",
                  "> budget 2048.0 MiB (the default"});
  EXPECT_FALSE(fs::exists("/tmp/aerial-budget-test.png"));
  ExpectRejected("export-vdb --froxels 256x256x256 --out /tmp/aerial-budget-test.vdb",
                 {"--froxels = 256x256x256 is invalid", "froxel export copies 5120.0 MiB",
                  "> budget 2048.0 MiB"});
  // The viewer checks before opening its window, so this needs no display.
  ExpectRejected("view --width 16384 --height 16384",
                 {"--width/--height = 16384x16384 is invalid", "swapchain images 4096.0 MiB",
                  "> budget 2048.0 MiB"});
}

// A budget beyond what the device has lets the allocation fail: the last resort names what ran out
// and what to lower, instead of the bare ErrorOutOfDeviceMemory. (lavapipe refuses the 4 GiB
// radiance target of a 16384x16384 frame at once.) The largest frame the options allow has a
// 4 GiB target; a device that can allocate that and hold the whole frame (21505 MiB, the estimate
// above) renders it, so there the test says why it cannot run.
TEST(ResourceLimits, OutOfDeviceMemoryIsANamedError) {
  {
    vk::Context context;
    constexpr uint64_t kLargestTarget = 16384ull * 16384 * 16, kLargestFrame = 21505ull << 20;
    auto properties = context.physical_device().getProperties2<::vk::PhysicalDeviceProperties2,
                                                               ::vk::PhysicalDeviceMaintenance3Properties>();
    uint64_t largest_allocation = properties.get<::vk::PhysicalDeviceMaintenance3Properties>().maxMemoryAllocationSize;
    if (largest_allocation >= kLargestTarget && context.largest_heap_bytes() >= kLargestFrame)
      GTEST_SKIP() << "this device allocates " << (largest_allocation >> 20) << " MiB at once and has "
                   << (context.largest_heap_bytes() >> 20)
                   << " MiB: the largest frame the options allow fits, so nothing runs out of memory";
  }
  CommandRun run = RunAerial("render --small-tables --quiet --width 16384 --height 16384 "
                             "--max-memory-mib 100000 --out /tmp/aerial-budget-test.png");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("aerial: error: device memory = vk::Image::bindMemory: ErrorOutOfDeviceMemory is "
                         "invalid; expected sizes that fit: lower --width/--height"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists("/tmp/aerial-budget-test.png"));
}

// The estimate of a 1152x1152 render with small spectral tables is 270.7 MiB (printed in the message;
// its frame, not the spectral scratch, is the largest part):
// 128 MiB rejects it, 512 MiB lets it render.
TEST(ResourceLimits, MaxMemoryMibSetsTheBudget) {
  fs::path out = fs::temp_directory_path() / ("aerial-budget-" + std::to_string(::getpid()) + ".png");
  const std::string render = "render --small-tables --quiet --width 1152 --height 1152 --out " + out.string();
  ExpectRejected(render + " --max-memory-mib 128",
                 {"--width/--height = 1152x1152 is invalid", "estimated 265.2 MiB", "> budget 128.0 MiB (--max-memory-mib 128)"});
  EXPECT_FALSE(fs::exists(out));
  CommandRun run = RunAerial(render + " --max-memory-mib 512");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(out));
  fs::remove(out);
}

}  // namespace
}  // namespace aerial::testing
