#include "aerial/bench/frame_measurement.h"

#include <chrono>
#include <ctime>

namespace aerial::bench {
namespace {

double ProcessCpuMs() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return double(now.tv_sec) * 1e3 + double(now.tv_nsec) * 1e-6;
}

}  // namespace

std::vector<std::vector<RunResult>> MeasureFrames(const std::vector<Renderer*>& renderers, const Scene& scene,
                                                  int warmup, int frames,
                                                  const std::function<void()>& on_frame) {
  std::vector<std::vector<RunResult>> measured(renderers.size());
  for (int i = 0; i < warmup + frames; ++i)
    for (size_t r = 0; r < renderers.size(); ++r) {
      auto start = std::chrono::steady_clock::now();
      double cpu_start = ProcessCpuMs();
      RunResult frame{.passes = renderers[r]->Render(scene)};
      frame.cpu_ms = ProcessCpuMs() - cpu_start;
      frame.wall_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (i >= warmup) measured[r].push_back(std::move(frame));
      if (on_frame) on_frame();
    }
  return measured;
}

}  // namespace aerial::bench
