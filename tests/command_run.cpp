#include "command_run.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace aerial::testing {

CommandRun RunAerial(const std::string& arguments, const RunOptions& options) {
  std::string err_file = std::filesystem::temp_directory_path() / ("aerial-cli-" + std::to_string(::getpid()));
  std::string command = options.wrapper + (options.wrapper.empty() ? "" : " ") + std::string(AERIAL_EXE) +
                        " " + arguments + " 2>" + err_file;
  int out[2];
  if (::pipe(out) != 0) throw std::runtime_error("pipe failed");
  pid_t child = ::fork();
  if (child < 0) throw std::runtime_error("fork failed");
  if (child == 0) {
    // Only async-signal-safe calls between fork and exec (the test process has threads).
    ::dup2(out[1], STDOUT_FILENO);
    ::close(out[0]);
    ::close(out[1]);
    if (options.file_size_limit_bytes) {
      ::signal(SIGXFSZ, options.ignore_file_size_signal ? SIG_IGN : SIG_DFL);
      struct rlimit limit = {*options.file_size_limit_bytes, *options.file_size_limit_bytes};
      if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(126);
    }
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(out[1]);
  CommandRun run{};
  std::array<char, 4096> buffer;
  for (;;) {
    ssize_t n = ::read(out[0], buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    run.out.append(buffer.data(), size_t(n));
  }
  ::close(out[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_file);
  run.err.assign(std::istreambuf_iterator<char>(err), {});
  std::filesystem::remove(err_file);
  return run;
}

CommandRun RunAerial(const std::string& arguments, const std::string& wrapper) {
  return RunAerial(arguments, RunOptions{.wrapper = wrapper});
}

}  // namespace aerial::testing
