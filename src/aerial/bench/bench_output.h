#pragma once
// The files `aerial bench` writes into its output directory: report.md, results.json,
// results.csv, one figure per view and the chart. Each is written atomically.
#include <filesystem>
#include <string>
#include <vector>

#include "aerial/bench/bench_results.h"

namespace aerial::bench {

// The names of every file a run of this plan writes into its directory: one figure per view, the
// chart, results.json, results.csv and report.md.
std::vector<std::string> BenchOutputFiles(const BenchPlan& plan);

// Before any work, making nothing: each of those files can be written in dir (created by the
// first write when missing), none is a directory or special file, and no two are the same file
// through links. Throws aerial::Error naming the path otherwise.
void CheckOutputDirectory(const std::filesystem::path& dir, const BenchPlan& plan);

void WriteBenchOutputs(const std::filesystem::path& dir, const BenchResults& results);

}  // namespace aerial::bench
