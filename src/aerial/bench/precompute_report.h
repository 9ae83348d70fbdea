#pragma once
// What the precompute benchmark measured, and its two renderings: a text table for people and a
// JSON document for scripts that track the numbers across commits.
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "aerial/bench/pass_stats.h"
#include "aerial/table_options.h"

namespace aerial::bench {

struct BenchResult {
  std::string device;
  PrecomputeOptions options;
  size_t table_bytes = 0;
  int threads = 0;             // lavapipe's worker threads, as far as we can tell
  std::string threads_source;  // where that number comes from
  int warmup = 0;
  std::optional<RunResult> cold;  // the first run of the process, if it was a warm-up
  std::vector<RunResult> runs;    // the measured runs
};

// Ratios of Bruneton 2017's time to our median time (> 1: we are faster). Only meaningful for the
// tables Bruneton's figures were measured with, on the driver they were measured on, so it is
// empty for any other options or device.
struct Speedup {
  double total = 0.0;
  std::vector<std::pair<std::string, double>> steps;  // in kBruneton2017Steps order
};
std::optional<Speedup> CompareWithBruneton2017(const BenchResult& result);

void PrintReport(const BenchResult& result, std::FILE* out);
nlohmann::json ReportDoc(const BenchResult& result);
std::string ReportJson(const BenchResult& result);  // ReportDoc, indented

}  // namespace aerial::bench
