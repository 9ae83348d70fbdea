#include "aerial/bench/bench_plan.h"

#include <algorithm>

#include "aerial/scene.h"

namespace aerial::bench {
namespace {

// The presets made to show the sun's shadows on the ground and in the air.
const std::vector<std::string> kShadowPresets = {"evening", "sunrise"};

// The presets whose views the accuracy is measured in against the CPU reference: all but the
// shadow presets, whose point the reference, without shadows, would miss.
std::vector<std::string> AccuracyViews() {
  std::vector<std::string> views = PresetNames();
  std::erase_if(views, [](const std::string& v) { return std::ranges::count(kShadowPresets, v) > 0; });
  return views;
}

}  // namespace

PrecomputeOptions TableTier::Options(LutVariant variant, ColourMode colour) const {
  PrecomputeOptions options =
      small_base ? PrecomputeOptions::Small(variant) : PrecomputeOptions::Default(variant);
  options.colour = colour;
  options.SetScatteringSize(r, mu, mu_s, variant == LutVariant::k4D ? nu : 1);
  options.Validate();
  return options;
}

std::string ScatteringSize(const TableResolution& r) {
  return std::to_string(r.scattering_r) + "x" + std::to_string(r.scattering_mu) + "x" +
         std::to_string(r.scattering_mu_s) + "x" + std::to_string(r.scattering_nu);
}

std::vector<std::string> BenchPlan::ShadowViews(size_t tier) const {
  return shadow_views_figure_tier_only && tier != figure_tier ? std::vector<std::string>{} : shadow_views;
}

int BenchPlan::PerPixelFrames(size_t tier) const {
  if (!per_pixel_frames_figure_tier_only) return frames;
  return tier == figure_tier ? *per_pixel_frames_figure_tier_only : 0;
}

BenchPlan BenchPlan::Full() {
  BenchPlan plan;
  // Small(), the defaults, and the defaults with twice the mu_s resolution: the axis that limits
  // accuracy near sunset (docs/accuracy.md, "Accuracy against the physical sky").
  const TableResolution d = PrecomputeOptions::Default().resolution;
  plan.tiers = {{"small", true, 16, 64, 16, 8},
                {"default", false, d.scattering_r, d.scattering_mu, d.scattering_mu_s, d.scattering_nu},
                {"fine-mu_s", false, d.scattering_r, d.scattering_mu, 2 * d.scattering_mu_s, d.scattering_nu}};
  plan.figure_tier = 1;
  plan.views = AccuracyViews();
  plan.shadow_views = kShadowPresets;
  return plan;
}

BenchPlan BenchPlan::Quick() {
  BenchPlan plan;
  plan.quick = true;
  plan.tiers = {{"tiny", true, 8, 32, 8, 8}, {"small", true, 16, 64, 16, 8}};
  plan.figure_tier = 1;
  // One timed precompute of each table after its cold run: the spread over runs is the full run's
  // to measure, as the marched per-pixel frame's time is.
  plan.precompute_runs = 1;
  plan.frame_warmup = 1;
  plan.frames = 3;
  // The marched per-pixel path costs seconds a frame at 720p: two frames of each variant would add
  // a third to the quick run. Its frame time is the full run's to measure.
  plan.per_pixel_frames_figure_tier_only = 0;
  plan.image_width = 320;
  plan.image_height = 180;
  plan.reference_columns = 8;
  plan.reference_rows = 5;
  plan.reference_paths = 8192;
  plan.views = AccuracyViews();
  // The shadowed per-pixel march costs about a second a frame at 320x180: the figure tier's only.
  plan.shadow_views = kShadowPresets;
  plan.shadow_views_figure_tier_only = true;
  return plan;
}

}  // namespace aerial::bench
