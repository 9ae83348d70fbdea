#include "aerial/viewer/dynamic_resolution.h"

#include <algorithm>

#include "aerial/viewer/frame_stats.h"

namespace aerial::viewer {

float DynamicResolution::Update(double frame_ms, float scale) {
  since_step_.push_back(frame_ms);
  const int frames = int(since_step_.size());
  if (frames < kStepDownFrames) return scale;
  // Slow frames are judged over the last few, fast ones over the whole window.
  const double recent = Percentile({since_step_.end() - kStepDownFrames, since_step_.end()}, 50.0);
  const double median = Percentile(since_step_, 50.0);
  auto predicted = [&](double ms, float other) { return ms * (double(other) * other) / (double(scale) * scale); };
  float next = scale;
  if (recent > target_ms_) {
    next = std::min(scale, kMinScale);  // a scale set by hand below the floor stays
    for (float choice : kRenderScales) {  // largest first
      if (choice < scale && choice >= kMinScale && predicted(recent, choice) <= target_ms_) {
        next = choice;
        break;
      }
    }
  } else if (frames >= kSettleFrames) {
    for (float choice : kRenderScales) {
      if (choice > scale && predicted(median, choice) < kStepUpFraction * target_ms_) {
        next = choice;
        break;
      }
    }
  }
  if (next != scale) since_step_.clear();
  else if (frames >= kSettleFrames) since_step_.erase(since_step_.begin());  // a sliding window
  return next;
}

}  // namespace aerial::viewer
