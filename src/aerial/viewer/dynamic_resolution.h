#pragma once
// Dynamic resolution (`aerial view --target-ms MS`): the render scale follows the frame time, as
// engines do on weak hardware. The scale steps down one of kRenderScales when the median frame
// time since the last step is above the target, and up when the frame at the next scale, predicted
// as today's frame times the pixel ratio (an upper bound: parts of the frame do not scale with the
// pixels), would take under kStepUpFraction of the target. A step rebuilds the renderer's targets,
// so it waits kSettleFrames frames after the previous one. Only frames of a moving view count: a
// still view is drawn at scale 1 (viewer.cpp), as `aerial render` draws it.
#include <array>
#include <vector>

namespace aerial::viewer {

// The viewer's target on a CPU device unless told otherwise: 30 frames a second.
inline constexpr double kCpuDeviceTargetMs = 1000.0 / 30.0;

// The scales the panel offers and the controller steps through, largest first.
inline constexpr std::array<float, 4> kRenderScales = {1.0f, 0.75f, 0.5f, 0.25f};

class DynamicResolution {
 public:
  static constexpr int kSettleFrames = 12;
  static constexpr double kStepUpFraction = 0.85;

  explicit DynamicResolution(double target_ms) : target_ms_(target_ms) {}

  // Records a frame drawn at `scale` that took frame_ms; returns the scale for the next frames.
  float Update(double frame_ms, float scale);

 private:
  double target_ms_;
  std::vector<double> since_step_;  // frame times since the last step
};

}  // namespace aerial::viewer
