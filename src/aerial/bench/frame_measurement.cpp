#include "aerial/bench/frame_measurement.h"

#include <chrono>

namespace aerial::bench {

std::vector<std::vector<RunResult>> MeasureFrames(const std::vector<Renderer*>& renderers, const Scene& scene,
                                                  int warmup, int frames,
                                                  const std::function<void()>& on_frame) {
  std::vector<std::vector<RunResult>> measured(renderers.size());
  for (int i = 0; i < warmup + frames; ++i)
    for (size_t r = 0; r < renderers.size(); ++r) {
      auto start = std::chrono::steady_clock::now();
      RunResult frame{.passes = renderers[r]->Render(scene)};
      frame.wall_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (i >= warmup) measured[r].push_back(std::move(frame));
      if (on_frame) on_frame();
    }
  return measured;
}

}  // namespace aerial::bench
