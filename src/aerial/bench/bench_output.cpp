#include "aerial/bench/bench_output.h"

#include "aerial/bench/chart.h"
#include "aerial/bench/comparison_figure.h"
#include "aerial/bench/report_markdown.h"
#include "aerial/bench/results_files.h"
#include "aerial/core/atomic_file.h"

namespace aerial::bench {
namespace {

Picture PrecomputeChart(const BenchResults& b) {
  ChartSpec spec{.title = "Precompute time against table memory, 3D and 4D tables",
                 .x_label = "Table memory (MiB)",
                 .y_label = "Precompute, GPU ms (median)",
                 .series = {{"4D tables", {200, 60, 40}, false, {}}, {"3D tables", {40, 90, 200}, true, {}}}};
  for (const VariantResult& r : b.results)
    spec.series[r.variant() == LutVariant::k4D ? 0 : 1].points.push_back(
        {double(r.precompute.table_bytes) / (1 << 20), r.PrecomputeMs()});
  return LogLogChart(spec, 900, 560);
}

}  // namespace

void CheckOutputDirectory(const std::filesystem::path& dir) { CheckWritable(dir / "report.md"); }

void WriteBenchOutputs(const std::filesystem::path& dir, const BenchResults& b) {
  const TableTier& tier = b.plan.tiers.at(b.plan.figure_tier);
  for (const FigureImages& figure : b.figures) {
    std::string title = "The " + figure.view + " view, " + tier.name + " tables, per-pixel path";
    WriteFileAtomically(dir / ViewFigureFile(figure.view), ComparisonFigure(figure, title).EncodePng());
  }
  WriteFileAtomically(dir / kChartFile, PrecomputeChart(b).EncodePng());
  WriteFileAtomically(dir / "results.json", ResultsJson(b).dump(2) + "\n");
  WriteFileAtomically(dir / "results.csv", ResultsCsv(b));
  WriteFileAtomically(dir / "report.md", MarkdownReport(b));
}

}  // namespace aerial::bench
