// Hostile input files (issue 13): each is refused by the command with exit status 1 and a
// message naming the field and the value; never a crash, a hang or a raw std:: exception. Huge
// and special files (FIFOs, devices, directories) are made here at run time.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "aerial/core/input_limits.h"
#include "command_run.h"
#include "scratch_directory.h"

namespace aerial::testing {
namespace {

namespace fs = std::filesystem;

// Files made at run time in a fresh directory.
class HostileFiles : public ::testing::Test {
 protected:
  fs::path Write(const std::string& name, const std::string& bytes) {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return dir_ / name;
  }
  fs::path Fifo(const std::string& name) {
    fs::path path = dir_ / name;
    EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0);
    return path;
  }
  // A file of size bytes that takes no disk space (sparse).
  fs::path Sparse(const std::string& name, uintmax_t size) {
    fs::path path = Write(name, "");
    fs::resize_file(path, size);
    return path;
  }

  ScratchDirectory dir_{"hostile"};
};

const char* kOut = "/tmp/aerial-hostile-test.png";
const std::string kRender = std::string("render --small-tables --quiet --out ") + kOut;
const std::string kPrecompute = "precompute --small-tables --quiet --no-cache";

// The command: exit status 1, a message naming the option and the reason, and no image. These
// refusals come before any GPU work and take well under a second; `timeout 30` turns a read that
// blocks or never ends (the old /dev/zero) into a failure (status 124) instead of a hang.
void ExpectRefused(const std::string& arguments, const std::string& field,
                   const std::string& reason) {
  fs::remove(kOut);
  CommandRun run = RunAerial(arguments, "timeout 30");
  EXPECT_FALSE(fs::exists(kOut)) << arguments;
  EXPECT_EQ(run.exit_code, 1) << arguments << "\n" << run.err;
  EXPECT_NE(run.err.find(field), std::string::npos) << "no " << field << " in:\n" << run.err;
  EXPECT_NE(run.err.find(reason), std::string::npos) << "no " << reason << " in:\n" << run.err;
}

TEST_F(HostileFiles, CommandRefusesDevZero) {
  ExpectRefused(kPrecompute + " --atmosphere /dev/zero", "--atmosphere = /dev/zero",
                "not a character device");
  ExpectRefused(kRender + " --scene /dev/zero", "--scene = /dev/zero", "not a character device");
}

TEST_F(HostileFiles, CommandRefusesAFifoWithoutBlocking) {
  fs::path fifo = Fifo("scene.toml");
  ExpectRefused(kRender + " --scene " + fifo.string(), "--scene = " + fifo.string(),
                "not a FIFO (named pipe)");
  ExpectRefused("view --camera-path " + fifo.string(), "--camera-path = " + fifo.string(),
                "not a FIFO (named pipe)");
}

TEST_F(HostileFiles, CommandRefusesADirectory) {
  ExpectRefused(kPrecompute + " --atmosphere " + dir_.path().string(),
                "--atmosphere = " + dir_.path().string(),
                "not a directory");
}

TEST_F(HostileFiles, CommandRefusesAFileOverTheTomlCap) {
  fs::path big = Sparse("big.toml", kMaxTomlFileBytes + 1);
  ExpectRefused(kRender + " --scene " + big.string(), "--scene = " + big.string(),
                "at most " + std::to_string(kMaxTomlFileBytes) + " bytes");
}

}  // namespace
}  // namespace aerial::testing
