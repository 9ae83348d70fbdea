#include "aerial/bench/variant_frames.h"

#include <array>
#include <memory>
#include <utility>

#include "aerial/bench/frame_measurement.h"
#include "aerial/render/renderer_options.h"

namespace aerial::bench {

void MeasureVariantFrames(VariantResult& lut4d, const Tables& tables4d, VariantResult& lut3d,
                          const Tables& tables3d, const Scene& scene, const BenchPlan& plan,
                          int per_pixel_frames, const std::function<void()>& on_frame) {
  using Frames = std::vector<RunResult> VariantResult::*;
  constexpr std::array<std::pair<AerialMode, Frames>, 3> kPaths = {{
      {AerialMode::kFroxel, &VariantResult::froxel_frames},
      {AerialMode::kPerPixel, &VariantResult::per_pixel_frames},
      {AerialMode::kTableDifference, &VariantResult::table_difference_frames},
  }};
  std::vector<std::unique_ptr<SceneRenderer>> renderers;
  std::vector<FrameSource> order;
  std::vector<std::vector<RunResult>*> destinations;
  for (auto [tables, result] : {std::pair{&tables4d, &lut4d}, std::pair{&tables3d, &lut3d}})
    for (const auto& [mode, frames] : kPaths) {
      int max_frames = mode == AerialMode::kPerPixel ? per_pixel_frames : plan.frames;
      (result->*frames).clear();
      if (max_frames == 0) continue;
      RendererOptions options{{.width = plan.frame_width, .height = plan.frame_height, .mode = mode,
                               .shadows = plan.shadows}};
      // The renderers share their built terrain chunks: the frames compare GPU times, which
      // building on the CPU does not enter, and only the first renderer's warm-up frame builds
      // the whole view.
      options.Validate();
      renderers.push_back(std::make_unique<SceneRenderer>(MakeSceneRenderer(*tables, scene, options)));
      order.push_back({.renderer = renderers.back().get(), .max_frames = max_frames});
      destinations.push_back(&(result->*frames));
    }
  std::vector<std::vector<RunResult>> measured =
      MeasureFrames(order, scene, plan.frame_warmup, plan.frames, [&](size_t) {
        if (on_frame) on_frame();
      });
  for (size_t i = 0; i < measured.size(); ++i) *destinations[i] = std::move(measured[i]);
}

}  // namespace aerial::bench
