#include "aerial/bench/report_markdown.h"

#include <cstdio>
#include <sstream>

#include "aerial/bench/number_text.h"
#include "aerial/bench/recommendations.h"
#include "aerial/bench/results_files.h"
#include "aerial/bench/variant_comparison.h"
#include "aerial/reference/monte_carlo.h"

namespace aerial::bench {

using validation::ErrorStats;
namespace {

double MiB(size_t bytes) { return double(bytes) / (1 << 20); }

// "0.41% / 2.3%": relative RMSE / maximum.
std::string Cell(const ErrorStats& e) {
  return e.pixels == 0 ? "n/a" : Percent(e.per_pixel_rel_rmse) + " / " + Percent(e.rel_max);
}

std::string TierLabel(const TableTier& tier) {
  return tier.name + " (" + std::to_string(tier.r) + "x" + std::to_string(tier.mu) + "x" +
         std::to_string(tier.mu_s) + ")";
}

void MachineSection(std::ostringstream& md, const BenchResults& b) {
  const MachineInfo& m = b.machine;
  md << "## Machine\n\n| | |\n|---|---|\n";
  md << "| device | " << m.device << " |\n";
  md << "| cores | " << m.cores;
  if (!b.results.empty())
    md << " (lavapipe threads: " << b.results[0].precompute.threads << ", "
       << b.results[0].precompute.threads_source << ")";
  md << " |\n| date | " << m.date << " |\n| command | `" << m.command << "` |\n";
  md << "| aerial | " << m.version << " |\n";
  md << "| mode | "
     << (b.plan.quick ? "quick (small tables, few frames, small images, few reference pixels)" : "full")
     << " |\n";
  md << "| sun shadows in the timed frames | " << (b.plan.shadows ? "on" : "off")
     << " (never in the accuracy renders: the reference has none) |\n";
  md << "| colour | "
     << (b.plan.colour == ColourMode::kSpectral
             ? "spectral (the tables and the reference at every wavelength, converted to linear sRGB)"
             : "rgb (the atmosphere's three wavelengths)")
     << " |\n";
  md << "| validation layers | " << (m.validation ? "on (every time below is inflated by them)" : "off")
     << " |\n";
  md << "| load average (1, 5, 15 min) | " << m.load_before << " before, " << m.load_after << " after |\n";
  md << "| run time | " << Format("%.0f", b.seconds) << " s |\n\n";
}

void SummarySection(std::ostringstream& md, const BenchResults& b) {
  const TableTier& tier = b.plan.tiers.at(b.plan.figure_tier);
  const VariantResult& lut4d = b.Find(tier.name, LutVariant::k4D);
  const VariantResult& lut3d = b.Find(tier.name, LutVariant::k3D);
  md << "## Summary\n\nAt the " << TierLabel(tier) << " resolution the 3D tables take "
     << Format("%.2f", MiB(lut3d.precompute.table_bytes)) << " MiB instead of "
     << Format("%.2f", MiB(lut4d.precompute.table_bytes)) << " MiB ("
     << Format("%.2fx", double(lut3d.precompute.table_bytes) / double(lut4d.precompute.table_bytes))
     << ") and precompute in " << Format("%.0f", lut3d.PrecomputeMs()) << " ms instead of "
     << Format("%.0f", lut4d.PrecomputeMs()) << " ms ("
     << Format("%.2fx", lut3d.PrecomputeMs() / lut4d.PrecomputeMs()) << "); a " << b.plan.frame_width << "x"
     << b.plan.frame_height << " frame takes " << Format("%.1f", lut3d.FrameMs()) << " ms with them and "
     << Format("%.1f", lut4d.FrameMs()) << " ms with the 4D tables. 3D against 4D, worst view: ";
  ErrorStats sky, opaque;
  std::string sky_view, opaque_view;
  for (const ViewAccuracy& v : lut3d.accuracy) {
    if (v.vs_4d->sky.pixels && v.vs_4d->sky.per_pixel_rel_rmse >= sky.per_pixel_rel_rmse)
      sky = v.vs_4d->sky, sky_view = v.view;
    if (v.vs_4d->opaque.pixels && v.vs_4d->opaque.per_pixel_rel_rmse >= opaque.per_pixel_rel_rmse)
      opaque = v.vs_4d->opaque, opaque_view = v.view;
  }
  md << "sky " << Cell(sky) << " (relative RMSE / max, " << sky_view << "), opaque " << Cell(opaque) << " ("
     << opaque_view << ").\n\n";
  md << "### Recommendations\n\nFrom this run's figures at the " << TierLabel(tier) << " resolution:\n\n";
  for (const std::string& line : Recommendations(b)) md << line << "\n";
  md << "\n";
}

// Median precompute GPU time of each kind of pass, all orders summed.
void PrecomputeKindsTable(std::ostringstream& md, const BenchResults& b) {
  if (b.results.empty()) return;
  std::vector<std::pair<std::string, double>> kinds = PassMedians(b.results[0].precompute, ComparisonKind);
  md << "Precompute GPU time by kind of pass (ms, medians; density = incident radiance + scattering density, "
        "multiple scattering includes accumulate, all orders summed):\n\n| tables | variant |";
  for (const auto& kind : kinds) md << " " << kind.first << " |";
  md << "\n|---|---|";
  for (size_t i = 0; i < kinds.size(); ++i) md << "---|";
  md << "\n";
  for (const VariantResult& r : b.results) {
    md << "| " << r.tier << " | " << ToString(r.variant()) << " |";
    for (const auto& [kind, ms] : PassMedians(r.precompute, ComparisonKind))
      md << " " << Format("%.1f", ms) << " |";
    md << "\n";
  }
  md << "\n";
}

void SpeedSection(std::ostringstream& md, const BenchResults& b) {
  const BenchPlan& p = b.plan;
  md << "## Speed and size\n\nPrecompute: GPU time of all passes, "
     << (p.precompute_runs == 1 ? std::string("one run") : "median of " + std::to_string(p.precompute_runs) + " runs")
     << " after " << p.precompute_warmup
     << " warm-up, every variant and tier interleaved in one process. Frames: " << p.frame_width << "x"
     << p.frame_height << ", the built-in default scene (preset noon, transparent objects "
     << "included), median of " << p.frames << " frames after " << p.frame_warmup
     << " warm-up, the six renderers of a tier (two variants, three paths) interleaved, the camera "
        "moving a little every frame so that each frame rebuilds its froxel volume and sky-view table "
        "(a still camera keeps them). Times are GPU timestamps in ms, but for the wall-clock column.";
  if (std::optional<int> n = p.per_pixel_frames_figure_tier_only; n && *n == 0)
    md << " The marched per-pixel path, seconds a frame here, is not timed in this mode (—).";
  else if (n)
    md << " The marched per-pixel path, seconds a frame here, is timed over " << *n << (*n == 1 ? " frame" : " frames")
       << " with the " << p.tiers.at(p.figure_tier).name << " tables only (— elsewhere).";
  md << "\n\n" << SpeedTable(b) << "\n";
  PrecomputeKindsTable(md, b);
  md << "3D / 4D ratios (below 1: the 3D tables are cheaper):\n\n"
     << "| tables | memory | precompute | frame, froxel path | frame, per-pixel path | precompute by kind |\n"
     << "|---|---|---|---|---|---|\n";
  for (const TableTier& tier : p.tiers) {
    const VariantResult& lut4d = b.Find(tier.name, LutVariant::k4D);
    const VariantResult& lut3d = b.Find(tier.name, LutVariant::k3D);
    VariantRatios ratios = CompareVariants(lut4d.precompute, lut3d.precompute);
    md << "| " << TierLabel(tier) << " | " << Format("%.3f", ratios.memory) << " | "
       << Format("%.3f", ratios.gpu) << " | " << Format("%.3f", lut3d.FrameMs() / lut4d.FrameMs()) << " | "
       << Format("%.3f", PerPixelFrameRatio(lut3d, lut4d)) << " |";
    for (size_t i = 0; i < ratios.kinds.size(); ++i)
      md << (i ? "; " : " ") << ratios.kinds[i].first << " " << Format("%.2f", ratios.kinds[i].second);
    md << " |\n";
  }
  md << "\nHow to read the times:\n\n"
     << "- On lavapipe a command buffer runs on the CPU, and the timestamps around a pass measure its CPU "
        "time. The first precompute and the first frame of each renderer include lavapipe's JIT compilation "
        "of every pipeline: they are warm-up and not counted.\n"
     << "- lavapipe defers rasterization, so the timestamps around the draws of the frame's one raster pass "
        "(opaque, sky, transparent) do not bound their work: the whole-frame times and the compute passes "
        "(froxel build, precompute passes) are the reliable figures. The wall-clock column adds the CPU's "
        "part of a frame (terrain selection, sorting, recording, submitting, waiting; the renderers share the "
        "terrain chunks they build, so building one falls on the first renderer whose frame needs it).\n"
     << "- Other work on the machine slows every run (see the load average above); the 3D / 4D ratios, "
        "from interleaved runs, suffer less from it than the times themselves.\n\n";
}

// One accuracy table: rows tier x view, a column per (variant or comparison, class).
void AccuracyTable(std::ostringstream& md, const BenchResults& b, const std::string& comparison,
                   bool both_variants) {
  md << (both_variants
             ? "| tables | view | 4D sky | 4D opaque | 3D sky | 3D opaque |\n|---|---|---|---|---|---|\n"
             : "| tables | view | sky | opaque |\n|---|---|---|---|\n");
  for (const TableTier& tier : b.plan.tiers)
    for (size_t v = 0; v < b.plan.views.size(); ++v) {
      md << "| " << TierLabel(tier) << " | " << b.plan.views[v] << " |";
      for (LutVariant variant : {LutVariant::k4D, LutVariant::k3D}) {
        if (!both_variants && variant == LutVariant::k4D) continue;
        for (const auto& [name, errors] : NamedComparisons(b.Find(tier.name, variant).accuracy.at(v)))
          if (name == comparison) md << " " << Cell(errors->sky) << " | " << Cell(errors->opaque) << " |";
      }
      md << "\n";
    }
  md << "\n";
}

// The froxel path against the per-pixel path in the shadow views, where they were measured.
void ShadowViewsTable(std::ostringstream& md, const BenchResults& b) {
  if (b.plan.shadow_views.empty()) return;
  md << "### Froxel path against per-pixel path, with the sun's shadows\n\n"
     << "| tables | view | 4D sky | 4D opaque | 3D sky | 3D opaque |\n|---|---|---|---|---|---|\n";
  for (size_t t = 0; t < b.plan.tiers.size(); ++t)
    for (const std::string& view : b.plan.ShadowViews(t)) {
      md << "| " << TierLabel(b.plan.tiers[t]) << " | " << view << " |";
      for (LutVariant variant : {LutVariant::k4D, LutVariant::k3D})
        for (const ViewAccuracy& a : b.Find(b.plan.tiers[t].name, variant).accuracy)
          if (a.shadow_view && a.view == view)
            md << " " << Cell(a.froxel_vs_per_pixel.sky) << " | " << Cell(a.froxel_vs_per_pixel.opaque) << " |";
      md << "\n";
    }
  md << "\n";
}

void AccuracySection(std::ostringstream& md, const BenchResults& b) {
  const BenchPlan& p = b.plan;
  md << "## Accuracy\n\n### What is compared\n\n- Views: the presets";
  for (const std::string& v : p.views) md << " " << v << (&v == &p.views.back() ? "" : ",");
  md << " of the built-in scene, rendered at " << p.image_width << "x" << p.image_height
     << " without the scene's transparent meshes, so every pixel is sky or an opaque surface. A pixel is "
        "sky where the opaque pass drew nothing (Renderer::ReadSurface alpha < 0).\n"
     << "- Each cell is the relative RMSE / the maximum relative error over the pixels of the class: "
     << kErrorDefinition << ".\n"
     << "- **3D against 4D**: every pixel of the 3D frame against the 4D frame, both on the per-pixel path "
        "(tables read per pixel, no froxels), so the difference is the tables' alone.\n"
     << "- **Against the CPU reference**: the double-precision reference (src/aerial/reference) on a "
     << p.reference_columns << "x" << p.reference_rows
     << " grid of pixel centers per view, each pixel's ray rebuilt from the frame's uniforms as the "
        "frame's shaders build it. Sky pixels: the sky radiance along the whole ray, of the orders the "
        "tables stand for ("
     << (b.results.empty() || b.results[0].precompute.options.RepresentedOrders() == reference::kAllOrders
             ? std::string("all orders: the reference's paths end by Russian roulette")
             : "orders 1.." + std::to_string(b.results[0].precompute.options.orders))
     << "); where the ray meets the bare planet, plus T albedo/pi (E_sun + E_sky) of "
        "the ground, E_sky of the same orders. Opaque pixels: the surface's lighting and its aerial "
        "perspective, L = L_surface T + inscatter over the segment to the surface, L_surface computed by "
        "the reference too: albedo/pi (E_sun <T>_disc max(n.sun, 0) + E_sky(n)), with the sky irradiance "
        "of the tilted surface itself (its whole hemisphere: below the horizon, the air and the lit bare "
        "ground; the renderer scales the horizontal irradiance by (1 + n.up)/2) and no shadows (the "
        "reference has none, and these frames are drawn without them), at the point, normal and albedo the scene has where the "
        "renderer's depth puts the surface: a CPU ray cast's mesh hit, or the terrain's height function "
        "(its exact normal, where the renderer draws a level of detail with per-vertex lighting). Pixels "
        "that see the sun disc are left out, and opaque pixels where the scene has no surface at the "
        "renderer's depth (beyond the terrain's level-of-detail bound). Orders >= 2 are Monte Carlo with "
     << p.reference_paths << " paths per query; the noise is listed below.\n"
     << "- **Why opaque pixels are further off than the sky** (the afternoon and sunset views most): the "
        "renderer lights the terrain from its level of detail's vertex normals, interpolated across each "
        "triangle, and the reference from the height function's exact normal at the point. With the sun "
        "low over a slope its cosine changes fast with the normal, so a few pixels on slopes turned from the "
        "sun carry most of the error, the same for both tables and every path: it is the surface's, not "
        "the air's. The sky columns measure the atmosphere.\n"
     << "- **Froxel path against per-pixel path**: every pixel of the frame on the froxel path (froxel "
        "volume and sky-view table) against the same tables read per pixel; in the views above without "
        "shadows, and in the views made to show the mountains' shadows on the ground and in the air"
     << [&] {
          std::string views;
          for (const std::string& v : p.shadow_views) views += (views.empty() ? " (" : ", ") + v;
          return views.empty() ? std::string() : views + ")";
        }()
     << " with them, on both paths: the per-pixel march shadows its steps as the froxel columns do, so "
        "what differs there is the froxels' resolution across the shadows' edges.\n"
     << "- **Two table reads per pixel**: what a user would otherwise pick, Bruneton 2017's demo: the "
        "segment's inscatter as S(x) - T S(p) from two 4D reads, no march, the sky read as the tables hold "
        "it (no correction of the Earth's shadow); against the CPU reference as above.\n\n";
  md << "### 3D tables against 4D tables (per-pixel path)\n\n";
  AccuracyTable(md, b, "3d_vs_4d", false);
  md << "### Against the CPU reference, froxel path\n\n";
  AccuracyTable(md, b, "froxel_vs_reference", true);
  md << "### Against the CPU reference, per-pixel path\n\n";
  AccuracyTable(md, b, "per_pixel_vs_reference", true);
  md << "### Froxel path against per-pixel path\n\n";
  AccuracyTable(md, b, "froxel_vs_per_pixel", true);
  ShadowViewsTable(md, b);
  md << "### Against the CPU reference, two table reads per pixel (Bruneton 2017)\n\n";
  AccuracyTable(md, b, "table_difference_vs_reference", true);
  md << "### Reference sampling\n\n"
     << "| view | sky pixels | opaque pixels | sun pixels left out | opaque pixels left out (no scene "
        "surface at the renderer's depth) | Monte Carlo noise (median relative standard error) |\n"
        "|---|---|---|---|---|---|\n";
  for (const ReferenceSummary& s : b.references)
    md << "| " << s.view << " | " << s.sky_pixels << " | " << s.opaque_pixels << " | " << s.sun_pixels
       << " | " << s.unmatched_pixels << " | " << Percent(s.median_relative_std_error) << " |\n";
  md << "\n";
}

void FiguresSection(std::ostringstream& md, const BenchResults& b) {
  const TableTier& tier = b.plan.tiers.at(b.plan.figure_tier);
  md << "## Figures\n\nEach view at the " << TierLabel(tier)
     << " resolution on the per-pixel path, left to right: the 3D frame and the 4D frame, tone-mapped "
        "with one exposure (the 4D frame's log-average luminance to mid grey), and their relative "
        "difference |3D - 4D| / 4D per pixel (the largest channel, floor as above) as a heat map, clipped "
        "at the top of its colour bar (the 99th percentile, rounded up).\n\n";
  for (const std::string& view : b.plan.views) md << "![" << view << "](" << ViewFigureFile(view) << ")\n\n";
  md << "Precompute time against table memory, every tier of both variants:\n\n"
     << "![precompute time against table memory](" << kChartFile << ")\n";
}

}  // namespace

std::string ViewFigureFile(const std::string& view) { return view + ".png"; }

std::string SpeedTable(const BenchResults& b) {
  std::ostringstream md;
  md << "| tables | variant | scattering (r x mu x mu_s x nu) | memory (MiB) | precompute (ms, min-max) "
        "| froxel build | frame, froxel path | frame, per-pixel path | frame, two table reads per pixel "
        "| frame wall clock, froxel path |\n"
     << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const TableTier& tier : b.plan.tiers)
    for (LutVariant variant : {LutVariant::k4D, LutVariant::k3D}) {
      const VariantResult& r = b.Find(tier.name, variant);
      Stats precompute = Summarize(GpuTotals(r.precompute.runs));
      md << "| " << tier.name << " | " << ToString(variant) << " | "
         << ScatteringSize(r.precompute.options.resolution) << " | "
         << Format("%.2f", MiB(r.precompute.table_bytes)) << " | " << Format("%.0f", precompute.median)
         << " (" << Format("%.0f", precompute.min) << "-" << Format("%.0f", precompute.max) << ") | "
         << Format("%.1f", r.FroxelBuildMs()) << " | " << Format("%.1f", r.FrameMs()) << " | "
         << Format("%.1f", r.PerPixelFrameMs()) << " | " << Format("%.1f", r.TableDifferenceFrameMs()) << " | "
         << Format("%.1f", r.FrameWallMs()) << " |\n";
    }
  return md.str();
}

std::string MarkdownReport(const BenchResults& b) {
  std::ostringstream md;
  md << "# aerial bench: 3D or 4D tables\n\n";
  MachineSection(md, b);
  SummarySection(md, b);
  SpeedSection(md, b);
  AccuracySection(md, b);
  FiguresSection(md, b);
  return md.str();
}

}  // namespace aerial::bench
