#pragma once
// Frame times and per-pass GPU times of a viewer session, for the panel and for
// `aerial view --stats FILE`:
//   {"frames": N, "median_frame_ms": ..., "p95_frame_ms": ..., "fps_median": 1000 / median,
//    "median_gpu_frame_ms": ..., "median_render_scale": ..., "passes": {"froxel build": median GPU ms, ...},
//    "frame_ms": [each frame's time, in order], "render_scale": [each frame's scale],
//    "gpu_frame_ms": [each GPU frame's time, in the order they finished]}
// A frame's time is wall clock from the end of the previous frame to the end of its present, so
// it is what a user sees: input, the panel, recording, waiting for the GPU and presenting. Pass
// times are GPU timestamps (on lavapipe, the CPU time of the pass), and a GPU frame is the sum of
// its passes; they arrive when the frame has finished, frames in flight later than its wall
// clock time. Percentiles are nearest-rank.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "aerial/device.h"

namespace aerial::viewer {

// Nearest-rank percentile (p in (0, 100]) of the values; 0 for none.
double Percentile(std::vector<double> values, double p);

class FrameStats {
 public:
  void AddFrame(double frame_ms, double render_scale = 1.0);
  void AddGpuFrame(const std::vector<PassTime>& passes);

  size_t frames() const { return frame_ms_.size(); }
  // Over the last `window` frames (all when 0).
  double MedianFrameMs(size_t window = 0) const;
  // Median GPU time of each pass over the frames that ran it.
  std::map<std::string, double> MedianPassMs() const;

  std::string ToJson() const;
  // Atomically (core/atomic_file.h).
  void Write(const std::filesystem::path& path) const;

 private:
  std::vector<double> frame_ms_, gpu_frame_ms_, render_scale_;
  std::map<std::string, std::vector<double>> pass_ms_;
};

}  // namespace aerial::viewer
