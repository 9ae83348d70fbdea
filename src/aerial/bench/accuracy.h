#pragma once
// Accuracy of one table tier over the plan's views. The views are rendered without the scene's
// transparent meshes, so every pixel is sky or an opaque surface whose lighting and aerial
// perspective the reference can compute. For each variant: both paths against the CPU reference
// (at the sampled pixels, reference_sampling.h) and the froxel path against the per-pixel path
// (every pixel); for the 3D tables also 3D against 4D on the per-pixel path (every pixel), where
// the difference is the tables' alone. In the shadow views, the froxel path against the per-pixel
// path only, both with the sun's shadows.
#include <functional>
#include <vector>

#include "aerial/bench/bench_plan.h"
#include "aerial/bench/bench_results.h"
#include "aerial/scene.h"
#include "aerial/tables.h"
#include "aerial/validation/reference_sampling.h"

namespace aerial::bench {

// The reference in each view of plan.views, at plan.image_width x height: tables only serve to
// render the views' surfaces (distances and sky pixels) and frame uniforms. Sets scene's view.
std::vector<validation::ViewReference> SampleViews(const Tables& tables, Scene& scene, const BenchPlan& plan,
                                       const std::function<void()>& on_pixel);

// Fills the accuracy of both results, plan.views' then shadow_views' (froxel against per-pixel,
// with the sun's shadows); figures (may be null) receives each of plan.views' images.
void MeasureAccuracy(VariantResult& lut4d, const Tables& tables4d, VariantResult& lut3d,
                     const Tables& tables3d, Scene& scene, const BenchPlan& plan,
                     const std::vector<std::string>& shadow_views,
                     const std::vector<validation::ViewReference>& references, std::vector<FigureImages>* figures,
                     const std::function<void()>& on_view);

}  // namespace aerial::bench
