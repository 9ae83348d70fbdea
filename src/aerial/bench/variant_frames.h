#pragma once
// Frame times of one table tier: the 4D and 3D tables, each on the froxel path, the marched
// per-pixel path and per pixel from two table reads (Bruneton 2017's demo), six renderers of the
// same scene with their frames interleaved (frame_measurement.h).
#include <functional>

#include "aerial/bench/bench_plan.h"
#include "aerial/bench/bench_results.h"
#include "aerial/tables.h"
#include "aerial/scene.h"

namespace aerial::bench {

// Fills the froxel, per-pixel and table-difference frames of both results, at plan.frame_width x
// height; the per-pixel path with at most per_pixel_frames frames (0: not rendered, its frames left
// empty).
void MeasureVariantFrames(VariantResult& lut4d, const Tables& tables4d, VariantResult& lut3d,
                          const Tables& tables3d, const Scene& scene, const BenchPlan& plan,
                          int per_pixel_frames, const std::function<void()>& on_frame);

}  // namespace aerial::bench
