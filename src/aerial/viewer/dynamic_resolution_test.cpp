#include "aerial/viewer/dynamic_resolution.h"

#include <gtest/gtest.h>

namespace aerial::viewer {
namespace {

// Frames of a fixed cost per pixel: ms = cost * scale^2.
float RunFrames(DynamicResolution& controller, float scale, double ms_at_full_scale, int frames) {
  for (int i = 0; i < frames; ++i) scale = controller.Update(ms_at_full_scale * scale * scale, scale);
  return scale;
}

// A frame twice the target at full scale settles at 0.5 (a quarter of the pixels), one step per
// settle period; a frame within the target stays at 1.
TEST(DynamicResolution, StepsDownUntilTheFrameFitsTheTarget) {
  DynamicResolution controller(33.0);
  EXPECT_EQ(RunFrames(controller, 1.0f, 66.0, DynamicResolution::kSettleFrames - 1), 1.0f) << "waits to settle";
  EXPECT_EQ(RunFrames(controller, 1.0f, 66.0, 1), 0.75f);
  // 66 * 0.5625 = 37 ms is still above: one more step after the next settle period.
  EXPECT_EQ(RunFrames(controller, 0.75f, 66.0, DynamicResolution::kSettleFrames), 0.5f);
  // 66 * 0.25 = 16.5 ms; 0.75 would take 37 ms: it stays.
  EXPECT_EQ(RunFrames(controller, 0.5f, 66.0, 10 * DynamicResolution::kSettleFrames), 0.5f);
  DynamicResolution fits(33.0);
  EXPECT_EQ(RunFrames(fits, 1.0f, 30.0, 10 * DynamicResolution::kSettleFrames), 1.0f);
}

// When the load drops, the scale climbs back, but only while the next scale is predicted under
// 85% of the target.
TEST(DynamicResolution, StepsUpWhenTheLargerScaleWouldFit) {
  DynamicResolution controller(33.0);
  EXPECT_EQ(RunFrames(controller, 0.5f, 20.0, DynamicResolution::kSettleFrames), 0.75f);  // 11.25 ms at 0.75
  EXPECT_EQ(RunFrames(controller, 0.75f, 20.0, DynamicResolution::kSettleFrames), 1.0f);  // 20 ms at 1
  DynamicResolution tight(33.0);
  // 30 ms at full scale is over 85% of 33: from 0.75 (16.9 ms) it does not step up.
  EXPECT_EQ(RunFrames(tight, 0.75f, 30.0, 10 * DynamicResolution::kSettleFrames), 0.75f);
}

}  // namespace
}  // namespace aerial::viewer
