// The report's recommendations follow the run's figures: the 3D tables are recommended for
// daylight only while they stay within the tolerance, and each line names the figure it rests on.
#include "aerial/bench/recommendations.h"

#include <gtest/gtest.h>

#include "aerial/bench/bruneton_2017.h"

namespace aerial::bench {
namespace {

ClassErrors Errors(double sky, double opaque) {
  return {.sky = {.pixels = 10, .per_pixel_rel_rmse = sky}, .opaque = {.pixels = 10, .per_pixel_rel_rmse = opaque}};
}

RunResult Frame(double ms) { return {.passes = {{"frame", ms}}}; }

// A quick run's results: 3D frames `daylight_3d` from the 4D ones in daylight, 30% at sunset.
BenchResults Results(double daylight_3d) {
  BenchResults b{.plan = BenchPlan::Quick()};
  for (LutVariant variant : {LutVariant::k4D, LutVariant::k3D})
    for (const TableTier& tier : b.plan.tiers) {
      VariantResult r{.tier = tier.name};
      r.precompute.options = tier.Options(variant);
      r.precompute.table_bytes = variant == LutVariant::k4D ? 8000 : 1000;
      r.froxel_frames = {Frame(80.0)};
      r.per_pixel_frames = {Frame(4000.0)};
      r.table_difference_frames = {Frame(150.0)};
      for (const std::string& view : b.plan.views) {
        bool low_sun = view == "sunset" || view == "twilight";
        ViewAccuracy a{.view = view,
                       .per_pixel_vs_reference = Errors(view == "twilight" ? 0.023 : 0.01, 0.2),
                       .froxel_vs_per_pixel = Errors(0.001, view == "sunset" ? 0.0137 : 0.005)};
        if (variant == LutVariant::k3D) a.vs_4d = Errors(low_sun ? 0.3 : daylight_3d, daylight_3d / 2);
        r.accuracy.push_back(a);
      }
      b.results.push_back(r);
    }
  return b;
}

std::string Joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

TEST(Recommendations, NameTheFiguresTheyRestOn) {
  std::string text = Joined(Recommendations(Results(0.004)));
  EXPECT_NE(text.find("froxel path, 80.0 ms a frame here against 150.0 ms"), std::string::npos) << text;
  EXPECT_NE(text.find("at most 1.37% RMSE from the marched path (sunset opaque)"), std::string::npos) << text;
  EXPECT_NE(text.find("4D tables; with the sun low the 3D tables' sky is 30.0% RMSE"), std::string::npos) << text;
  EXPECT_NE(text.find("within 2.30% RMSE of the CPU reference (twilight sky)"), std::string::npos) << text;
  EXPECT_NE(text.find("Quick mode measures the tiny, small tables only"), std::string::npos) << text;
}

// Both sides of the tolerance: recommended at 0.9%, not at 1.1%.
TEST(Recommendations, ThreeDTablesForDaylightOnlyWithinTheTolerance) {
  std::string within = Joined(Recommendations(Results(0.009)));
  EXPECT_NE(within.find("the 3D tables, 8.0x smaller, within 0.90% RMSE"), std::string::npos) << within;
  std::string beyond = Joined(Recommendations(Results(0.011)));
  EXPECT_NE(beyond.find("not the 3D tables at this resolution: 1.10% RMSE"), std::string::npos) << beyond;
}

// The anchor's precompute figure was taken on llvmpipe: lavapipe reports that name; a GPU does not.
TEST(Bruneton2017, SpeedUpOnlyOnTheAnchorsDriver) {
  EXPECT_TRUE(IsBruneton2017Device("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_FALSE(IsBruneton2017Device("NVIDIA H200"));
}

}  // namespace
}  // namespace aerial::bench
