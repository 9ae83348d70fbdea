#include "aerial/bench/pass_stats.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

#include "aerial/error.h"

namespace aerial::bench {

double RunResult::GpuMs() const {
  double total = 0.0;
  for (const auto& pass : passes) total += pass.milliseconds;
  return total;
}

std::vector<double> GpuTotals(const std::vector<RunResult>& runs) {
  std::vector<double> values;
  for (const auto& run : runs) values.push_back(run.GpuMs());
  return values;
}

namespace {

// One field of every run.
template <typename Field>
std::vector<double> Each(const std::vector<RunResult>& runs, Field RunResult::*field) {
  std::vector<double> values;
  for (const auto& run : runs) values.push_back(run.*field);
  return values;
}

}  // namespace

std::vector<double> WallTotals(const std::vector<RunResult>& runs) { return Each(runs, &RunResult::wall_ms); }
std::vector<double> CpuTotals(const std::vector<RunResult>& runs) { return Each(runs, &RunResult::cpu_ms); }
std::vector<double> CallerCpuTotals(const std::vector<RunResult>& runs) {
  return Each(runs, &RunResult::caller_cpu_ms);
}
std::vector<double> DrawCounts(const std::vector<RunResult>& runs) { return Each(runs, &RunResult::draws); }
std::vector<double> DrawBindCounts(const std::vector<RunResult>& runs) { return Each(runs, &RunResult::draw_binds); }

double MeanPerRun(const std::vector<RunResult>& runs, int RunResult::*count) {
  if (runs.empty()) return 0.0;
  double sum = 0.0;
  for (const auto& run : runs) sum += run.*count;
  return sum / double(runs.size());
}

std::optional<double> MedianFragmentInvocations(const std::vector<RunResult>& runs, const std::string& pass) {
  std::vector<double> counts;
  for (const RunResult& run : runs) {
    std::optional<double> count;
    for (const PassTime& p : run.passes)
      if (p.pass == pass && p.fragment_shader_invocations) count = count.value_or(0.0) + double(*p.fragment_shader_invocations);
    if (count) counts.push_back(*count);
  }
  if (counts.empty()) return std::nullopt;
  return Summarize(std::move(counts)).median;
}

Stats Summarize(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  size_t n = values.size();
  double median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  return {median, values.front(), values.back()};
}

double MedianPairedRatio(const std::vector<double>& numerators, const std::vector<double>& denominators) {
  if (numerators.empty() || numerators.size() != denominators.size())
    throw std::invalid_argument("paired ratio: " + std::to_string(numerators.size()) + " numerators for " +
                                std::to_string(denominators.size()) + " denominators");
  std::vector<double> ratios;
  for (size_t i = 0; i < numerators.size(); ++i) ratios.push_back(numerators[i] / denominators[i]);
  return Summarize(std::move(ratios)).median;
}

std::vector<Series> GroupPasses(const std::vector<RunResult>& runs,
                                const std::function<std::string(const std::string&)>& key) {
  std::vector<Series> series;
  std::map<std::string, size_t> index;
  for (size_t run = 0; run < runs.size(); ++run) {
    for (const auto& pass : runs[run].passes) {
      std::string name = key(pass.pass);
      if (name.empty()) continue;
      auto [it, added] = index.try_emplace(name, series.size());
      // Every run executes the same passes, so a key's vector gets one slot per run.
      if (added) series.push_back({name, std::vector<double>(runs.size(), 0.0)});
      series[it->second].ms[run] += pass.milliseconds;
    }
  }
  return series;
}

Series SumOfPasses(const std::vector<RunResult>& runs, const std::vector<std::string>& passes,
                   const std::string& label) {
  for (const std::string& pass : passes) {
    bool timed = false;
    for (const auto& run : runs)
      for (const auto& p : run.passes) timed = timed || p.pass == pass;
    if (!timed) throw Error("pass", pass, "a pass the runs timed", label);
  }
  return GroupPasses(runs, [&](const std::string& pass) {
           return std::find(passes.begin(), passes.end(), pass) != passes.end() ? label : std::string();
         }).at(0);
}

std::string PassKind(const std::string& pass) {
  // A spectral precompute's group label, "[2/4] ", leads the pass's name.
  size_t start = pass.starts_with("[") && pass.find("] ") != std::string::npos ? pass.find("] ") + 2 : 0;
  size_t suffix = pass.find(" (order ");
  return pass.substr(start, suffix == std::string::npos ? std::string::npos : suffix - start);
}

}  // namespace aerial::bench
