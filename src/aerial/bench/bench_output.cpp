#include "aerial/bench/bench_output.h"

#include "aerial/bench/chart.h"
#include "aerial/bench/comparison_figure.h"
#include "aerial/bench/report_markdown.h"
#include "aerial/bench/results_files.h"
#include "aerial/core/atomic_file.h"

namespace aerial::bench {
namespace {

Picture PrecomputeChart(const BenchResults& b) {
  ChartSpec spec{.title = "PRECOMPUTE TIME AGAINST TABLE MEMORY, 3D AND 4D TABLES",
                 .x_label = "TABLE MEMORY (MIB)",
                 .y_label = "PRECOMPUTE, GPU MS (MEDIAN)",
                 .series = {{"4D TABLES", {200, 60, 40}, false, {}}, {"3D TABLES", {40, 90, 200}, true, {}}}};
  for (const VariantResult& r : b.results)
    spec.series[r.variant() == LutVariant::k4D ? 0 : 1].points.push_back(
        {double(r.precompute.table_bytes) / (1 << 20), r.PrecomputeMs()});
  return LogLogChart(spec, 900, 560);
}

std::string Upper(std::string text) {
  for (char& c : text) c = char(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

void CheckOutputDirectory(const std::filesystem::path& dir) { CheckWritable(dir / "report.md"); }

void WriteBenchOutputs(const std::filesystem::path& dir, const BenchResults& b) {
  const TableTier& tier = b.plan.tiers.at(b.plan.figure_tier);
  for (const FigureImages& figure : b.figures) {
    std::string title = Upper(figure.view) + ", " + Upper(tier.name) + " TABLES, PER-PIXEL PATH";
    WriteFileAtomically(dir / ViewFigureFile(figure.view), ComparisonFigure(figure, title).EncodePng());
  }
  WriteFileAtomically(dir / kChartFile, PrecomputeChart(b).EncodePng());
  WriteFileAtomically(dir / "results.json", ResultsJson(b).dump(2) + "\n");
  WriteFileAtomically(dir / "results.csv", ResultsCsv(b));
  WriteFileAtomically(dir / "report.md", MarkdownReport(b));
}

}  // namespace aerial::bench
