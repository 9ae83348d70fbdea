#include "aerial/bench/bench_results.h"

#include "aerial/bench/frame_measurement.h"
#include "aerial/error.h"

namespace aerial::bench {
namespace {

double Median(const std::vector<RunResult>& frames, const char* pass) {
  return Summarize(SumOfPasses(frames, {pass}, pass).ms).median;
}

}  // namespace

double VariantResult::PrecomputeMs() const { return Summarize(GpuTotals(precompute.runs)).median; }
double VariantResult::FrameMs() const { return Summarize(GpuTotals(froxel_frames)).median; }
std::optional<double> VariantResult::PerPixelFrameMs() const {
  if (per_pixel_frames.empty()) return std::nullopt;
  return Summarize(GpuTotals(per_pixel_frames)).median;
}
double VariantResult::TableDifferenceFrameMs() const {
  return Summarize(GpuTotals(table_difference_frames)).median;
}
double VariantResult::FroxelBuildMs() const { return Median(froxel_frames, kFroxelBuildPass); }
double VariantResult::FrameWallMs() const { return Summarize(WallTotals(froxel_frames)).median; }

std::optional<double> PerPixelFrameRatio(const VariantResult& lut3d, const VariantResult& lut4d) {
  std::optional<double> ms3d = lut3d.PerPixelFrameMs(), ms4d = lut4d.PerPixelFrameMs();
  if (!ms3d || !ms4d) return std::nullopt;
  return *ms3d / *ms4d;
}

const VariantResult& BenchResults::Find(const std::string& tier, LutVariant variant) const {
  for (const VariantResult& r : results)
    if (r.tier == tier && r.variant() == variant) return r;
  throw Error("bench result", tier + " " + ToString(variant), "a measured tier and variant");
}

}  // namespace aerial::bench
