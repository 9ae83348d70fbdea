#pragma once
// Each subcommand registers its options and its action on the root application.
#include <CLI/CLI.hpp>

namespace aerial::cli {

void AddBenchCommand(CLI::App& app);
void AddPrecomputeCommand(CLI::App& app);
void AddProbeCommand(CLI::App& app);
void AddRenderCommand(CLI::App& app);
void AddExportVdbCommand(CLI::App& app);
void AddEnvmapCommand(CLI::App& app);
void AddViewCommand(CLI::App& app);

}  // namespace aerial::cli
