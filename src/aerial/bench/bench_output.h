#pragma once
// The files `aerial bench` writes into its output directory: report.md, results.json,
// results.csv, one figure per view and the chart. Each is written atomically.
#include <filesystem>

#include "aerial/bench/bench_results.h"

namespace aerial::bench {

// Before any work: the directory exists (it is created if missing) and files can be created in
// it. Throws aerial::Error naming the path otherwise.
void CheckOutputDirectory(const std::filesystem::path& dir);

void WriteBenchOutputs(const std::filesystem::path& dir, const BenchResults& results);

}  // namespace aerial::bench
