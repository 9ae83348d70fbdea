// A full disk, in miniature: the command runs with RLIMIT_FSIZE below what it must write and
// SIGXFSZ ignored, so its writes past the limit fail with EFBIG as they would with ENOSPC. What is
// written must be whole or not at all, and only the command's real output decides its success.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "command_run.h"

namespace aerial::testing {
namespace {

namespace fs = std::filesystem;

class FullDisk : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("aerial-full-disk-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "out");
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> Entries(const fs::path& dir) const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

std::string Contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// OpenVDB wrote through an unchecked std::ofstream: the truncated file replaced the old one and
// the command exited 0.
TEST_F(FullDisk, ExportVdbKeepsTheOldFileAndFails) {
  const std::string common = "export-vdb --small-tables --quiet --froxels 16x16x16 --cache-dir " +
                             (dir_ / "cache").string() + " --out ";
  // The tables are cached first, so that the limited run writes nothing but the VDB file.
  CommandRun warm = RunAerial(common + (dir_ / "warm.vdb").string());
  ASSERT_EQ(warm.exit_code, 0) << warm.err;
  ASSERT_GT(fs::file_size(dir_ / "warm.vdb"), 128u << 10) << "the new file must exceed the limit below";
  const fs::path out = dir_ / "out" / "froxels.vdb";
  const std::string old_bytes = "the old file, which must survive\n";
  std::ofstream(out, std::ios::binary) << old_bytes;

  // 64 KiB: the old file and the messages fit, the new file (about 190 KiB) does not.
  CommandRun run = RunAerial(common + out.string(), {.file_size_limit_bytes = 64 << 10});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("file = " + out.string() + " is invalid"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("File too large"), std::string::npos) << run.err;
  EXPECT_EQ(Contents(out), old_bytes);
  EXPECT_EQ(Entries(dir_ / "out"), std::vector<std::string>{"froxels.vdb"}) << "no temporary left";
}

// A cache write that fails for want of room warns, like a read-only cache directory, and the
// render still writes its image; it used to fail after computing the tables. With SIGXFSZ at its
// default, as under a shell's `ulimit -f`, the signal killed the command (exit status 153, no
// message, the temporary left behind): now the write fails with a named error either way.
TEST_F(FullDisk, RenderWritesItsImageWhenTheCacheDoesNotFit) {
  for (bool ignore_signal : {true, false}) {
    SCOPED_TRACE(ignore_signal ? "SIGXFSZ ignored" : "SIGXFSZ at its default");
    const fs::path cache = dir_ / (ignore_signal ? "cache" : "cache-signal"), out = dir_ / "out" / "frame.png";
    // 1 MiB: a 64x64 PNG (3 KB) fits, the small tables' cache file (4.3 MB) does not.
    CommandRun run = RunAerial("render --small-tables --quiet --width 64 --height 64 --cache-dir " +
                                   cache.string() + " --out " + out.string(),
                               RunOptions{.file_size_limit_bytes = 1 << 20, .ignore_file_size_signal = ignore_signal});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(fs::exists(out));
    EXPECT_GT(fs::file_size(out), 0u);
    EXPECT_NE(run.err.find("aerial: warning: not caching the tables (file = " + cache.string() + "/tables-"),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("File too large: the file would pass the file size limit (ulimit -f)"), std::string::npos)
        << run.err;
    EXPECT_FALSE(fs::exists(cache)) << "no partial cache file or temporary, nor the directory made for them";
    fs::remove(out);
  }
}

}  // namespace
}  // namespace aerial::testing
