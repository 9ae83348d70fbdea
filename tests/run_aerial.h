#pragma once
// Runs the built aerial command (AERIAL_EXE) as users run it, for the command-line tests.
#include <string>

namespace aerial::testing {

struct CommandRun {
  int exit_code;
  std::string out;
  std::string err;
};

// arguments: the command line after "aerial", as a shell would split it.
CommandRun RunAerial(const std::string& arguments);

}  // namespace aerial::testing
