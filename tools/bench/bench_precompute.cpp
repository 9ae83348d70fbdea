// aerial_bench_precompute: GPU time of each precompute pass, as medians over several runs in one
// process, after warm-up runs (aerial/bench/precompute_measurement.h). --lut both (the default)
// measures the 4D and 3D variants in one process, their runs interleaved so that both see the
// same machine noise, and compares them.
#include <cstdio>
#include <vector>

#include <CLI/CLI.hpp>

#include "aerial/atmosphere.h"
#include "aerial/bench/precompute_measurement.h"
#include "aerial/bench/variant_comparison.h"
#include "aerial/core/atomic_file.h"
#include "aerial/bench/pass_stats.h"
#include "aerial/device.h"
#include "bench_main.h"

namespace {

struct BenchOptions {
  int runs = 5;
  int warmup = 1;
  int orders = 4;
  bool half = false;
  std::string lut = "both";
  bool small = false;
  std::string json_file;
  // Colour modes to compare, interleaved: 0 = rgb, N = spectral with N wavelengths.
  std::vector<int> wavelengths;

  std::vector<std::string> Variants() const {
    return lut == "both" ? std::vector<std::string>{"4d", "3d"} : std::vector<std::string>{lut};
  }

  aerial::PrecomputeOptions MakePrecomputeOptions(const std::string& lut_name) const {
    aerial::LutVariant variant = aerial::ParseLutVariant(lut_name, "--lut");
    aerial::PrecomputeOptions options = small ? aerial::PrecomputeOptions::Small(variant)
                                              : aerial::PrecomputeOptions::Default(variant);
    options.orders = orders;
    if (half) options.precision = aerial::TablePrecision::kFloat16;
    options.Validate();
    return options;
  }
};

// The precompute's cost per colour mode, as medians of interleaved runs and ratios to the first.
void BenchColours(const BenchOptions& cli) {
  std::vector<aerial::PrecomputeOptions> options;
  for (int n : cli.wavelengths) {
    aerial::PrecomputeOptions o = cli.MakePrecomputeOptions(cli.lut == "both" ? "4d" : cli.lut);
    o.colour = n == 0 ? aerial::ColourMode::kRgb : aerial::ColourMode::kSpectral;
    if (n != 0) o.spectral_wavelengths = n;
    o.Validate();
    options.push_back(o);
  }
  aerial::Device device;
  auto on_run = [](const aerial::bench::BenchResult& result, const aerial::bench::RunResult& run, bool warming,
                   int index) {
    std::fprintf(stderr, "%s %d (%s): %.1f ms GPU, %.1f ms wall\n", warming ? "warm-up" : "run", index,
                 result.options.Describe().c_str(), run.GpuMs(), run.wall_ms);
  };
  auto measured = aerial::bench::MeasurePrecompute(device, aerial::AtmosphereParameters::Earth(), options,
                                                   cli.warmup, cli.runs, on_run);
  std::printf("%-24s %14s %14s %10s %10s\n", "colour", "GPU ms median", "wall ms median", "GPU ratio",
              "wall ratio");
  double gpu0 = 0.0, wall0 = 0.0;
  for (size_t i = 0; i < measured.size(); ++i) {
    const aerial::bench::BenchResult& r = measured[i].result;
    double gpu = aerial::bench::Summarize(aerial::bench::GpuTotals(r.runs)).median;
    double wall = aerial::bench::Summarize(aerial::bench::WallTotals(r.runs)).median;
    if (i == 0) gpu0 = gpu, wall0 = wall;
    std::string name = cli.wavelengths[i] == 0 ? "rgb" : "spectral " + std::to_string(cli.wavelengths[i]);
    std::printf("%-24s %14.1f %14.1f %10.2f %10.2f\n", name.c_str(), gpu, wall, gpu / gpu0, wall / wall0);
  }
}

void Bench(const BenchOptions& cli) {
  if (!cli.wavelengths.empty()) return BenchColours(cli);
  std::vector<aerial::PrecomputeOptions> options;
  for (const std::string& lut : cli.Variants()) options.push_back(cli.MakePrecomputeOptions(lut));
  // Fail on an unwritable --json path now rather than after minutes of precomputation.
  if (!cli.json_file.empty()) aerial::CheckWritable(cli.json_file);
  aerial::Device device;
  auto on_run = [](const aerial::bench::BenchResult& result, const aerial::bench::RunResult& run,
                   bool warming, int index) {
    std::fprintf(stderr, "%s %d (%s): %.1f ms GPU, %.1f ms wall\n", warming ? "warm-up" : "run", index,
                 aerial::ToString(result.options.variant).c_str(), run.GpuMs(), run.wall_ms);
  };
  std::vector<aerial::bench::BenchResult> results;
  for (auto& m : aerial::bench::MeasurePrecompute(device, aerial::AtmosphereParameters::Earth(), options,
                                                  cli.warmup, cli.runs, on_run))
    results.push_back(std::move(m.result));
  if (results.size() == 1) {
    aerial::bench::PrintReport(results[0], stdout);
    if (!cli.json_file.empty()) aerial::WriteFileAtomically(cli.json_file, aerial::bench::ReportJson(results[0]));
    return;
  }
  for (const auto& result : results) {
    std::printf("%s=== %s tables ===\n", &result == &results[0] ? "" : "\n",
                aerial::ToString(result.options.variant).c_str());
    aerial::bench::PrintReport(result, stdout);
  }
  aerial::bench::PrintComparison(results[0], results[1], stdout);
  if (!cli.json_file.empty())
    aerial::WriteFileAtomically(cli.json_file, aerial::bench::ComparisonJson(results[0], results[1]));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"aerial_bench_precompute: median GPU time of each precompute pass over several runs"};
  BenchOptions cli;
  app.add_option("--runs", cli.runs, "Measured runs (the median is over these)")->check(CLI::Range(1, 1000));
  app.add_option("--warmup", cli.warmup, "Unmeasured runs first; the first one is reported as the cold time")
      ->check(CLI::Range(0, 100));
  app.add_option("--orders", cli.orders, "Scattering orders to precompute")->check(CLI::Range(1, 16));
  app.add_flag("--half", cli.half, "Store the scattering tables as 16-bit floats (the 4D default; this sets the 3D tables too)");
  app.add_option("--lut", cli.lut, "Scattering table variant: 4d, 3d, or both (interleaved runs, compared)")
      ->check(CLI::IsMember({"both", "4d", "3d"}));
  app.add_flag("--small", cli.small, "Small tables (about 1/16 of the texels), for a quick check");
  app.add_option("--colours", cli.wavelengths,
                 "Compare colour modes instead of variants: a list of wavelength counts, 0 for rgb "
                 "(e.g. 0,6,9,12,15), interleaved, with ratios to the first")
      ->delimiter(',');
  app.add_option("--json", cli.json_file, "Also write the results as JSON to this file");
  return aerial::bench::ParseAndRun(app, argc, argv, "aerial_bench_precompute", [&] { Bench(cli); });
}
