// `aerial bench --quick` as users run it: the report's files and structure, comparisons that cover
// every pixel, and what the command exists to show, at the figures of docs/tables-3d-4d.md (the 3D tables are
// smaller, close to the 4D ones in daylight and far from them at sunset), from one run.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "command_run.h"

namespace aerial::testing {
namespace {

namespace fs = std::filesystem;

const char* const kViews[] = {"noon", "afternoon", "sunset", "twilight", "high-altitude"};

std::string ReadText(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}

void CheckFilesAndStructure(const fs::path& dir, const nlohmann::json& results) {
  for (const char* file : {"report.md", "results.json", "results.csv", "precompute-vs-memory.png"})
    EXPECT_TRUE(fs::is_regular_file(dir / file)) << file;
  for (const char* view : kViews)
    EXPECT_TRUE(fs::is_regular_file(dir / (std::string(view) + ".png"))) << view;

  std::string report = ReadText(dir / "report.md");
  report.insert(report.begin(), '\n');  // every heading starts a line
  for (const char* heading :
       {"# aerial bench", "## Machine", "## Summary", "### Recommendations", "## Speed and size", "## Accuracy",
        "### What is compared", "### 3D tables against 4D tables",
        "### Against the CPU reference, froxel path", "### Against the CPU reference, per-pixel path",
        "### Froxel path against per-pixel path", "### Against the CPU reference, two table reads per pixel",
        "### Reference sampling", "## Figures"})
    EXPECT_NE(report.find('\n' + std::string(heading)), std::string::npos) << heading;
  EXPECT_NE(report.find("aerial bench --quick"), std::string::npos) << "the command is in the report";

  std::string csv = ReadText(dir / "results.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "variant,tier,scattering_size,table_bytes,precompute_ms,frame_ms,per_pixel_frame_ms,"
            "table_difference_frame_ms,froxel_build_ms,frame_wall_ms,view,comparison,pixels,pixel_count,rel_rmse,"
            "rel_max");

  EXPECT_EQ(results["mode"], "quick");
  ASSERT_TRUE(results["results"].is_array());
  std::set<std::string> variants;
  for (const auto& entry : results["results"]) {
    for (const char* key : {"variant", "tier", "resolution", "table_bytes", "precompute_ms", "frame_ms",
                            "per_pixel_frame_ms", "table_difference_frame_ms", "froxel_build_ms", "frame_wall_ms",
                            "accuracy"})
      EXPECT_TRUE(entry.contains(key)) << key;
    variants.insert(entry["variant"].get<std::string>());
    for (const char* view : kViews) EXPECT_TRUE(entry["accuracy"].contains(view)) << view;
  }
  EXPECT_EQ(variants, (std::set<std::string>{"3d", "4d"}));
}

// docs/tables-3d-4d.md, "Choosing 3D or 4D tables": --quick renders 320x180 images and samples the reference
// at 8x5 pixels.
constexpr int kImagePixels = 320 * 180;
constexpr int kReferencePixels = 8 * 5;

// Times are positive, errors finite, and each comparison covers all its pixels: those of the
// image (sky and opaque), or, against the reference, the grid's but those left out (that see the
// sun disc, or where the scene has no surface at the renderer's depth).
void CheckNumbersAndCoverage(const nlohmann::json& results) {
  std::map<std::string, int> left_out;
  for (const auto& reference : results["reference"])
    left_out[reference["view"].get<std::string>()] =
        reference["sun_pixels_left_out"].get<int>() + reference["unmatched_pixels_left_out"].get<int>();
  for (const auto& entry : results["results"]) {
    // Quick mode does not time the marched per-pixel path (bench_plan.h): null in every tier.
    EXPECT_TRUE(entry["per_pixel_frame_ms"].is_null()) << entry["variant"] << " " << entry["tier"];
    for (const char* key : {"table_bytes", "precompute_ms", "frame_ms", "table_difference_frame_ms",
                            "froxel_build_ms", "frame_wall_ms"}) {
      ASSERT_TRUE(entry[key].is_number()) << entry["variant"] << " " << entry["tier"] << " " << key;
      double v = entry[key].get<double>();
      EXPECT_TRUE(std::isfinite(v) && v > 0.0)
          << entry["variant"] << " " << entry["tier"] << " " << key << " = " << v;
    }
    for (const auto& [view, comparisons] : entry["accuracy"].items())
      for (const auto& [name, classes] : comparisons.items()) {
        std::string where = entry["variant"].get<std::string>() + " " + entry["tier"].get<std::string>() +
                            " " + view + " " + name;
        int pixels = 0;
        for (const auto& [pixel_class, e] : classes.items()) {
          pixels += e["pixels"].get<int>();
          double rmse = e["rel_rmse"].get<double>(), max = e["rel_max"].get<double>();
          EXPECT_TRUE(std::isfinite(rmse) && std::isfinite(max) && rmse >= 0.0) << where << " " << pixel_class;
        }
        bool against_reference = name.ends_with("_vs_reference");
        if (against_reference) {
          ASSERT_TRUE(left_out.count(view)) << view;
        }
        EXPECT_EQ(pixels, against_reference ? kReferencePixels - left_out[view] : kImagePixels) << where;
      }
  }
}

const nlohmann::json& Entry(const nlohmann::json& results, const std::string& variant, const std::string& tier) {
  for (const auto& entry : results["results"])
    if (entry["variant"] == variant && entry["tier"] == tier) return entry;
  static const nlohmann::json kNone;
  ADD_FAILURE() << "no " << variant << " entry for tier " << tier;
  return kNone;
}

double MiB(const nlohmann::json& entry) { return entry["table_bytes"].get<double>() / (1 << 20); }

// The figures docs/tables-3d-4d.md states for the two variants, in both tiers of the quick run.
void CheckThreeDAgainstFourD(const nlohmann::json& results) {
  // docs/tables-3d-4d.md's table of speed and size, "small" rows (16x64x16 scattering, Small() otherwise):
  // 4.13 and 0.83 MiB, to the printed 0.01 MiB.
  EXPECT_NEAR(MiB(Entry(results, "4d", "small")), 4.13, 0.005);
  EXPECT_NEAR(MiB(Entry(results, "3d", "small")), 0.83, 0.005);
  for (const char* tier : {"tiny", "small"}) {
    SCOPED_TRACE(tier);
    const nlohmann::json& lut3d = Entry(results, "3d", tier);
    // One nu slice instead of 8: the scattering tables are 8x smaller.
    EXPECT_LT(lut3d["table_bytes"].get<double>(), Entry(results, "4d", tier)["table_bytes"].get<double>());
    auto difference = [&](const char* view, const char* pixels) -> const nlohmann::json& {
      return lut3d["accuracy"][view]["3d_vs_4d"][pixels];
    };
    // docs/tables-3d-4d.md, "Choosing 3D or 4D tables": in daylight (noon, afternoon, 30 km up) the 3D tables
    // stay within 1% RMSE of the 4D ones (there measured with the default tables; the error is the
    // 3D assumption's, which every tier shares). Not 0: they drop the nu axis, so equal frames
    // would mean the bench compared a variant with itself.
    for (const char* view : {"noon", "afternoon", "high-altitude"})
      for (const char* pixels : {"sky", "opaque"}) {
        double rmse = difference(view, pixels)["rel_rmse"].get<double>();
        EXPECT_GT(rmse, 0.0) << view << " " << pixels;
        EXPECT_LT(rmse, 0.01) << view << " " << pixels;
      }
    // docs/tables-3d-4d.md, "The 3D tables": at most 3.9% from the 4D sky in daylight (sun zenith <= 80
    // degrees, cameras 0-30 km, views above the horizon): the largest sky pixel's error in the
    // two daylight views from the ground.
    for (const char* view : {"noon", "afternoon"})
      EXPECT_LT(difference(view, "sky")["rel_max"].get<double>(), 0.039) << view;
    // docs/tables-3d-4d.md: with the sun at or below the horizon the 3D tables lose the Earth's shadow
    // along the view ray, at any resolution: the loss is their parameterization's. At twilight, looking
    // away from the sun into the shadow, it stands at 84% (small) and 186% (tiny): bound at ten times
    // the daylight 1%. The sunset view looks toward the sun, where little of the sky lies in the
    // shadow: 5.1% (small) and 9.1% (tiny), bound at three times the daylight 1%, so that the view
    // still shows why 4D is chosen for sunsets.
    EXPECT_GT(difference("twilight", "sky")["rel_rmse"].get<double>(), 0.10);
    EXPECT_GT(difference("sunset", "sky")["rel_rmse"].get<double>(), 0.03);
  }
}

// What the per-pixel frame of Bruneton 2017's demo (two table reads, no march) is there to show:
// at a low sun its sky, read without the correction of the Earth's shadow (sky_lookup.glsl), is
// further from the reference than the marched path's. Measured with the small 4D tables
// (docs/accuracy.md, "Radiance to a point"): sunset sky 0.57% against 8.0% RMSE, twilight 2.3%
// against 17.6%. What it costs against the march is the report's figure to show, not this test's
// to bound: a time depends on the machine and its load.
void CheckTableDifference(const nlohmann::json& results) {
  const nlohmann::json& lut4d = Entry(results, "4d", "small");
  for (const char* view : {"sunset", "twilight"}) {
    const nlohmann::json& accuracy = lut4d["accuracy"][view];
    double marched = accuracy["per_pixel_vs_reference"]["sky"]["rel_rmse"].get<double>();
    double two_reads = accuracy["table_difference_vs_reference"]["sky"]["rel_rmse"].get<double>();
    // Twice: the uncorrected order 1 is 13-27% off around sun zenith 95 degrees (sky_lookup.glsl),
    // the marched path within the reference's noise (1.3% at sunset, 8.8% at twilight).
    EXPECT_GT(two_reads, 2.0 * marched) << view;
  }
  // In every view the two frames differ, so the bench did not render one path twice (identical
  // frames give identical errors); and the two-read frames were timed, pass by pass.
  for (const char* view : kViews) {
    const nlohmann::json& accuracy = lut4d["accuracy"][view];
    EXPECT_NE(accuracy["per_pixel_vs_reference"]["sky"]["rel_rmse"].get<double>(),
              accuracy["table_difference_vs_reference"]["sky"]["rel_rmse"].get<double>())
        << view;
  }
  EXPECT_FALSE(lut4d["frame_pass_median_ms"]["table_difference"].empty());
}

// The shadow views (bench_plan.h): in quick mode the figure tier's only, the froxel path against
// the per-pixel path alone, both with the sun's shadows. Measured with the small tables at 320x180,
// opaque pixels: 2.1% RMSE at evening and 3.1% at sunrise, from the froxels' resolution across the
// shadows' edges (docs/accuracy.md): bound at 4%, and above 0.1% (equal frames would mean that one
// path was rendered twice).
void CheckShadowViews(const nlohmann::json& results) {
  for (const char* variant : {"4d", "3d"}) {
    EXPECT_FALSE(Entry(results, variant, "tiny")["accuracy"].contains("evening")) << variant;
    const nlohmann::json& accuracy = Entry(results, variant, "small")["accuracy"];
    for (const char* view : {"evening", "sunrise"}) {
      ASSERT_TRUE(accuracy.contains(view)) << variant << " " << view;
      EXPECT_EQ(accuracy[view].size(), 1u) << variant << " " << view << ": froxel_vs_per_pixel alone";
      double opaque = accuracy[view]["froxel_vs_per_pixel"]["opaque"]["rel_rmse"].get<double>();
      EXPECT_GT(opaque, 0.001) << variant << " " << view;
      EXPECT_LT(opaque, 0.04) << variant << " " << view;
    }
  }
}

// One run (a test process each would run it again) checked for five things: its files and their
// structure, its numbers and what they cover, the 3D tables against the 4D, the two table reads, and
// the shadow views.
TEST(BenchQuick, ReportFilesNumbersAndComparisons) {
  fs::path dir = fs::temp_directory_path() / ("aerial-bench-test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  CommandRun run = RunAerial("bench --quick --quiet --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  nlohmann::json results = nlohmann::json::parse(ReadText(dir / "results.json"));
  {
    SCOPED_TRACE("files and structure");
    CheckFilesAndStructure(dir, results);
  }
  {
    SCOPED_TRACE("numbers and coverage");
    CheckNumbersAndCoverage(results);
  }
  {
    SCOPED_TRACE("3D against 4D");
    CheckThreeDAgainstFourD(results);
  }
  {
    SCOPED_TRACE("two table reads per pixel");
    CheckTableDifference(results);
  }
  {
    SCOPED_TRACE("shadow views");
    CheckShadowViews(results);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace aerial::testing
