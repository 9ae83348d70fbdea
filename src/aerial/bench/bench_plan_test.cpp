// Quick mode times the marched per-pixel path once, with the figure tier's tables only, and the
// report says "not measured" for the other tiers instead of inventing a time: "—" in the
// markdown, null in the JSON, an empty CSV field.
#include "aerial/bench/bench_plan.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "aerial/bench/bench_results.h"
#include "aerial/bench/number_text.h"
#include "aerial/bench/report_markdown.h"
#include "aerial/bench/results_files.h"

namespace aerial::bench {
namespace {

// The quick run leaves the marched per-pixel path's seconds-long frames out; the full run times
// them in every tier, as the other paths.
TEST(BenchPlan, OnlyTheFullRunTimesThePerPixelPath) {
  const BenchPlan quick = BenchPlan::Quick(), full = BenchPlan::Full();
  ASSERT_EQ(quick.tiers.size(), 2u);
  for (size_t t = 0; t < quick.tiers.size(); ++t) EXPECT_EQ(quick.PerPixelFrames(t), 0) << quick.tiers[t].name;
  for (size_t t = 0; t < full.tiers.size(); ++t) EXPECT_EQ(full.PerPixelFrames(t), full.frames) << full.tiers[t].name;
}

RunResult Frame(double ms) { return {.passes = {{"frame", ms}}}; }

// Both variants of both quick tiers, per-pixel frames only in the figure tier (a plan that times
// them there, to read how a frame not timed is reported beside one that is).
BenchResults QuickResults() {
  BenchResults b{.plan = BenchPlan::Quick()};
  b.plan.per_pixel_frames_figure_tier_only = 1;
  for (size_t t = 0; t < b.plan.tiers.size(); ++t)
    for (LutVariant variant : {LutVariant::k4D, LutVariant::k3D}) {
      VariantResult r{.tier = b.plan.tiers[t].name};
      r.precompute.options = b.plan.tiers[t].Options(variant);
      r.precompute.runs = {Frame(100.0)};
      r.froxel_frames = {{.passes = {{"froxel build", 10.0}, {"frame", 70.0}}}};
      r.table_difference_frames = {Frame(150.0)};
      r.accuracy = {{.view = "noon"}};
      if (b.plan.PerPixelFrames(t) > 0) r.per_pixel_frames = {Frame(variant == LutVariant::k4D ? 4000.0 : 3000.0)};
      b.results.push_back(r);
    }
  return b;
}

// --colour reaches every table the bench precomputes, and the results say which they were.
TEST(BenchPlan, ColourReachesTheTablesAndTheResults) {
  BenchPlan plan = BenchPlan::Quick();
  EXPECT_EQ(plan.colour, ColourMode::kSpectral);  // the default of every command (docs/colour.md)
  plan.colour = ColourMode::kRgb;
  for (const TableTier& tier : plan.tiers)
    for (LutVariant variant : {LutVariant::k4D, LutVariant::k3D})
      EXPECT_EQ(tier.Options(variant, plan.colour).colour, ColourMode::kRgb) << tier.name;
  BenchResults results = QuickResults();
  EXPECT_EQ(ResultsJson(results)["settings"]["colour"], "spectral");
  results.plan.colour = ColourMode::kRgb;
  EXPECT_EQ(ResultsJson(results)["settings"]["colour"], "rgb");
}

TEST(BenchPlan, AFrameNotTimedIsReportedAsNotMeasured) {
  BenchResults b = QuickResults();
  const std::string tiny = b.plan.tiers[0].name, small = b.plan.tiers[1].name;
  EXPECT_FALSE(b.Find(tiny, LutVariant::k4D).PerPixelFrameMs().has_value());
  EXPECT_EQ(b.Find(small, LutVariant::k4D).PerPixelFrameMs(), 4000.0);
  EXPECT_FALSE(PerPixelFrameRatio(b.Find(tiny, LutVariant::k3D), b.Find(tiny, LutVariant::k4D)).has_value());
  EXPECT_EQ(PerPixelFrameRatio(b.Find(small, LutVariant::k3D), b.Find(small, LutVariant::k4D)), 0.75);
  EXPECT_EQ(Format("%.1f", std::optional<double>()), "—");
  EXPECT_EQ(Format("%.1f", std::optional<double>(2.25)), "2.2");

  nlohmann::json json = ResultsJson(b);
  for (const auto& entry : json["results"]) {
    bool timed = entry["tier"] == small;
    EXPECT_EQ(entry["per_pixel_frame_ms"].is_null(), !timed) << entry["tier"];
    if (timed) {
      EXPECT_GT(entry["per_pixel_frame_ms"].get<double>(), 0.0);
    }
  }
  for (const auto& ratios : json["ratios_3d_over_4d"])
    EXPECT_EQ(ratios["per_pixel_frame_ms"].is_null(), ratios["tier"] == tiny) << ratios["tier"];

  // The CSV's seventh field, per_pixel_frame_ms: empty for the tiny tables, a time for the small.
  std::istringstream csv(ResultsCsv(b));
  std::string line;
  std::getline(csv, line);  // the header
  int rows = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> fields;
    std::istringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
    ASSERT_GT(fields.size(), 6u) << line;
    bool timed = fields[1] == small;
    EXPECT_EQ(fields[6].empty(), !timed) << line;
    if (timed) {
      EXPECT_EQ(fields[6], fields[0] == "4d" ? "4000" : "3000") << line;
    }
    ++rows;
  }
  EXPECT_GT(rows, 0);

  // The speed table's rows: the tiny ones say "—" in the per-pixel column, the small ones a time.
  std::string table = SpeedTable(b);
  EXPECT_NE(table.find("| 80.0 | — | 150.0 |"), std::string::npos) << table;
  EXPECT_NE(table.find("| 80.0 | 4000.0 | 150.0 |"), std::string::npos) << table;
  EXPECT_NE(table.find("| 80.0 | 3000.0 | 150.0 |"), std::string::npos) << table;
}

}  // namespace
}  // namespace aerial::bench
