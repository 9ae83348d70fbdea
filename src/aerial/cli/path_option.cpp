#include "aerial/cli/path_option.h"

#include "aerial/error.h"

namespace aerial::cli {

CLI::Option* AddPathOption(CLI::App& command, const std::string& name, std::filesystem::path& path,
                           const std::string& help) {
  auto not_empty = [name](const std::string& value) -> std::string {
    if (value.empty()) throw Error(name, "", "a path");
    return "";
  };
  return command.add_option(name, path, help)->check(CLI::Validator(not_empty, "PATH"));
}

}  // namespace aerial::cli
