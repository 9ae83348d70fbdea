#include "aerial/bench/precompute_report.h"

#include "aerial/bench/bruneton_2017.h"

namespace aerial::bench {
namespace {

std::string Identity(const std::string& pass) { return pass; }
// Passes that run once (transmittance, single scattering...) already have their row above.
std::string KindAllOrders(const std::string& pass) {
  std::string kind = PassKind(pass);
  return kind == pass ? "" : kind + " (all orders)";
}

void PrintRow(std::FILE* out, const std::string& name, const Stats& s) {
  std::fprintf(out, "  %-40s %10.1f %10.1f %10.1f\n", name.c_str(), s.median, s.min, s.max);
}

nlohmann::json StatsJson(const Stats& s) {
  return {{"median_ms", s.median}, {"min_ms", s.min}, {"max_ms", s.max}};
}

nlohmann::json SeriesJson(const std::vector<Series>& series) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& s : series) {
    nlohmann::json row = StatsJson(Summarize(s.ms));
    row["name"] = s.name;
    row["runs_ms"] = s.ms;
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

std::optional<Speedup> CompareWithBruneton2017(const BenchResult& result) {
  // Describe() lists variant, precision, orders and every table size: equal to the defaults means
  // the tables this comparison stands for (4D, 4 orders, the default sizes and precision; Bruneton
  // 2017 computes 32x128x32x8 in float32).
  if (result.options.Describe() != PrecomputeOptions{}.Describe()) return std::nullopt;
  if (!IsBruneton2017Device(result.device)) return std::nullopt;
  Speedup speedup{.total = kBruneton2017TotalSeconds * 1000.0 /
                           Summarize(GpuTotals(result.runs)).median};
  std::vector<Series> ours = GroupPasses(result.runs, Bruneton2017Step);
  for (const auto& step : kBruneton2017Steps)
    for (const auto& s : ours)
      if (s.name == step.name) speedup.steps.emplace_back(s.name, step.seconds * 1000.0 / Summarize(s.ms).median);
  return speedup;
}

void PrintReport(const BenchResult& r, std::FILE* out) {
  std::fprintf(out, "device: %s\ntables: %s\ntable memory: %.2f MiB\n", r.device.c_str(),
               r.options.Describe().c_str(), double(r.table_bytes) / (1 << 20));
  std::fprintf(out, "lavapipe threads: %d (%s)\n", r.threads, r.threads_source.c_str());
  std::fprintf(out, "runs: %zu measured after %d warm-up\n", r.runs.size(), r.warmup);
  if (r.cold)
    std::fprintf(out, "first run (cold): %.1f ms GPU, %.1f ms wall (includes lavapipe's JIT of each pipeline)\n",
                 r.cold->GpuMs(), r.cold->wall_ms);
  else
    std::fprintf(out, "no warm-up: the first measured run includes lavapipe's JIT of each pipeline\n");

  std::fprintf(out, "\n  %-40s %10s %10s %10s\n", "GPU time per pass", "median ms", "min ms", "max ms");
  for (const auto& s : GroupPasses(r.runs, Identity)) PrintRow(out, s.name, Summarize(s.ms));
  for (const auto& s : GroupPasses(r.runs, KindAllOrders)) PrintRow(out, s.name, Summarize(s.ms));
  PrintRow(out, "total GPU", Summarize(GpuTotals(r.runs)));
  PrintRow(out, "wall (Precompute call)", Summarize(WallTotals(r.runs)));

  std::fprintf(out, "\nBruneton 2017 (OpenGL on llvmpipe, docs/speed.md): %.1f s total;", kBruneton2017TotalSeconds);
  for (const auto& step : kBruneton2017Steps)
    std::fprintf(out, " %.*s %g s%s", int(step.name.size()), step.name.data(), step.seconds,
                 &step == &kBruneton2017Steps.back() ? "\n" : ",");
  std::optional<Speedup> speedup = CompareWithBruneton2017(r);
  if (!speedup) {
    std::fprintf(out, "speed-up vs Bruneton 2017: not shown; it applies only to the default tables "
                      "(4d, 4 orders, default sizes and precision) on llvmpipe, where that figure was taken\n");
    return;
  }
  std::fprintf(out, "speed-up vs Bruneton 2017: %.1fx (total), per kind:", speedup->total);
  for (size_t i = 0; i < speedup->steps.size(); ++i)
    std::fprintf(out, " %s %.1fx%s", speedup->steps[i].first.c_str(), speedup->steps[i].second,
                 i + 1 < speedup->steps.size() ? "," : "\n");
  std::fprintf(out, "  (density = incident radiance + scattering density; multiple scattering includes "
                    "accumulate; direct irradiance counts in the total only)\n");
}

nlohmann::json ReportDoc(const BenchResult& r) {
  nlohmann::json doc = {
      {"device", r.device},
      {"tables", r.options.Describe()},
      {"table_bytes", r.table_bytes},
      {"lavapipe_threads", {{"count", r.threads}, {"source", r.threads_source}}},
      {"warmup", r.warmup},
      {"runs", r.runs.size()},
      {"passes", SeriesJson(GroupPasses(r.runs, Identity))},
      {"kinds", SeriesJson(GroupPasses(r.runs, PassKind))},
      {"total_gpu", StatsJson(Summarize(GpuTotals(r.runs)))},
      {"wall", StatsJson(Summarize(WallTotals(r.runs)))},
  };
  doc["cold"] = r.cold ? nlohmann::json{{"gpu_ms", r.cold->GpuMs()}, {"wall_ms", r.cold->wall_ms}}
                       : nlohmann::json(nullptr);
  doc["speedup_vs_bruneton_2017"] = nullptr;
  if (std::optional<Speedup> speedup = CompareWithBruneton2017(r)) {
    nlohmann::json steps;
    for (const auto& [name, ratio] : speedup->steps) steps[name] = ratio;
    doc["speedup_vs_bruneton_2017"] = {{"total", speedup->total}, {"steps", steps}};
  }
  return doc;
}

std::string ReportJson(const BenchResult& r) { return ReportDoc(r).dump(2) + "\n"; }

}  // namespace aerial::bench
