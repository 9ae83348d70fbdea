#include "aerial/core/live_temporary.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace aerial {
namespace {

namespace fs = std::filesystem;

// Issue 41: SIGINT during a write (export-vdb's "out.vdb.tmp-*") left the temporary for good.
// The child (a fresh process: "threadsafe" death tests re-run the binary) registers a temporary
// and is interrupted mid-write; the signal still ends it.
TEST(LiveTemporaryDeathTest, SigintRemovesTheTemporaryAndStillEndsTheProgram) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  fs::path path = fs::temp_directory_path() / ("aerial-live-temporary-" + std::to_string(::getpid()));
  EXPECT_EXIT(
      {
        ::signal(SIGINT, SIG_DFL);  // a test run in the background may inherit SIGINT ignored
        std::ofstream(path) << "half written";
        LiveTemporary live(path);
        ::raise(SIGINT);
      },
      ::testing::KilledBySignal(SIGINT), "");
  EXPECT_FALSE(fs::exists(path));
  fs::remove(path);
}

TEST(LiveTemporary, AnUnregisteredPathStays) {
  fs::path path = fs::temp_directory_path() / ("aerial-live-temporary-kept-" + std::to_string(::getpid()));
  std::ofstream(path) << "done";
  { LiveTemporary live(path); }
  EXPECT_TRUE(fs::exists(path));
  fs::remove(path);
}

}  // namespace
}  // namespace aerial
