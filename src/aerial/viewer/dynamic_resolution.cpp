#include "aerial/viewer/dynamic_resolution.h"

#include <algorithm>
#include <cmath>

#include "aerial/viewer/frame_stats.h"

namespace aerial::viewer {

float DynamicResolution::Update(double frame_ms, float scale) {
  since_step_.push_back(frame_ms);
  if (int(since_step_.size()) < kSettleFrames) return scale;
  double median = Percentile(since_step_, 50.0);
  // The nearest of the scales (a scale set by hand may lie between them).
  auto at = std::min_element(kRenderScales.begin(), kRenderScales.end(),
                             [&](float a, float b) { return std::abs(a - scale) < std::abs(b - scale); });
  float next = scale;
  if (median > target_ms_ && at + 1 != kRenderScales.end()) {
    next = *(at + 1);
  } else if (at != kRenderScales.begin()) {
    float up = *(at - 1);
    double predicted = median * (double(up) * up) / (double(scale) * scale);
    if (predicted < kStepUpFraction * target_ms_) next = up;
  }
  if (next != scale) since_step_.clear();
  else since_step_.erase(since_step_.begin());  // a sliding window of kSettleFrames frames
  return next;
}

}  // namespace aerial::viewer
