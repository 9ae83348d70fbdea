// aerial: physically based sky and aerial perspective. Errors from any boundary (configs, CLI
// values, files, Vulkan) arrive here as exceptions, are printed once (the library's under the
// options that set what they name) and turn into exit status 1; a command line that does not
// parse exits with 2 (the footer of --help).
#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include <CLI/CLI.hpp>
#include <vulkan/vulkan.hpp>  // the out-of-memory exceptions below

#include "aerial/cli/commands.h"
#include "aerial/cli/huge_pages.h"
#include "aerial/cli/option_names.h"
#include "aerial/cli/option_values.h"
#include "aerial/device.h"
#include "aerial/error.h"
#include "aerial/version.h"

namespace {

constexpr int kUsageError = 2;

int Fail(const std::exception& e) {
  std::fprintf(stderr, "aerial: error: %s\n", aerial::Printable(e.what()).c_str());
  return 1;
}

// The last resort when memory runs out: the estimates checked against --max-memory-mib before
// allocating should have caught it first.
aerial::Error OutOfMemory(const std::string& memory, const std::string& reason) {
  return aerial::Error(memory, reason,
                       "sizes that fit: lower --width/--height, --froxels or the table sizes, or a "
                       "--max-memory-mib that this machine has, so that the estimate stops it first");
}

}  // namespace

int main(int argc, char** argv) {
  aerial::cli::RestartWithHugePages(argv);
  CLI::App app{"aerial: precomputed atmospheric scattering (Bruneton 2008) on Vulkan"};
  app.require_subcommand(1);
  app.set_version_flag("--version", AERIAL_VERSION);
  app.option_defaults()->always_capture_default();  // every command's --help shows its defaults
  app.footer("Exit status: 0 done; 1 a run-time error (a bad value, file, config or device: the message "
             "names it); 2 a usage error (an unknown command or option, a missing or malformed value); 3 "
             "Vulkan validation messages (with --validation).\n");
  aerial::cli::AddPrecomputeCommand(app);
  aerial::cli::AddProbeCommand(app);
  aerial::cli::AddRenderCommand(app);
  aerial::cli::AddExportVdbCommand(app);
  aerial::cli::AddEnvmapCommand(app);
  aerial::cli::AddViewCommand(app);
  aerial::cli::AddBenchCommand(app);
  aerial::cli::RefuseNonFiniteNumbers(app);
  // CLI11 reports a mistyped command only as "a subcommand is required": name it instead.
  if (argc > 1 && argv[1][0] != '-') {
    std::string commands;
    bool known = false;
    for (const CLI::App* command : app.get_subcommands({})) {
      commands += (commands.empty() ? "" : ", ") + command->get_name();
      known = known || command->get_name() == argv[1];
    }
    if (!known) {
      std::fprintf(stderr, "aerial: error: command = %s is invalid; expected one of: %s\n",
                   aerial::Printable(argv[1]).c_str(), commands.c_str());
      return kUsageError;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version end here too, with status 0; a real parse error is said in aerial's
    // own form, not CLI11's.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "aerial: error: %s (aerial --help lists the commands, aerial COMMAND --help "
                 "their options)\n", aerial::Printable(e.what()).c_str());
    return kUsageError;
  } catch (const aerial::Error& e) {
    return Fail(aerial::cli::AsTyped(aerial::cli::WithOptionNames(e), app));
  } catch (const ::vk::OutOfDeviceMemoryError& e) {
    return Fail(OutOfMemory("device memory", e.what()));
  } catch (const ::vk::OutOfHostMemoryError& e) {
    return Fail(OutOfMemory("host memory", e.what()));
  } catch (const std::bad_alloc& e) {
    return Fail(OutOfMemory("host memory", e.what()));
  } catch (const std::exception& e) {
    return Fail(e);
  }
  // With validation on, any message is a failure even if the command otherwise succeeded.
  if (int messages = aerial::Device::ValidationMessageCount(); messages > 0) {
    std::fprintf(stderr, "aerial: error: %d Vulkan validation message(s)\n", messages);
    return 3;
  }
  return 0;
}
