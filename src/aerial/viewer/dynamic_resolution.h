#pragma once
// Dynamic resolution (`aerial view --target-ms MS`): the render scale follows the frame time, as
// engines do on weak hardware. A frame's time at another scale is predicted as its time at this
// scale times the ratio of their pixels: too low for a smaller scale (parts of the frame do not
// shrink with the pixels: the froxel volume, the shadow map, the present at the window's size),
// and so a safe bound for a larger one. Slow frames are answered quickly and fast ones slowly, so
// that the view does not stutter for long and the scale does not swing:
//   - when the median of the last kStepDownFrames frames is over the target, the scale drops to
//     the largest one predicted to meet it (to kMinScale when none is);
//   - when the median of the last kSettleFrames frames, all at this scale, predicts a larger scale
//     under kStepUpFraction of the target, it rises to the largest such scale.
// Only frames of a moving view count: a still view is drawn at scale 1 (viewer.cpp), as `aerial
// render` draws it.
#include <array>
#include <vector>

namespace aerial::viewer {

// The viewer's target on a CPU device unless told otherwise: 30 frames a second.
inline constexpr double kCpuDeviceTargetMs = 1000.0 / 30.0;

// The scales the panel offers, largest first.
inline constexpr std::array<float, 4> kRenderScales = {1.0f, 0.75f, 0.5f, 0.25f};

class DynamicResolution {
 public:
  static constexpr int kStepDownFrames = 4;
  static constexpr int kSettleFrames = 12;
  static constexpr double kStepUpFraction = 0.85;
  // The smallest scale the controller chooses, and the one a moving view starts at (a smaller
  // scale set by hand is kept until the controller steps). Below half, the parts of the frame that
  // do not shrink with the pixels are most of it: on lavapipe the corridor flight's frame goes
  // from about 42 ms at 0.5 to 34 ms at 0.25, a fifth of the time for three quarters of the
  // pixels. Starting low and climbing trades a few soft frames for no stutter at the start.
  // Unreal's dynamic resolution has the same floor by default (r.DynamicRes.MinScreenPercentage 50).
  static constexpr float kMinScale = 0.5f;

  explicit DynamicResolution(double target_ms) : target_ms_(target_ms) {}

  // Records a frame drawn at `scale` that took frame_ms; returns the scale for the next frames.
  float Update(double frame_ms, float scale);

 private:
  double target_ms_;
  std::vector<double> since_step_;  // frame times since the last step
};

}  // namespace aerial::viewer
