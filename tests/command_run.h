#pragma once
// Runs the built `aerial` command as users do, for the command-line tests.
#include <string>

namespace aerial::testing {

struct CommandRun {
  int exit_code;
  std::string out;
  std::string err;
};

// `aerial <arguments>`, optionally under a wrapper command ("xvfb-run -a"); stdout and stderr
// captured separately.
CommandRun RunAerial(const std::string& arguments, const std::string& wrapper = "");

}  // namespace aerial::testing
