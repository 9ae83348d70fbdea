#include "aerial/bench/variant_frames.h"

#include <memory>

#include "aerial/bench/frame_measurement.h"

namespace aerial::bench {

void MeasureVariantFrames(VariantResult& lut4d, const Tables& tables4d, VariantResult& lut3d,
                          const Tables& tables3d, const Scene& scene, const BenchPlan& plan,
                          const std::function<void()>& on_frame) {
  std::vector<std::unique_ptr<SceneRenderer>> renderers;
  std::vector<FrameSource> order;
  for (const Tables* tables : {&tables4d, &tables3d})
    for (AerialMode mode : {AerialMode::kFroxel, AerialMode::kPerPixel}) {
      RenderOptions options{.width = plan.frame_width, .height = plan.frame_height, .mode = mode,
                            .shadows = plan.shadows};
      options.Validate();
      renderers.push_back(std::make_unique<SceneRenderer>(*tables, scene, options));
      order.push_back({renderers.back().get()});
    }
  auto frames = MeasureFrames(order, scene, plan.frame_warmup, plan.frames, on_frame);
  lut4d.froxel_frames = std::move(frames[0]);
  lut4d.per_pixel_frames = std::move(frames[1]);
  lut3d.froxel_frames = std::move(frames[2]);
  lut3d.per_pixel_frames = std::move(frames[3]);
}

}  // namespace aerial::bench
