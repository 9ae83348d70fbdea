#include "aerial/core/live_temporary.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <string>

#include <filesystem>
#include <fstream>

namespace aerial {
namespace {

namespace fs = std::filesystem;

int OpenDirectory(const fs::path& path) { return ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); }

// The death tests' files are in the working directory (the build's), under names without a pid:
// the child, a fresh process ("threadsafe" death tests re-run the binary), runs the test from its
// start and must name the same files as its parent.

// SIGINT during a write (export-vdb's "out.vdb.tmp-*") left the temporary for good. The child
// registers a temporary and is interrupted mid-write; the signal still ends it.
TEST(LiveTemporaryDeathTest, SigintRemovesTheTemporaryAndStillEndsTheProgram) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  fs::path dir = fs::current_path();
  std::string name = "aerial-live-temporary-test.tmp";
  EXPECT_EXIT(
      {
        ::signal(SIGINT, SIG_DFL);  // a test run in the background may inherit SIGINT ignored
        std::ofstream(dir / name) << "half written";
        LiveTemporary live(OpenDirectory(dir), name);
        ::raise(SIGINT);
      },
      ::testing::KilledBySignal(SIGINT), "");
  EXPECT_FALSE(fs::exists(dir / name));
  fs::remove(dir / name);
}

// The directories a write made go too, newest first, but only while empty. Before, SIGTERM during
// bench left its --out directory chain behind.
TEST(LiveTemporaryDeathTest, SigtermRemovesTheDirectoriesMadeForTheWrite) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  fs::path dir = fs::current_path() / "aerial-live-directories-test";
  fs::remove_all(dir);
  fs::create_directories(dir / "kept");
  EXPECT_EXIT(
      {
        ::signal(SIGTERM, SIG_DFL);
        fs::create_directories(dir / "a" / "b");
        LiveTemporary a(OpenDirectory(dir), "a", true);
        LiveTemporary b(OpenDirectory(dir / "a"), "b", true);
        std::ofstream(dir / "a" / "b" / "t.tmp") << "half written";
        LiveTemporary t(OpenDirectory(dir / "a" / "b"), "t.tmp");
        std::ofstream(dir / "kept" / "done") << "a finished output";
        LiveTemporary kept(OpenDirectory(dir), "kept", true);
        ::raise(SIGTERM);
      },
      ::testing::KilledBySignal(SIGTERM), "");
  EXPECT_FALSE(fs::exists(dir / "a"));
  EXPECT_TRUE(fs::exists(dir / "kept" / "done")) << "a directory with a file in it stays";
  fs::remove_all(dir);
}

// In a child: under a 1 KiB file size limit with SIGXFSZ at its default, a writer registers its
// temporary and writes 4 KiB. Exits 0 when the write stopped at the limit with EFBIG.
void WritePastTheFileSizeLimit(const fs::path& path) {
  ::signal(SIGXFSZ, SIG_DFL);
  struct rlimit limit {};
  limit.rlim_cur = limit.rlim_max = 1024;
  ::setrlimit(RLIMIT_FSIZE, &limit);
  std::ofstream(path) << "x";
  LiveTemporary live(OpenDirectory(path.parent_path()), path.filename().string());
  std::string big(4096, 'x');
  int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  bool efbig = ::write(fd, big.data(), big.size()) == 1024 && ::write(fd, big.data(), 1) < 0 && errno == EFBIG;
  ::_exit(efbig ? 0 : 1);
}

// With SIGXFSZ at its default, a write past `ulimit -f` killed the program without a word (exit
// 153); now it fails with EFBIG, which the writer names.
TEST(LiveTemporaryDeathTest, AWritePastTheFileSizeLimitFailsInsteadOfKilling) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  fs::path path = fs::current_path() / "aerial-file-size-test.tmp";
  EXPECT_EXIT(WritePastTheFileSizeLimit(path), ::testing::ExitedWithCode(0), "");
  fs::remove(path);
}

TEST(LiveTemporary, AnUnregisteredPathStays) {
  fs::path dir = fs::temp_directory_path();
  std::string name = "aerial-live-temporary-kept-" + std::to_string(::getpid());
  std::ofstream(dir / name) << "done";
  int fd = OpenDirectory(dir);
  { LiveTemporary live(fd, name); }
  ::close(fd);
  EXPECT_TRUE(fs::exists(dir / name));
  fs::remove(dir / name);
}

}  // namespace
}  // namespace aerial
