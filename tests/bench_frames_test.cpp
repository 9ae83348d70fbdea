// The benchmarks' frame loop (bench/frame_measurement.h): every source gets its warm-up frames and
// then its measured frames, all of them unless it sets max_frames (the quick bench's marched
// per-pixel path), each with positive GPU and wall-clock times; each round starts one source later.
#include <gtest/gtest.h>

#include "aerial/bench/frame_measurement.h"
#include "aerial/scene.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

class BenchFrames : public GpuTest {};

TEST_F(BenchFrames, EverySourceGetsItsFramesAndAtMostItsLimit) {
  Scene scene = BuildPreset("noon", SmallPublicTables().atmosphere().bottom_radius_m);
  const RenderOptions options{.width = 64, .height = 36};
  SceneRenderer unlimited(SmallPublicTables(), scene, options), limited(SmallPublicTables(), scene, options),
      still(SmallPublicTables(), scene, options);
  std::vector<size_t> calls;
  std::vector<std::vector<bench::RunResult>> frames = bench::MeasureFrames(
      {{.renderer = &unlimited}, {.renderer = &limited, .max_frames = 1},
       {.renderer = &still, .motion = bench::Motion::kStill}},
      scene, /*warmup=*/2, /*frames=*/3, [&](size_t source) { calls.push_back(source); });
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(frames[0].size(), 3u);
  EXPECT_EQ(frames[1].size(), 1u);
  EXPECT_EQ(frames[2].size(), 3u);
  // on_frame after every frame, warm-up included; the limited source stops after its one measured
  // frame (rounds 0 and 1 warm up).
  const std::vector<size_t> rounds = {0, 1, 2, 1, 2, 0, 2, 0, 1, 0, 2, 2, 0};
  EXPECT_EQ(calls, rounds);
  for (const auto& source : frames)
    for (const bench::RunResult& frame : source) {
      EXPECT_FALSE(frame.passes.empty());
      EXPECT_GT(frame.wall_ms, 0.0);
    }
}

}  // namespace
}  // namespace aerial::testing
