#pragma once
// Every option that names a file or directory is added here, so each refuses an empty path the
// same way: `--stats ""` would otherwise read as "no --stats" and do nothing, silently.
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

namespace aerial::cli {

// command.add_option(name, path, help), refusing an empty value with
// Error(name, "", "a path") (exit status 1, as for any bad value).
CLI::Option* AddPathOption(CLI::App& command, const std::string& name, std::filesystem::path& path,
                           const std::string& help);

}  // namespace aerial::cli
