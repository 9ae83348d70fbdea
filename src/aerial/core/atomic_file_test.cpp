#include "aerial/core/atomic_file.h"

#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
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

// The check makes nothing (before, it made the missing directories, which a SIGTERM'd bench then
// left behind, empty); the write makes them.
TEST_F(AtomicFile, CheckWritableAcceptsNewPathAndMakesNothing) {
  EXPECT_NO_THROW(CheckWritable(dir_ / "new" / "deeper" / "out.bin"));
  EXPECT_TRUE(Entries().empty());  // no directory, and the probe file is gone
  WriteFileAtomically(dir_ / "new" / "deeper" / "out.bin", std::string_view("x"));
  EXPECT_EQ(Entries(), (std::vector<std::string>{"new", "new/deeper", "new/deeper/out.bin"}));
}

TEST_F(AtomicFile, CheckWritableRejectsParentThatIsAFile) {
  MakeRegularFile(dir_ / "blocker");
  EXPECT_THROW(CheckWritable(dir_ / "blocker" / "out.bin"), Error);
  EXPECT_THROW(CheckWritable(dir_ / "blocker" / "deeper" / "out.bin"), Error);
}

TEST_F(AtomicFile, CheckWritableRejectsDirectoryTarget) {
  EXPECT_THROW(CheckWritable(dir_), Error);
}

// Outputs write into what exists, or refuse it.

TEST_F(AtomicFile, ReplacedFileKeepsItsModeAndOwner) {
  WriteFileAtomically(dir_ / "out.txt", std::string_view("old"));
  fs::permissions(dir_ / "out.txt", fs::perms::owner_read | fs::perms::owner_write);  // 0600
  ASSERT_EQ(::chown((dir_ / "out.txt").c_str(), 1234, 5678), 0);  // tests run as root
  WriteFileAtomically(dir_ / "out.txt", std::string_view("new"));
  struct stat info;
  ASSERT_EQ(::stat((dir_ / "out.txt").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 07777, 0600u) << "the replacement must keep the mode, not take 0644";
  EXPECT_EQ(info.st_uid, 1234u);
  EXPECT_EQ(info.st_gid, 5678u);
}

TEST_F(AtomicFile, WriteThroughASymlinkReplacesItsTargetAndKeepsTheLink) {
  WriteFileAtomically(dir_ / "target.txt", std::string_view("old"));
  fs::create_symlink("target.txt", dir_ / "link.txt");
  WriteFileAtomically(dir_ / "link.txt", std::string_view("new"));
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.txt"));
  EXPECT_EQ(ReadFile(dir_ / "target.txt").size(), 3u);
  EXPECT_EQ(Entries(), (std::vector<std::string>{"link.txt", "target.txt"}));
}

// A FIFO, or a symlink to a device, is refused by name: as root, renaming over /dev/null would
// replace the system's /dev/null. (Checked through a link, so that a regression replaces only
// the link.)
TEST_F(AtomicFile, SpecialFilesAreRefusedByNameNotReplaced) {
  ASSERT_EQ(::mkfifo((dir_ / "fifo").c_str(), 0600), 0);
  fs::create_symlink("/dev/null", dir_ / "null");
  for (const auto& [name, kind] : {std::pair{"fifo", "not a FIFO (named pipe)"},
                                   std::pair{"null", "not a character device"}}) {
    for (auto write : {+[](const fs::path& p) { WriteFileAtomically(p, std::string_view("x")); },
                       +[](const fs::path& p) { CheckWritable(p); }}) {
      try {
        write(dir_ / name);
        ADD_FAILURE() << name << " accepted";
      } catch (const Error& e) {
        EXPECT_NE(e.allowed().find(kind), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_TRUE(fs::is_fifo(dir_ / "fifo"));
  EXPECT_TRUE(fs::is_symlink(dir_ / "null"));
  EXPECT_EQ(Entries(), (std::vector<std::string>{"fifo", "null"})) << "no temporary left";
}

TEST_F(AtomicFile, CheckOutputFileCreatesNothing) {
  try {
    CheckOutputFile(dir_ / "missing" / "dir" / "s.json", "--stats");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "--stats");
    EXPECT_EQ(e.value(), (dir_ / "missing" / "dir" / "s.json").string());
  }
  EXPECT_TRUE(Entries().empty()) << "a refused output must not create its directory chain";
  EXPECT_THROW(CheckOutputFile("", "--stats"), Error);
  EXPECT_NO_THROW(CheckOutputFile(dir_ / "s.json", "--stats"));
}

// A pid that names no process in this pid namespace.
pid_t DeadPid() {
  pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);  // reaped: its pid names no process now
  return dead;
}

// A write removes the temporaries that killed writers of the same path left, whatever the output
// (not only the table cache's): nothing holds their lock.
TEST_F(AtomicFile, StaleTemporariesOfTheTargetAreRemovedByTheNextWrite) {
  MakeRegularFile(dir_ / ("out.vdb.tmp-" + std::to_string(DeadPid()) + "-0123456789abcdef"));
  MakeRegularFile(dir_ / ("out.vdb.tmp-" + std::to_string(::getpid()) + "-0123456789abcdee"));
  WriteFileAtomically(dir_ / "out.vdb", std::string_view("x"));
  EXPECT_EQ(Entries(), std::vector<std::string>{"out.vdb"});
}

// A writer in another pid namespace (a container sharing the cache) or on another host has a pid
// that names no process here, or another one: only its lock tells it is alive. Before, the sweep
// judged by the pid and removed the live writer's file, whose rename then failed.
TEST_F(AtomicFile, ATemporaryWhoseWriterHoldsItsLockIsKeptWhateverItsPid) {
  const std::string live = "out.vdb.tmp-" + std::to_string(DeadPid()) + "-0123456789abcdef";
  MakeRegularFile(dir_ / live);
  int writer = ::open((dir_ / live).c_str(), O_WRONLY | O_CLOEXEC);  // as the other writer holds it
  ASSERT_GE(writer, 0);
  ASSERT_EQ(::flock(writer, LOCK_EX), 0);
  WriteFileAtomically(dir_ / "out.vdb", std::string_view("x"));
  EXPECT_TRUE(RemoveStaleTemporaries(dir_, "out.vdb").empty());
  EXPECT_EQ(Entries(), (std::vector<std::string>{"out.vdb", live}));
  ::close(writer);  // the writer is gone: now the temporary is stale
  EXPECT_EQ(RemoveStaleTemporaries(dir_, "out.vdb"), std::vector<fs::path>{dir_ / live});
}

// A name of 244 bytes is valid (up to 255), but "<name>.tmp-<pid>-<16 digits>" is not: the
// temporary's name is cut, and both the check and the write succeed. Before, the check refused
// the path, blaming the user's name ("File name too long").
TEST_F(AtomicFile, AnyValidNameCanBeWritten) {
  for (size_t length : {244u, 255u}) {
    const fs::path path = dir_ / (std::string(length - 4, 'n') + ".png");
    EXPECT_NO_THROW(CheckOutputFile(path, "--out")) << length;
    EXPECT_NO_THROW(CheckWritable(path)) << length;
    WriteFileAtomically(path, std::string_view("x"));
    EXPECT_EQ(ReadFile(path).size(), 1u);
    fs::remove(path);
  }
  EXPECT_TRUE(Entries().empty()) << "no temporary left";
}

// A symbolic link to a file that does not exist yet: the file is written where it points, and
// the link kept (before, the link was replaced by a regular file).
TEST_F(AtomicFile, WriteThroughADanglingLinkMakesItsFileAndKeepsTheLink) {
  fs::create_directories(dir_ / "real");
  fs::create_symlink("real/frame.png", dir_ / "link.png");
  EXPECT_NO_THROW(CheckOutputFile(dir_ / "link.png", "--out"));
  WriteFileAtomically(dir_ / "link.png", std::string_view("new"));
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.png"));
  EXPECT_EQ(ReadFile(dir_ / "real" / "frame.png").size(), 3u);
  EXPECT_EQ(OutputTarget(dir_ / "link.png"), dir_ / "real/frame.png");
  // A link into a directory that does not exist is refused by the output check, as a path there.
  fs::create_symlink("missing/frame.png", dir_ / "nowhere.png");
  EXPECT_THROW(CheckOutputFile(dir_ / "nowhere.png", "--out"), Error);
}

}  // namespace
}  // namespace aerial
