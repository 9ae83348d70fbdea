#pragma once
// Runs the built `aerial` command as users do, for the command-line tests.
#include <sys/resource.h>

#include <optional>
#include <string>

namespace aerial::testing {

struct CommandRun {
  int exit_code;
  std::string out;
  std::string err;
};

struct RunOptions {
  // A command aerial runs under ("xvfb-run -a", "env NAME=value").
  std::string wrapper;
  // RLIMIT_FSIZE of the child, a full disk in miniature: with SIGXFSZ ignored (as the child
  // inherits it), a write past the limit fails with EFBIG instead of killing the process.
  std::optional<rlim_t> file_size_limit_bytes;
  // With the limit: false leaves SIGXFSZ at its default action (killing), as a shell's
  // `ulimit -f` does, for aerial to handle itself.
  bool ignore_file_size_signal = true;
};

// `aerial <arguments>`; stdout and stderr captured separately.
CommandRun RunAerial(const std::string& arguments, const RunOptions& options);
CommandRun RunAerial(const std::string& arguments, const std::string& wrapper = "");

}  // namespace aerial::testing
