#include "aerial/viewer/frame_stats.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "aerial/core/atomic_file.h"

namespace aerial::viewer {

double Percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  // Nearest rank: the smallest value with at least p% of the values at or below it.
  size_t rank = size_t(std::ceil(p / 100.0 * double(values.size())));
  return values[std::clamp<size_t>(rank, 1, values.size()) - 1];
}

void FrameStats::AddFrame(double frame_ms, double render_scale) {
  frame_ms_.push_back(frame_ms);
  render_scale_.push_back(render_scale);
}

void FrameStats::AddGpuFrame(const std::vector<PassTime>& passes) {
  if (passes.empty()) return;
  double total = 0.0;
  for (const PassTime& pass : passes) {
    pass_ms_[pass.pass].push_back(pass.milliseconds);
    total += pass.milliseconds;
  }
  gpu_frame_ms_.push_back(total);
}

double FrameStats::MedianFrameMs(size_t window) const {
  size_t first = window == 0 || window >= frame_ms_.size() ? 0 : frame_ms_.size() - window;
  return Percentile({frame_ms_.begin() + first, frame_ms_.end()}, 50.0);
}

std::map<std::string, double> FrameStats::MedianPassMs() const {
  std::map<std::string, double> medians;
  for (const auto& [name, times] : pass_ms_) medians[name] = Percentile(times, 50.0);
  return medians;
}

std::string FrameStats::ToJson() const {
  double median = MedianFrameMs();
  nlohmann::json json = {{"frames", frames()},
                         {"median_frame_ms", median},
                         {"p95_frame_ms", Percentile(frame_ms_, 95.0)},
                         {"fps_median", median > 0.0 ? 1000.0 / median : 0.0},
                         {"median_gpu_frame_ms", Percentile(gpu_frame_ms_, 50.0)},
                         {"median_render_scale", Percentile(render_scale_, 50.0)},
                         {"passes", MedianPassMs()},
                         {"frame_ms", frame_ms_},
                         {"render_scale", render_scale_},
                         {"gpu_frame_ms", gpu_frame_ms_}};
  return json.dump(2) + "\n";
}

void FrameStats::Write(const std::filesystem::path& path) const {
  WriteFileAtomically(path, ToJson());
}

}  // namespace aerial::viewer
