#include "aerial/core/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "aerial/error.h"

namespace aerial {
namespace {
namespace fs = std::filesystem;

// A fresh directory per test, removed afterwards, so tests can run in parallel.
class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("aerial_atomic_file_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Everything in dir_, so a test can check that no temporary was left behind.
  std::vector<std::string> Entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(dir_))
      names.push_back(entry.path().lexically_relative(dir_).string());
    std::sort(names.begin(), names.end());
    return names;
  }

  void MakeRegularFile(const fs::path& path) { std::ofstream(path) << "not a directory"; }

  fs::path dir_;
};

TEST_F(AtomicFile, WriteThenReadGivesSameBytes) {
  std::vector<std::byte> bytes(1000);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = std::byte(i * 7 + 3);
  WriteFileAtomically(dir_ / "out.bin", bytes);
  EXPECT_EQ(ReadFile(dir_ / "out.bin"), bytes);
  EXPECT_EQ(Entries(), std::vector<std::string>{"out.bin"});
}

TEST_F(AtomicFile, OverwriteReplacesWholeContent) {
  WriteFileAtomically(dir_ / "out.txt", std::string_view("a long first version"));
  WriteFileAtomically(dir_ / "out.txt", std::string_view("short"));
  std::vector<std::byte> bytes = ReadFile(dir_ / "out.txt");
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()), "short");
}

TEST_F(AtomicFile, EmptyFileRoundTrips) {
  WriteFileAtomically(dir_ / "empty", std::span<const std::byte>());
  EXPECT_TRUE(ReadFile(dir_ / "empty").empty());
}

TEST_F(AtomicFile, CreatesMissingParentDirectories) {
  WriteFileAtomically(dir_ / "a" / "b" / "out.txt", std::string_view("x"));
  EXPECT_EQ(ReadFile(dir_ / "a" / "b" / "out.txt").size(), 1u);
}

// Tests run as root, for whom permission bits do not stop a write; a parent that is a regular
// file stops everyone.
TEST_F(AtomicFile, FailedWriteThrowsNamingPathAndLeavesNoTemporary) {
  MakeRegularFile(dir_ / "blocker");
  const fs::path target = dir_ / "blocker" / "out.bin";
  try {
    WriteFileAtomically(target, std::string_view("data"));
    FAIL() << "expected aerial::Error";
  } catch (const Error& e) {
    EXPECT_EQ(e.value(), target.string());
    EXPECT_NE(std::string(e.what()).find("Not a directory"), std::string::npos) << e.what();
  }
  EXPECT_EQ(Entries(), std::vector<std::string>{"blocker"});
}

// rename() fails when the target is a non-empty directory: this happens after the temporary was
// written, so it checks the clean-up path.
TEST_F(AtomicFile, FailedRenameRemovesTemporary) {
  fs::create_directories(dir_ / "target" / "inside");
  EXPECT_THROW(WriteFileAtomically(dir_ / "target", std::string_view("data")), Error);
  EXPECT_EQ(Entries(), (std::vector<std::string>{"target", "target/inside"}));
}

TEST_F(AtomicFile, ReadMissingFileNamesPath) {
  try {
    ReadFile(dir_ / "missing.bin");
    FAIL() << "expected aerial::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.bin"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos) << e.what();
  }
}

TEST_F(AtomicFile, ReadDirectoryThrows) { EXPECT_THROW(ReadFile(dir_), Error); }

TEST_F(AtomicFile, CheckWritableAcceptsNewPathAndCreatesParent) {
  EXPECT_NO_THROW(CheckWritable(dir_ / "new" / "out.bin"));
  EXPECT_TRUE(fs::is_directory(dir_ / "new"));
  EXPECT_EQ(Entries(), std::vector<std::string>{"new"});  // the probe file is gone.
}

TEST_F(AtomicFile, CheckWritableRejectsParentThatIsAFile) {
  MakeRegularFile(dir_ / "blocker");
  EXPECT_THROW(CheckWritable(dir_ / "blocker" / "out.bin"), Error);
  EXPECT_THROW(CheckWritable(dir_ / "blocker" / "deeper" / "out.bin"), Error);
}

TEST_F(AtomicFile, CheckWritableRejectsDirectoryTarget) {
  EXPECT_THROW(CheckWritable(dir_), Error);
}

}  // namespace
}  // namespace aerial
