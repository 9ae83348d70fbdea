#include "aerial/viewer/dynamic_resolution.h"

#include <gtest/gtest.h>

namespace aerial::viewer {
namespace {

// Frames of a fixed part and a part per pixel: ms = fixed + per_pixel * scale^2.
float RunFrames(DynamicResolution& controller, float scale, double per_pixel_ms, int frames, double fixed_ms = 0.0) {
  for (int i = 0; i < frames; ++i) scale = controller.Update(fixed_ms + per_pixel_ms * scale * scale, scale);
  return scale;
}

// A slow frame is answered after kStepDownFrames frames, straight to the scale the pixel ratio
// predicts: 100 ms at full scale, target 33 ms: 0.75 predicts 56 ms, 0.5 25 ms.
TEST(DynamicResolution, StepsDownAtOnceToTheScaleThatFits) {
  DynamicResolution controller(33.0);
  EXPECT_EQ(RunFrames(controller, 1.0f, 100.0, DynamicResolution::kStepDownFrames - 1), 1.0f) << "waits for a few";
  EXPECT_EQ(RunFrames(controller, 1.0f, 100.0, 1), 0.5f);
  // 50 ms at full scale: 0.75 predicts 28 ms, within the target.
  DynamicResolution nearer(33.0);
  EXPECT_EQ(RunFrames(nearer, 1.0f, 50.0, DynamicResolution::kStepDownFrames), 0.75f);
}

// Parts of the frame that do not shrink keep it over the target at every scale: the controller
// goes no lower than kMinScale, and stays there.
TEST(DynamicResolution, GoesNoLowerThanItsFloor) {
  DynamicResolution controller(33.0);
  // 70 ms at full scale, 40 of it per pixel: 0.5 predicts 17.5 ms but takes 40.
  EXPECT_EQ(RunFrames(controller, 1.0f, 40.0, DynamicResolution::kStepDownFrames, 30.0), 0.5f);
  EXPECT_EQ(RunFrames(controller, 0.5f, 40.0, 10 * DynamicResolution::kSettleFrames, 30.0), DynamicResolution::kMinScale);
  // A smaller scale set by hand stays while the frame is slow.
  DynamicResolution by_hand(33.0);
  EXPECT_EQ(RunFrames(by_hand, 0.25f, 40.0, 10 * DynamicResolution::kSettleFrames, 40.0), 0.25f);
}

// One slow frame among fast ones moves nothing: the median of the last few decides.
TEST(DynamicResolution, OneSlowFrameIsNotASlowView) {
  DynamicResolution controller(33.0);
  float scale = 1.0f;
  for (int i = 0; i < 5 * DynamicResolution::kSettleFrames; ++i)
    scale = controller.Update(i % 4 == 3 ? 90.0 : 20.0, scale);
  EXPECT_EQ(scale, 1.0f);
}

// When the load drops, the scale climbs back after kSettleFrames frames, as far as the pixel
// ratio (an upper bound) predicts under 85% of the target.
TEST(DynamicResolution, StepsUpWhenTheLargerScaleWouldFit) {
  DynamicResolution controller(33.0);
  EXPECT_EQ(RunFrames(controller, 0.5f, 20.0, DynamicResolution::kSettleFrames - 1), 0.5f) << "waits to settle";
  EXPECT_EQ(RunFrames(controller, 0.5f, 20.0, 1), 1.0f);  // 5 ms at 0.5: 20 ms at 1, under 28
  DynamicResolution partway(33.0);
  EXPECT_EQ(RunFrames(partway, 0.5f, 40.0, DynamicResolution::kSettleFrames), 0.75f);  // 22.5 ms at 0.75, 40 at 1
  DynamicResolution tight(33.0);
  // 30 ms at full scale is over 85% of 33: from 0.75 (16.9 ms) it does not step up.
  EXPECT_EQ(RunFrames(tight, 0.75f, 30.0, 10 * DynamicResolution::kSettleFrames), 0.75f);
}

}  // namespace
}  // namespace aerial::viewer
