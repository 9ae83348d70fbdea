// aerial_bench_precompute: GPU time of each precompute pass, as medians over several runs in one
// process. The first Precompute of a process also pays lavapipe's JIT compilation of every
// pipeline (tens to hundreds of ms per pass), so warm-up runs come first and the first of them is
// reported apart as the cold time. --lut both (the default) measures the 4D and 3D variants in
// one process, their runs interleaved so that both see the same machine noise, and compares them.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench_main.h"
#include "aerial/atmosphere/parameters.h"
#include "aerial/core/atomic_file.h"
#include "aerial/core/error.h"
#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/precompute/precomputer.h"
#include "aerial/vk/context.h"
#include "comparison.h"
#include "report.h"

namespace {

struct BenchOptions {
  int runs = 5;
  int warmup = 1;
  int orders = 4;
  bool half = false;
  std::string lut = "both";
  bool small = false;
  std::string json_file;

  std::vector<std::string> Variants() const {
    return lut == "both" ? std::vector<std::string>{"4d", "3d"} : std::vector<std::string>{lut};
  }

  aerial::PrecomputeOptions MakePrecomputeOptions(const std::string& lut_name) const {
    aerial::LutVariant variant = aerial::ParseLutVariant(lut_name, "--lut");
    aerial::PrecomputeOptions options = small ? aerial::PrecomputeOptions::Small(variant)
                                              : aerial::PrecomputeOptions::Default(variant);
    options.orders = orders;
    options.precision = half ? aerial::TablePrecision::kFloat16 : aerial::TablePrecision::kFloat32;
    options.Validate();
    return options;
  }
};

aerial::bench::RunResult RunOnce(const aerial::vk::Context& context, const aerial::PrecomputeOptions& options,
                                 size_t* table_bytes) {
  // Fresh tables each run, as a real precompute would allocate them; only the Precompute call
  // is timed on the wall clock.
  aerial::AtmosphereTables tables(context, aerial::AtmosphereParameters::Earth(), options);
  *table_bytes = tables.table_bytes();
  auto start = std::chrono::steady_clock::now();
  aerial::bench::RunResult run{.passes = aerial::Precompute(tables, nullptr)};
  run.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return run;
}

void Bench(const BenchOptions& cli) {
  // One result per variant, all with the same settings; their runs are interleaved below.
  std::vector<aerial::bench::BenchResult> results;
  for (const std::string& lut : cli.Variants())
    results.push_back({.options = cli.MakePrecomputeOptions(lut), .warmup = cli.warmup});
  // Fail on an unwritable --json path now rather than after minutes of precomputation.
  if (!cli.json_file.empty()) aerial::CheckWritable(cli.json_file);
  aerial::vk::Context context(aerial::vk::ContextCreateInfo{.device_name = "", .validation = false});
  for (auto& result : results) {
    // lavapipe runs one worker per core unless LP_NUM_THREADS says otherwise; 1 thread is ~2x slower.
    if (const char* lp = std::getenv("LP_NUM_THREADS")) {
      result.threads = std::atoi(lp);
      result.threads_source = "LP_NUM_THREADS";
    } else {
      result.threads = int(std::thread::hardware_concurrency());
      result.threads_source = "hardware_concurrency; LP_NUM_THREADS unset";
    }
    result.device = context.device_name();
  }
  for (int i = 0; i < cli.warmup + cli.runs; ++i) {
    bool warming = i < cli.warmup;
    for (auto& result : results) {
      aerial::bench::RunResult run = RunOnce(context, result.options, &result.table_bytes);
      std::fprintf(stderr, "%s %d (%s): %.1f ms GPU, %.1f ms wall\n", warming ? "warm-up" : "run",
                   warming ? i + 1 : i - cli.warmup + 1, aerial::ToString(result.options.variant).c_str(),
                   run.GpuMs(), run.wall_ms);
      if (i == 0 && warming) result.cold = std::move(run);
      else if (!warming) result.runs.push_back(std::move(run));
    }
  }
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
  app.add_flag("--half", cli.half, "Store the scattering tables as 16-bit floats");
  app.add_option("--lut", cli.lut, "Scattering table variant: 4d, 3d, or both (interleaved runs, compared)")
      ->check(CLI::IsMember({"both", "4d", "3d"}));
  app.add_flag("--small", cli.small, "Small tables (about 1/16 of the texels), for a quick check");
  app.add_option("--json", cli.json_file, "Also write the results as JSON to this file");
  return aerial::bench::ParseAndRun(app, argc, argv, "aerial_bench_precompute", [&] { Bench(cli); });
}
