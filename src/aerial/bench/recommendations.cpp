#include "aerial/bench/recommendations.h"

#include <algorithm>
#include <span>

#include "aerial/bench/number_text.h"

namespace aerial::bench {
namespace {

// The largest relative RMSE of one comparison over some views and both pixel classes, and where.
struct Worst {
  double per_pixel_rel_rmse = 0.0;
  std::string where = "none";
};

Worst WorstOf(const VariantResult& r, std::span<const char* const> views,
              const ClassErrors& (*comparison)(const ViewAccuracy&), bool sky_only = false) {
  Worst worst;
  for (const ViewAccuracy& a : r.accuracy) {
    if (std::find(views.begin(), views.end(), a.view) == views.end()) continue;
    const ClassErrors& e = comparison(a);
    for (auto [stats, name] : {std::pair{&e.sky, "sky"}, std::pair{&e.opaque, "opaque"}}) {
      if (stats->pixels == 0 || (sky_only && stats == &e.opaque) ||
          stats->per_pixel_rel_rmse < worst.per_pixel_rel_rmse)
        continue;
      worst = {stats->per_pixel_rel_rmse, a.view + " " + name};
    }
  }
  return worst;
}

const ClassErrors& FroxelVsPerPixel(const ViewAccuracy& a) { return a.froxel_vs_per_pixel; }
const ClassErrors& PerPixelVsReference(const ViewAccuracy& a) { return a.per_pixel_vs_reference; }
const ClassErrors& ThreeDVsFourD(const ViewAccuracy& a) { return *a.vs_4d; }

}  // namespace

std::vector<std::string> Recommendations(const BenchResults& b) {
  const TableTier& tier = b.plan.tiers.at(b.plan.figure_tier);
  const VariantResult& lut4d = b.Find(tier.name, LutVariant::k4D);
  const VariantResult& lut3d = b.Find(tier.name, LutVariant::k3D);
  std::vector<const char*> all_views(std::begin(kDaylightViews), std::end(kDaylightViews));
  all_views.insert(all_views.end(), std::begin(kLowSunViews), std::end(kLowSunViews));
  std::vector<std::string> lines;

  std::vector<const char*> frame_views = all_views;
  for (const std::string& view : b.plan.shadow_views) frame_views.push_back(view.c_str());
  Worst froxel = WorstOf(lut4d, frame_views, FroxelVsPerPixel);
  lines.push_back("- **Real-time frames (the viewer, an engine)**: the froxel path, " +
                  Format("%.1f", lut4d.FrameMs()) + " ms a frame here against " +
                  Format("%.1f", lut4d.TableDifferenceFrameMs()) +
                  " ms for two table reads per pixel (Bruneton 2017's demo) and " +
                  Format("%.0f", lut4d.PerPixelFrameMs()) + " ms marched per pixel; at most " +
                  Percent(froxel.per_pixel_rel_rmse) + " RMSE from the marched path (" + froxel.where + ").");

  Worst low_sun = WorstOf(lut3d, kLowSunViews, ThreeDVsFourD, true);
  lines.push_back("- **Any sun, sunsets and twilight included**: the 4D tables; with the sun low the 3D "
                  "tables' sky is " + Percent(low_sun.per_pixel_rel_rmse) + " RMSE from theirs (" + low_sun.where +
                  "): they have no Earth's shadow along the view ray.");

  Worst daylight = WorstOf(lut3d, kDaylightViews, ThreeDVsFourD);
  double smaller = double(lut4d.precompute.table_bytes) / double(lut3d.precompute.table_bytes);
  lines.push_back(daylight.per_pixel_rel_rmse <= kDaylightTolerance
                      ? "- **Daylight only, memory tight**: the 3D tables, " + Format("%.1f", smaller) +
                            "x smaller, within " + Percent(daylight.per_pixel_rel_rmse) + " RMSE of the 4D frames (" +
                            daylight.where + ")."
                      : "- **Daylight only, memory tight**: not the 3D tables at this resolution: " +
                            Percent(daylight.per_pixel_rel_rmse) + " RMSE from the 4D frames (" + daylight.where +
                            "), above " + Percent(kDaylightTolerance) + ".");

  Worst reference = WorstOf(lut4d, all_views, PerPixelVsReference, true);
  lines.push_back("- **Reference images, validation**: `--aerial per-pixel` with the 4D tables, " +
                  Format("%.0f", lut4d.PerPixelFrameMs()) + " ms a frame here; its sky is within " +
                  Percent(reference.per_pixel_rel_rmse) + " RMSE of the CPU reference (" + reference.where + ").");
  if (b.plan.quick) {
    std::string tiers;
    for (const TableTier& t : b.plan.tiers) tiers += (tiers.empty() ? "" : ", ") + t.name;
    lines.push_back("- Quick mode measures the " + tiers +
                    " tables only, not the default ones: `aerial bench` without `--quick` does.");
  }
  return lines;
}

}  // namespace aerial::bench
