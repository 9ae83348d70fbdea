#include "aerial/bench/bench_output.h"

#include "aerial/bench/chart.h"
#include "aerial/bench/comparison_figure.h"
#include "aerial/bench/report_markdown.h"
#include "aerial/bench/results_files.h"
#include "aerial/core/atomic_file.h"
#include "aerial/core/output_conflicts.h"

namespace aerial::bench {
namespace {

constexpr const char* kResultsJsonFile = "results.json";
constexpr const char* kResultsCsvFile = "results.csv";
constexpr const char* kReportFile = "report.md";

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

std::vector<std::string> BenchOutputFiles(const BenchPlan& plan) {
  std::vector<std::string> files;
  for (const std::string& view : plan.views) files.push_back(ViewFigureFile(view));
  for (const char* file : {kChartFile, kResultsJsonFile, kResultsCsvFile, kReportFile}) files.push_back(file);
  return files;
}

void CheckOutputDirectory(const std::filesystem::path& dir, const BenchPlan& plan) {
  std::vector<NamedFile> outputs;
  for (const std::string& file : BenchOutputFiles(plan)) {
    CheckWritable(dir / file);
    outputs.push_back({"--out", dir / file});
  }
  CheckOutputConflicts(outputs);
}

void WriteBenchOutputs(const std::filesystem::path& dir, const BenchResults& b) {
  const TableTier& tier = b.plan.tiers.at(b.plan.figure_tier);
  for (const FigureImages& figure : b.figures) {
    std::string title = "The " + figure.view + " view, " + tier.name + " tables, per-pixel path";
    WriteFileAtomically(dir / ViewFigureFile(figure.view), ComparisonFigure(figure, title).EncodePng());
  }
  WriteFileAtomically(dir / kChartFile, PrecomputeChart(b).EncodePng());
  WriteFileAtomically(dir / kResultsJsonFile, ResultsJson(b).dump(2) + "\n");
  WriteFileAtomically(dir / kResultsCsvFile, ResultsCsv(b));
  WriteFileAtomically(dir / kReportFile, MarkdownReport(b));
}

}  // namespace aerial::bench
