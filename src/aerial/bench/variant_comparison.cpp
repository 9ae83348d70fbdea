#include "aerial/bench/variant_comparison.h"

#include <nlohmann/json.hpp>

#include "aerial/bench/pass_stats.h"

namespace aerial::bench {
namespace {

double MiB(size_t bytes) { return double(bytes) / (1 << 20); }
double MedianGpu(const BenchResult& r) { return Summarize(GpuTotals(r.runs)).median; }
double MedianWall(const BenchResult& r) { return Summarize(WallTotals(r.runs)).median; }

double MedianOf(const std::vector<std::pair<std::string, double>>& medians, const std::string& name) {
  for (const auto& [n, ms] : medians)
    if (n == name) return ms;
  return 0.0;
}

std::string Identity(const std::string& pass) { return pass; }

}  // namespace

std::vector<std::pair<std::string, double>> PassMedians(
    const BenchResult& r, const std::function<std::string(const std::string&)>& key) {
  std::vector<std::pair<std::string, double>> medians;
  for (const auto& s : GroupPasses(r.runs, key)) medians.emplace_back(s.name, Summarize(s.ms).median);
  return medians;
}

nlohmann::json VariantJson(const BenchResult& r) {
  nlohmann::json entry = ReportDoc(r);
  entry["variant"] = ToString(r.options.variant);
  entry["precompute_ms"] = MedianGpu(r);
  entry["wall_ms"] = MedianWall(r);
  nlohmann::json passes = nlohmann::json::object();
  for (const auto& [name, ms] : PassMedians(r, Identity)) passes[name] = ms;
  entry["pass_median_ms"] = passes;
  return entry;
}

std::string ComparisonKind(const std::string& pass) {
  std::string kind = PassKind(pass);
  if (kind == "incident radiance" || kind == "scattering density") return "density";
  if (kind == "accumulate") return "multiple scattering";
  return kind;
}

VariantRatios CompareVariants(const BenchResult& lut4d, const BenchResult& lut3d) {
  VariantRatios ratios{.gpu = MedianGpu(lut3d) / MedianGpu(lut4d),
                       .wall = MedianWall(lut3d) / MedianWall(lut4d),
                       .memory = double(lut3d.table_bytes) / double(lut4d.table_bytes)};
  std::vector<std::pair<std::string, double>> kinds3d = PassMedians(lut3d, ComparisonKind);
  for (const auto& [kind, ms4d] : PassMedians(lut4d, ComparisonKind))
    ratios.kinds.emplace_back(kind, MedianOf(kinds3d, kind) / ms4d);
  return ratios;
}

void PrintComparison(const BenchResult& lut4d, const BenchResult& lut3d, std::FILE* out) {
  VariantRatios ratios = CompareVariants(lut4d, lut3d);
  std::fprintf(out, "\n3d vs 4d (medians over %zu interleaved runs: run i measures 4d, then 3d)\n",
               lut4d.runs.size());
  std::fprintf(out, "  %-28s %12s %12s %12s\n", "variant", "total GPU ms", "wall ms", "tables MiB");
  for (const BenchResult* r : {&lut4d, &lut3d})
    std::fprintf(out, "  %-28s %12.1f %12.1f %12.2f\n", ToString(r->options.variant).c_str(),
                 MedianGpu(*r), MedianWall(*r), MiB(r->table_bytes));
  std::fprintf(out, "  %-28s %12.3f %12.3f %12.3f\n", "ratio 3d / 4d", ratios.gpu, ratios.wall, ratios.memory);
  std::fprintf(out, "\n  %-28s %12s %12s %12s\n", "GPU time per kind", "4d ms", "3d ms", "3d / 4d");
  std::vector<std::pair<std::string, double>> kinds4d = PassMedians(lut4d, ComparisonKind);
  std::vector<std::pair<std::string, double>> kinds3d = PassMedians(lut3d, ComparisonKind);
  for (const auto& [kind, ratio] : ratios.kinds)
    std::fprintf(out, "  %-28s %12.1f %12.1f %12.3f\n", kind.c_str(), MedianOf(kinds4d, kind),
                 MedianOf(kinds3d, kind), ratio);
  std::fprintf(out, "  (density = incident radiance + scattering density; multiple scattering includes "
                    "accumulate; all orders summed)\n");
  if (std::optional<Speedup> speedup = CompareWithBruneton2017(lut4d))
    std::fprintf(out, "  4d speed-up vs Bruneton 2017: %.1fx (total)\n", speedup->total);
  else
    std::fprintf(out, "  4d speed-up vs Bruneton 2017: not shown (only for the default tables on llvmpipe)\n");
}

std::string ComparisonJson(const BenchResult& lut4d, const BenchResult& lut3d) {
  VariantRatios ratios = CompareVariants(lut4d, lut3d);
  nlohmann::json kinds = nlohmann::json::object();
  for (const auto& [kind, ratio] : ratios.kinds) kinds[kind] = ratio;
  nlohmann::json doc = {
      {"lut", "both"},
      {"interleaved", true},
      {"device", lut4d.device},
      {"lavapipe_threads", {{"count", lut4d.threads}, {"source", lut4d.threads_source}}},
      {"warmup", lut4d.warmup},
      {"runs", lut4d.runs.size()},
      {"variants", nlohmann::json::array({VariantJson(lut4d), VariantJson(lut3d)})},
      {"ratios", {{"description", "3d / 4d of the medians"},
                  {"precompute_ms", ratios.gpu},
                  {"wall_ms", ratios.wall},
                  {"table_bytes", ratios.memory},
                  {"kinds", kinds}}},
  };
  doc["speedup_vs_bruneton_2017_4d"] = nullptr;
  if (std::optional<Speedup> speedup = CompareWithBruneton2017(lut4d))
    doc["speedup_vs_bruneton_2017_4d"] = speedup->total;
  return doc.dump(2) + "\n";
}

}  // namespace aerial::bench
