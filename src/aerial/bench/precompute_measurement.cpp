#include "aerial/bench/precompute_measurement.h"

#include <chrono>
#include <cstdlib>
#include <thread>


namespace aerial::bench {
namespace {

// Fresh tables each run, precomputed without the cache as a first run would be; the wall clock
// times the whole call (the tables' allocation and upload of their uniforms, then the passes).
RunResult RunOnce(PrecomputeMeasurement& measurement, const Device& device, const AtmosphereParameters& atmosphere) {
  measurement.tables.reset();  // the previous run's memory goes first
  auto start = std::chrono::steady_clock::now();
  measurement.tables = std::make_unique<Tables>(Tables::LoadOrPrecompute(
      device, atmosphere, measurement.result.options, {.read_cache = false, .write_cache = false}));
  RunResult run{.passes = measurement.tables->precompute_times()};
  run.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  measurement.result.table_bytes = measurement.tables->gpu_bytes();
  return run;
}

}  // namespace

std::vector<PrecomputeMeasurement> MeasurePrecompute(const Device& device,
                                                     const AtmosphereParameters& atmosphere,
                                                     const std::vector<PrecomputeOptions>& options,
                                                     int warmup, int runs,
                                                     const PrecomputeRunCallback& on_run) {
  std::vector<PrecomputeMeasurement> measurements;
  for (const PrecomputeOptions& option : options) {
    BenchResult result{.device = device.name(), .options = option, .warmup = warmup};
    // lavapipe runs one worker per core unless LP_NUM_THREADS says otherwise; 1 thread is ~2x slower.
    if (const char* lp = std::getenv("LP_NUM_THREADS")) {
      result.threads = std::atoi(lp);
      result.threads_source = "LP_NUM_THREADS";
    } else {
      result.threads = int(std::thread::hardware_concurrency());
      result.threads_source = "hardware_concurrency; LP_NUM_THREADS unset";
    }
    measurements.push_back({std::move(result), nullptr});
  }
  for (int i = 0; i < warmup + runs; ++i) {
    bool warming = i < warmup;
    for (PrecomputeMeasurement& m : measurements) {
      RunResult run = RunOnce(m, device, atmosphere);
      if (on_run) on_run(m.result, run, warming, warming ? i + 1 : i - warmup + 1);
      if (i == 0 && warming)
        m.result.cold = std::move(run);
      else if (!warming)
        m.result.runs.push_back(std::move(run));
    }
  }
  return measurements;
}

}  // namespace aerial::bench
