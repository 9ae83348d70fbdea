#pragma once
// The fixture of the hostile-input command tests: runs `aerial` under `timeout 30`, so that a hang
// (a FIFO opened for reading or writing) is a failure, and checks its exit status and stderr.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <initializer_list>
#include <string>

#include "command_run.h"
#include "scratch_directory.h"

namespace aerial::testing {

class HostileCommand : public ::testing::Test {
 protected:
  explicit HostileCommand(const std::string& name) : dir_(name) {}

  // The command exits with status, and its stderr holds each of the texts.
  CommandRun Expect(const std::string& arguments, int status, std::initializer_list<std::string> texts,
                    const std::string& wrapper = "") {
    CommandRun run = RunAerial(arguments, "timeout 30" + (wrapper.empty() ? "" : " " + wrapper));
    EXPECT_EQ(run.exit_code, status) << arguments << "\n" << run.err;
    for (const std::string& text : texts)
      EXPECT_NE(run.err.find(text), std::string::npos) << "no \"" << text << "\" in:\n" << run.err;
    return run;
  }
  // A FIFO at name in the scratch directory.
  std::filesystem::path Fifo(const std::string& name) {
    EXPECT_EQ(::mkfifo((dir_ / name).c_str(), 0600), 0) << name;
    return dir_ / name;
  }

  ScratchDirectory dir_;
};

}  // namespace aerial::testing
