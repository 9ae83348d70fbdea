#pragma once
// report.md of `aerial bench`: the machine, the speed and size of both variants at every table
// tier, the 3D/4D ratios, the accuracy tables and the figures, readable on their own.
#include <string>

#include "aerial/bench/bench_results.h"

namespace aerial::bench {

// The figures' file names, beside report.md.
std::string ViewFigureFile(const std::string& view);  // "sunset.png"
inline constexpr const char* kChartFile = "precompute-vs-memory.png";

std::string MarkdownReport(const BenchResults& results);

// The "Speed and size" table alone (docs/tables-3d-4d.md quotes it).
std::string SpeedTable(const BenchResults& results);

}  // namespace aerial::bench
