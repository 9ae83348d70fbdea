#include "aerial/core/bounded_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "aerial/error.h"
#include "tests/scratch_directory.h"

namespace aerial {
namespace {

namespace fs = std::filesystem;

class BoundedFile : public ::testing::Test {
 protected:
  testing::ScratchDirectory dir_{"bounded_file"};
};

// The Error ReadBoundedFile(path, "--scene", max_bytes) throws.
Error ErrorOf(const fs::path& path, size_t max_bytes) {
  try {
    ReadBoundedFile(path, "--scene", max_bytes);
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no error for " << path;
  return Error("", "", "");
}

TEST_F(BoundedFile, ReadsAFileUpToTheCapWhole) {
  fs::path path = dir_ / "ten.txt";
  std::ofstream(path) << "0123456789";
  std::vector<unsigned char> bytes = ReadBoundedFile(path, "--scene", 10);
  EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "0123456789");
}

TEST_F(BoundedFile, RefusesAFileOneByteOverTheCap) {
  fs::path path = dir_ / "big.toml";
  std::ofstream(path) << "0123456789";
  Error e = ErrorOf(path, 9);
  EXPECT_EQ(e.field(), "--scene");
  EXPECT_EQ(e.value(), path.string());
  EXPECT_EQ(e.allowed(), "a regular file of at most 9 bytes (it has 10)");
}

TEST_F(BoundedFile, StopsReadingAFileLargerThanItsStatSize) {
  // Files under /proc report size 0 but have content, as a file growing while read would: the
  // read loop itself must stop at the cap (status is over 500 bytes on any Linux).
  Error e = ErrorOf("/proc/self/status", 16);
  EXPECT_EQ(e.allowed(), "a regular file of at most 16 bytes (it grew past that while read)");
}

TEST_F(BoundedFile, RefusesNonRegularFilesByKind) {
  EXPECT_EQ(ErrorOf(dir_.path(), 100).allowed(), "a regular file, not a directory");
  EXPECT_EQ(ErrorOf("/dev/zero", 100).allowed(), "a regular file, not a character device");
  // A FIFO is refused without opening it: opening it would block, as there is no writer. Should
  // that regress, SIGALRM ends this test's process after 10 s instead of letting it hang.
  fs::path fifo = dir_ / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  ::alarm(10);
  EXPECT_EQ(ErrorOf(fifo, 100).allowed(), "a regular file, not a FIFO (named pipe)");
  ::alarm(0);
}

TEST_F(BoundedFile, MissingFileGivesTheReason) {
  Error e = ErrorOf(dir_ / "none.toml", 100);
  EXPECT_EQ(e.value(), (dir_ / "none.toml").string());
  EXPECT_EQ(e.allowed(), "a readable file (No such file or directory)");
}

}  // namespace
}  // namespace aerial
