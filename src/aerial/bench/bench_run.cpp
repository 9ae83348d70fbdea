#include "aerial/bench/bench_run.h"

#include <chrono>

#include "aerial/bench/accuracy.h"
#include "aerial/bench/precompute_measurement.h"
#include "aerial/bench/variant_frames.h"
#include "aerial/core/progress.h"
#include "aerial/scene.h"

namespace aerial::bench {

using validation::OpaqueScene;
using validation::ReferencePixel;
using validation::ViewReference;
namespace {

int ProgressSteps(const BenchPlan& p) {
  int tiers = int(p.tiers.size()), views = int(p.views.size());
  // Per tier: two variants' precomputes, and their frames on three paths (variant_frames.h), the
  // per-pixel path's fewer or none in quick mode (bench_plan.h).
  int frames = 0;
  for (int t = 0; t < tiers; ++t) {
    int per_pixel = p.PerPixelFrames(t);
    frames += 4 * (p.frame_warmup + p.frames) + (per_pixel ? 2 * (p.frame_warmup + per_pixel) : 0);
  }
  int shadow_views = 0;
  for (int t = 0; t < tiers; ++t) shadow_views += 2 * int(p.ShadowViews(t).size());
  return tiers * 2 * (p.precompute_warmup + p.precompute_runs) + frames +
         views * p.reference_columns * p.reference_rows + tiers * views + shadow_views;
}

ReferenceSummary SummarizeReference(const std::string& view, const ViewReference& reference) {
  ReferenceSummary summary{.view = view,
                           .sun_pixels = reference.sun_pixels,
                           .unmatched_pixels = reference.unmatched_pixels,
                           .median_relative_std_error = reference.median_relative_std_error};
  for (const ReferencePixel& p : reference.pixels) ++(p.sky ? summary.sky_pixels : summary.opaque_pixels);
  return summary;
}

}  // namespace

BenchResults RunBench(const BenchPlan& plan, const Device& device, const MachineInfo& machine,
                      bool quiet) {
  auto start = std::chrono::steady_clock::now();
  AtmosphereParameters atmosphere = AtmosphereParameters::Earth();
  BenchResults b{.plan = plan, .machine = machine};
  Progress progress("bench", ProgressSteps(plan), stderr, quiet);

  std::vector<PrecomputeOptions> options;
  for (const TableTier& tier : plan.tiers)
    for (LutVariant variant : {LutVariant::k4D, LutVariant::k3D}) options.push_back(tier.Options(variant, plan.colour));
  std::vector<PrecomputeMeasurement> tables =
      MeasurePrecompute(device, atmosphere, options, plan.precompute_warmup, plan.precompute_runs,
                        [&](const BenchResult& r, const RunResult&, bool, int) {
                          progress.Advance("precompute, " + ToString(r.options.variant) + " " +
                                           ScatteringSize(r.options.resolution));
                        });
  for (size_t i = 0; i < tables.size(); ++i)
    b.results.push_back({.tier = plan.tiers[i / 2].name, .precompute = std::move(tables[i].result)});

  Scene scene = BuildDefaultScene(atmosphere.bottom_radius_m);
  ApplyPresetView(scene, "noon", atmosphere.bottom_radius_m);
  for (size_t t = 0; t < plan.tiers.size(); ++t)
    MeasureVariantFrames(b.results[2 * t], *tables[2 * t].tables, b.results[2 * t + 1],
                         *tables[2 * t + 1].tables, scene, plan, plan.PerPixelFrames(t),
                         [&] { progress.Advance("frames, " + plan.tiers[t].name + " tables"); });

  Scene opaque = OpaqueScene(scene);
  std::vector<ViewReference> references = SampleViews(*tables[2 * plan.figure_tier].tables, opaque, plan,
                                                      [&] { progress.Advance("CPU reference"); });
  for (size_t v = 0; v < plan.views.size(); ++v)
    b.references.push_back(SummarizeReference(plan.views[v], references[v]));
  for (size_t t = 0; t < plan.tiers.size(); ++t)
    MeasureAccuracy(b.results[2 * t], *tables[2 * t].tables, b.results[2 * t + 1], *tables[2 * t + 1].tables,
                    opaque, plan, plan.ShadowViews(t), references, t == plan.figure_tier ? &b.figures : nullptr,
                    [&] { progress.Advance("accuracy, " + plan.tiers[t].name + " tables"); });
  progress.Finish();
  b.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return b;
}

}  // namespace aerial::bench
