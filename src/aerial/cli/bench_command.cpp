// aerial bench: the 3D and 4D tables compared on this machine, in one process: table memory,
// precompute and frame times, and accuracy in five views against each other and against the CPU
// reference. Writes report.md, results.json, results.csv and PNG figures into --out (checked
// before the work, each file written atomically).
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <thread>

#include "aerial/bench/bench_output.h"
#include "aerial/bench/bench_run.h"
#include "aerial/cli/commands.h"
#include "aerial/cli/path_option.h"
#include "aerial/cli/scene_options.h"
#include "aerial/error.h"
#include "aerial/version.h"

namespace aerial::cli {
namespace {

struct BenchCommandOptions {
  bool quick = false;
  std::filesystem::path out = "bench-out";
  std::string device;
  bool validation = false;
  bool quiet = false;
  std::string shadows = "on";
  std::string colour = "spectral";

  // The command line that reproduces this run.
  std::string Command() const {
    std::string command = "aerial bench";
    if (quick) command += " --quick";
    command += " --out " + out.string();
    if (!device.empty()) command += " --device \"" + device + "\"";
    if (validation) command += " --validation";
    if (shadows != "on") command += " --shadows " + shadows;
    if (colour != "spectral") command += " --colour " + colour;
    return command;
  }
};

std::string UtcNow() {
  std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &utc);
  return text;
}

// The first three fields of /proc/loadavg, or "unknown".
std::string LoadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  if (!(in >> one >> five >> fifteen)) return "unknown";
  return one + " " + five + " " + fifteen;
}

void RunBenchCommand(const BenchCommandOptions& options) {
  // Values first: a bad one must not leave the --out directory chain behind.
  bench::BenchPlan plan = options.quick ? bench::BenchPlan::Quick() : bench::BenchPlan::Full();
  plan.shadows = ParseShadows(options.shadows);
  plan.colour = ParseColourMode(options.colour, "--colour");
  bench::CheckOutputDirectory(options.out, plan);
  Device device(DeviceOptions{.device_name = options.device, .validation = options.validation});
  bench::MachineInfo machine{.device = device.name(),
                             .date = UtcNow(),
                             .command = options.Command(),
                             .version = AERIAL_VERSION,
                             .cores = int(std::thread::hardware_concurrency()),
                             .validation = device.validation_enabled(),
                             .load_before = LoadAverage()};
  bench::BenchResults results = bench::RunBench(plan, device, machine, options.quiet);
  results.machine.load_after = LoadAverage();
  bench::WriteBenchOutputs(options.out, results);
  std::printf("aerial bench: %s mode, %.0f s; wrote %s\n", plan.quick ? "quick" : "full", results.seconds,
              Printable((options.out / "report.md").native()).c_str());
}

}  // namespace

void AddBenchCommand(CLI::App& app) {
  auto options = std::make_shared<BenchCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "bench", "Compare the 3D and 4D tables on this machine: memory, speed and accuracy, as a report");
  command->add_flag("--quick", options->quick,
                    "Small tables, few frames, small images, few reference pixels (about 3 minutes on 2 CPU "
                    "cores with lavapipe)");
  AddPathOption(*command, "--out", options->out, "Output directory (default bench-out; created if missing)");
  command->add_option("--device", options->device,
                      "Vulkan device to use: part of its name (or AERIAL_DEVICE)");
  command->add_flag("--validation", options->validation,
                    "Enable the Vulkan validation layers (or AERIAL_VALIDATION=1); inflates every time");
  command->add_flag("--quiet", options->quiet, "No progress bar");
  command->add_option("--shadows", options->shadows,
                      "The sun's shadow map in the timed frames: on (default) or off (the accuracy renders "
                      "never have it: the CPU reference has no shadows)");
  command->add_option("--colour", options->colour,
                      "What the tables' channels hold: spectral (default: 12 wavelengths converted with the "
                      "CIE 1931 observer, against the spectral reference) or rgb (the three wavelengths)")
      ->check(CLI::IsMember({"rgb", "spectral"}));
  command->callback([options] { RunBenchCommand(*options); });
}

}  // namespace aerial::cli
