#pragma once
// The machine-readable results of `aerial bench`.
//   results.json: an object whose "results" lists one entry per variant and table tier, each with
//     "variant" ("3d"/"4d"), "tier", the table resolution, "table_bytes", "precompute_ms",
//     "frame_ms" and the other medians (ms), the precompute's per-pass detail and "accuracy" by
//     view; beside it the settings, the machine, the 3D/4D ratios and the reference sampling.
//   results.csv: one row per variant, tier, view, comparison and pixel class (tidy data): the
//     entry's sizes and times repeated on each of its rows, then the error figures.
#include <nlohmann/json.hpp>
#include <string>

#include "aerial/bench/bench_results.h"

namespace aerial::bench {

// How a relative error is defined (image_metrics.h), for the files and the report.
extern const char* const kErrorDefinition;

nlohmann::json ResultsJson(const BenchResults& results);
std::string ResultsCsv(const BenchResults& results);

// The comparisons of one view's accuracy in file order, with their names in the files
// ("3d_vs_4d", "froxel_vs_reference", "per_pixel_vs_reference", "froxel_vs_per_pixel"); the
// 3D-vs-4D comparison only for the 3D tables; a shadow view's froxel_vs_per_pixel alone.
std::vector<std::pair<std::string, const ClassErrors*>> NamedComparisons(const ViewAccuracy& accuracy);

}  // namespace aerial::bench
