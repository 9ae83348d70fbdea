#include "aerial/viewer/frame_stats.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace aerial::viewer {
namespace {

TEST(Percentile, IsNearestRank) {
  std::vector<double> values = {5, 1, 4, 2, 3};
  EXPECT_EQ(Percentile(values, 50.0), 3.0);
  EXPECT_EQ(Percentile(values, 95.0), 5.0);  // rank ceil(4.75) = 5
  EXPECT_EQ(Percentile(values, 20.0), 1.0);
  EXPECT_EQ(Percentile({}, 50.0), 0.0);
}

TEST(FrameStats, JsonHasTheScriptedKeys) {
  FrameStats stats;
  for (int i = 1; i <= 20; ++i) {
    stats.AddFrame(10.0 * i);
    stats.AddGpuFrame({{"froxel build", 1.0 * i}, {"opaque raster", 2.0}});
  }
  stats.AddFrame(1000.0);
  stats.AddGpuFrame({{"present", 0.5}});
  stats.AddGpuFrame({});  // a frame whose times were not read: not counted
  auto json = nlohmann::json::parse(stats.ToJson());
  EXPECT_EQ(json["frames"], 21);
  EXPECT_EQ(json["median_frame_ms"], 110.0);  // 11th of 21
  EXPECT_EQ(json["p95_frame_ms"], 200.0);     // rank ceil(19.95) = 20
  EXPECT_NEAR(json["fps_median"].get<double>(), 1000.0 / 110.0, 1e-12);
  // GPU frames 3, 4, ..., 22 ms and 0.5 ms: the 11th of 21 is 12 (frame 10: 10 + 2).
  EXPECT_EQ(json["median_gpu_frame_ms"], 12.0);
  EXPECT_EQ(json["passes"]["froxel build"], 10.0);  // 10th of 20 frames that ran it
  EXPECT_EQ(json["passes"]["opaque raster"], 2.0);
  EXPECT_EQ(json["passes"]["present"], 0.5);
  EXPECT_EQ(stats.MedianFrameMs(3), 200.0);  // frames 190, 200, 1000
}

TEST(FrameStats, JsonListsEachFrameInOrder) {
  FrameStats stats;
  stats.AddFrame(30.0, 1.0);
  stats.AddFrame(10.0, 0.5);
  stats.AddGpuFrame({{"froxel build", 4.0}, {"present", 1.0}});
  stats.AddFrame(20.0, 0.75);
  auto json = nlohmann::json::parse(stats.ToJson());
  EXPECT_EQ(json["frame_ms"], nlohmann::json({30.0, 10.0, 20.0}));
  EXPECT_EQ(json["render_scale"], nlohmann::json({1.0, 0.5, 0.75}));
  EXPECT_EQ(json["gpu_frame_ms"], nlohmann::json({5.0}));
}

}  // namespace
}  // namespace aerial::viewer
