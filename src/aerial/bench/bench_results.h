#pragma once
// Everything one `aerial bench` run measured, as the report writers read it.
#include <optional>
#include <string>
#include <vector>

#include "aerial/bench/bench_plan.h"
#include "aerial/bench/precompute_report.h"
#include "aerial/image.h"
#include "aerial/validation/image_metrics.h"

namespace aerial::bench {

struct ClassErrors {
  validation::ErrorStats sky, opaque;
};

// One variant's accuracy in one view. In a shadow view (BenchPlan::shadow_views) only
// froxel_vs_per_pixel is measured, both frames with the sun's shadows.
struct ViewAccuracy {
  std::string view;
  bool shadow_view = false;
  ClassErrors froxel_vs_reference, per_pixel_vs_reference, froxel_vs_per_pixel;
  // Per pixel from two table reads (AerialMode::kTableDifference, Bruneton 2017's demo).
  ClassErrors table_difference_vs_reference;
  std::optional<ClassErrors> vs_4d;  // 3D tables only: 3D against 4D, both on the per-pixel path
};

// One variant at one table tier.
struct VariantResult {
  std::string tier;
  BenchResult precompute;  // options, table bytes, the precompute runs
  std::vector<RunResult> froxel_frames, per_pixel_frames, table_difference_frames;
  std::vector<ViewAccuracy> accuracy;  // in the plan's view order, then its shadow views

  LutVariant variant() const { return precompute.options.variant; }
  // Medians over the runs or frames, in ms (GPU timestamps).
  double PrecomputeMs() const;
  double FrameMs() const;          // whole froxel-path frame
  // Whole per-pixel-path frame; none where it was not timed (bench_plan.h).
  std::optional<double> PerPixelFrameMs() const;
  double TableDifferenceFrameMs() const;  // whole frame, per pixel from two table reads
  double FrameWallMs() const;      // the froxel-path frame's wall-clock time, CPU work included
  double FroxelBuildMs() const;
};

// The 3D / 4D ratio of the per-pixel frame's time, where both were timed.
std::optional<double> PerPixelFrameRatio(const VariantResult& lut3d, const VariantResult& lut4d);

// How the CPU reference was sampled in one view.
struct ReferenceSummary {
  std::string view;
  int sky_pixels = 0, opaque_pixels = 0, sun_pixels = 0;
  int unmatched_pixels = 0;  // opaque pixels where the scene has no surface at the renderer's depth
  double median_relative_std_error = 0.0;  // Monte Carlo noise of the reference
};

// The images a view's figure shows: both variants on the per-pixel path, and the surface (to
// tell sky from geometry).
struct FigureImages {
  std::string view;
  ImageRgbF lut3d, lut4d, surface;
};

struct MachineInfo {
  std::string device, date, command, version;
  int cores = 0;
  bool validation = false;  // validation layers on: every time is inflated
  // /proc/loadavg's 1, 5 and 15 minute averages before and after the run: other work on a shared
  // machine slows every measurement (the 3D/4D ratios suffer less than the times).
  std::string load_before, load_after;
};

struct BenchResults {
  BenchPlan plan;
  MachineInfo machine;
  std::vector<VariantResult> results;  // per tier of the plan: 4D, then 3D
  std::vector<ReferenceSummary> references;
  std::vector<FigureImages> figures;
  double seconds = 0.0;  // wall-clock time of the whole run

  // The result of a variant at a tier; throws if absent.
  const VariantResult& Find(const std::string& tier, LutVariant variant) const;
};

}  // namespace aerial::bench
