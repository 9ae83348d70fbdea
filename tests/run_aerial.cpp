#include "run_aerial.h"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace aerial::testing {

CommandRun RunAerial(const std::string& arguments) {
  std::string err_file =
      std::filesystem::temp_directory_path() / ("aerial-cli-" + std::to_string(::getpid()));
  std::string command = std::string(AERIAL_EXE) + " " + arguments + " 2>" + err_file;
  CommandRun run{};
  FILE* pipe = ::popen(command.c_str(), "r");
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) run.out.append(buffer.data(), n);
  int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_file);
  run.err.assign(std::istreambuf_iterator<char>(err), {});
  std::filesystem::remove(err_file);
  return run;
}

}  // namespace aerial::testing
