#include "aerial/bench/variant_frames.h"

#include <array>
#include <memory>
#include <utility>

#include "aerial/bench/frame_measurement.h"

namespace aerial::bench {

void MeasureVariantFrames(VariantResult& lut4d, const Tables& tables4d, VariantResult& lut3d,
                          const Tables& tables3d, const Scene& scene, const BenchPlan& plan,
                          const std::function<void()>& on_frame) {
  using Frames = std::vector<RunResult> VariantResult::*;
  constexpr std::array<std::pair<AerialMode, Frames>, 3> kPaths = {{
      {AerialMode::kFroxel, &VariantResult::froxel_frames},
      {AerialMode::kPerPixel, &VariantResult::per_pixel_frames},
      {AerialMode::kTableDifference, &VariantResult::table_difference_frames},
  }};
  std::vector<std::unique_ptr<SceneRenderer>> renderers;
  std::vector<FrameSource> order;
  for (const Tables* tables : {&tables4d, &tables3d})
    for (const auto& [mode, frames] : kPaths) {
      RenderOptions options{.width = plan.frame_width, .height = plan.frame_height, .mode = mode,
                            .shadows = plan.shadows};
      options.Validate();
      renderers.push_back(std::make_unique<SceneRenderer>(*tables, scene, options));
      order.push_back({renderers.back().get()});
    }
  std::vector<std::vector<RunResult>> measured = MeasureFrames(order, scene, plan.frame_warmup, plan.frames, on_frame);
  size_t next = 0;
  for (VariantResult* result : {&lut4d, &lut3d})
    for (const auto& path : kPaths) result->*path.second = std::move(measured[next++]);
}

}  // namespace aerial::bench
