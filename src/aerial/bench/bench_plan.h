#pragma once
// What `aerial bench` measures: the table resolutions of both variants, the frame and image sizes,
// the number of runs and frames, and the reference sampling; in full mode or in quick mode (small
// tables, fewer frames, smaller images, fewer and noisier reference pixels).
#include <optional>
#include <string>
#include <vector>

#include "aerial/table_options.h"

namespace aerial::bench {

// One table resolution, for both variants: the same transmittance, irradiance and scattering
// (r, mu, mu_s) sizes; the 4D tables add nu, the 3D ones have one nu slice.
struct TableTier {
  std::string name;
  bool small_base = false;  // transmittance, irradiance and sample counts of Small() (else Default())
  int r = 32, mu = 128, mu_s = 32, nu = 8;

  PrecomputeOptions Options(LutVariant variant, ColourMode colour = ColourMode::kSpectral) const;
};

// "RxMUxMU_SxNU" of the scattering tables, e.g. "32x128x32x8".
std::string ScatteringSize(const TableResolution& resolution);

struct BenchPlan {
  bool quick = false;
  std::vector<TableTier> tiers;
  size_t figure_tier = 0;  // the tier whose images the figures show
  int precompute_warmup = 1, precompute_runs = 3;
  int frame_width = 1280, frame_height = 720, frame_warmup = 2, frames = 7;
  // The marched per-pixel path costs seconds a frame on lavapipe (the reference path, not a
  // real-time one). Unset, it is timed like the other paths (`frames`, in every tier); set, over
  // this many frames in the figure tier and not at all in the others (quick mode: 0, not at all).
  std::optional<int> per_pixel_frames_figure_tier_only;
  // The sun's shadow map in the timed frames (--shadows). The accuracy renders never have it:
  // their CPU reference lights every surface point as if nothing stood between it and the sun.
  bool shadows = true;
  // What the tables' channels hold (--colour). Spectral tables are compared with the spectral
  // reference (validation/reference_sampling.h, SampleSpectralReference).
  ColourMode colour = ColourMode::kSpectral;
  int image_width = 1280, image_height = 720;  // the accuracy renders
  int reference_columns = 16, reference_rows = 9;
  int reference_paths = 32768;  // Monte Carlo paths per reference query (orders >= 2)
  std::vector<std::string> views;
  // Views made to show the mountains' shadows on the ground and in the air: there the froxel path
  // is compared with the per-pixel path, both with the sun's shadows (the CPU reference has none,
  // so the views above are rendered without them). In every tier, or in the figure tier only.
  std::vector<std::string> shadow_views;
  bool shadow_views_figure_tier_only = false;

  // Measured frames of the per-pixel path in tier `tier` (0: not rendered at all).
  int PerPixelFrames(size_t tier) const;
  // The shadow views measured in tier `tier`.
  std::vector<std::string> ShadowViews(size_t tier) const;

  static BenchPlan Full();
  static BenchPlan Quick();
};

}  // namespace aerial::bench
