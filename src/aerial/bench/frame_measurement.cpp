#include "aerial/bench/frame_measurement.h"

#include <chrono>
#include <ctime>

#include "aerial/api/impl.h"
#include "aerial/validation/image_metrics.h"

namespace aerial::bench {

double CpuClockMs(clockid_t clock) {
  timespec now{};
  clock_gettime(clock, &now);
  return double(now.tv_sec) * 1e3 + double(now.tv_nsec) * 1e-6;
}

Scene Moved(const Scene& scene, Motion motion, int frame) {
  Scene moved = scene;
  if (motion == Motion::kCamera) {
    moved.camera.yaw_deg += 0.1 * frame;
    if (frame % 2 == 1) moved.camera.position.z += 12.0;
  } else if (motion == Motion::kSun) {
    moved.sun.zenith_deg += 0.02 * frame;
  }
  return moved;
}

std::vector<std::vector<RunResult>> MeasureFrames(const std::vector<FrameSource>& sources, const Scene& scene,
                                                  int warmup, int frames,
                                                  const std::function<void(size_t source)>& on_frame) {
  std::vector<std::vector<RunResult>> measured(sources.size());
  for (int i = 0; i < warmup + frames; ++i)
    for (size_t k = 0; k < sources.size(); ++k) {
      // Each round starts one renderer later, so that the one a renderer follows (whose state it
      // finds in the caches and lavapipe's threads) changes from round to round: in a fixed order,
      // two renderers of the same settings differed by more than most configurations do.
      const size_t r = (k + size_t(i)) % sources.size();
      if (i - warmup >= sources[r].max_frames) continue;
      Scene frame_scene = Moved(scene, sources[r].motion, i);
      auto start = std::chrono::steady_clock::now();
      double cpu_start = CpuClockMs(CLOCK_PROCESS_CPUTIME_ID), caller_start = CpuClockMs(CLOCK_THREAD_CPUTIME_ID);
      RunResult frame{.passes = sources[r].renderer->Render(frame_scene, /*complete=*/false)};
      frame.caller_cpu_ms = CpuClockMs(CLOCK_THREAD_CPUTIME_ID) - caller_start;
      frame.cpu_ms = CpuClockMs(CLOCK_PROCESS_CPUTIME_ID) - cpu_start;
      const FrameInfo& info = sources[r].renderer->frame_info();
      frame.shadow_tiles_redrawn = info.shadow_tiles_redrawn;
      frame.shadow_tile_regions_redrawn = info.shadow_tile_regions_redrawn;
      frame.draws = info.draws;
      frame.draw_binds = info.draw_binds;
      frame.wall_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (i >= warmup) measured[r].push_back(std::move(frame));
      if (on_frame) on_frame(r);
    }
  return measured;
}

size_t CoveredPixels(const SceneRenderer& renderer) {
  const ImageRgbF surface = ImplOf(renderer).renderer.ReadSurface();
  size_t covered = 0;
  for (int y = 0; y < surface.height; ++y)
    for (int x = 0; x < surface.width; ++x) covered += !validation::IsSky(surface, x, y);
  return covered;
}

}  // namespace aerial::bench
