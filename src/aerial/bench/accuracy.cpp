#include "aerial/bench/accuracy.h"

#include <memory>

#include "aerial/api/impl.h"
#include "aerial/renderer.h"
#include "aerial/scene.h"
#include "aerial/spectrum/spectral_sampling.h"

namespace aerial::bench {

using validation::CompareImages;
using validation::CompareSamples;
using validation::PixelClass;
using validation::ReferenceSamples;
using validation::ReferenceSampling;
using validation::SampleReference;
using validation::SampleSpectralReference;
using validation::ViewReference;
namespace {

// Without shadows unless asked: the CPU reference has none (lambertian_radiance.h).
std::unique_ptr<SceneRenderer> ImageRenderer(const Tables& tables, const Scene& scene,
                                        const BenchPlan& plan, AerialMode mode, bool shadows = false) {
  RenderOptions options{.width = plan.image_width, .height = plan.image_height, .mode = mode, .shadows = shadows};
  options.Validate();
  return std::make_unique<SceneRenderer>(tables, scene, options);
}

// One variant's renderers, one per path.
struct VariantRenderers {
  std::unique_ptr<SceneRenderer> froxel, per_pixel, table_difference;
};

VariantRenderers MakeRenderers(const Tables& tables, const Scene& scene, const BenchPlan& plan) {
  return {ImageRenderer(tables, scene, plan, AerialMode::kFroxel),
          ImageRenderer(tables, scene, plan, AerialMode::kPerPixel),
          ImageRenderer(tables, scene, plan, AerialMode::kTableDifference)};
}

// One variant's frame of a view on every path; the surface is the same on all.
struct VariantImages {
  ImageRgbF froxel, per_pixel, table_difference, surface;
};

VariantImages Render(VariantRenderers& renderers, const Scene& scene) {
  for (SceneRenderer* r : {renderers.froxel.get(), renderers.per_pixel.get(), renderers.table_difference.get()})
    r->Render(scene);
  return {renderers.froxel->ReadOutput(), renderers.per_pixel->ReadOutput(),
          renderers.table_difference->ReadOutput(), ImplOf(*renderers.per_pixel).renderer.ReadSurface()};
}

ClassErrors AgainstReference(const ViewReference& reference, const ImageRgbF& rendered) {
  return {CompareSamples(ReferenceSamples(reference, rendered, PixelClass::kSky)),
          CompareSamples(ReferenceSamples(reference, rendered, PixelClass::kOpaque))};
}

ClassErrors AgainstImage(const ImageRgbF& actual, const ImageRgbF& expected, const ImageRgbF& surface) {
  return {CompareImages(actual, expected, surface, PixelClass::kSky),
          CompareImages(actual, expected, surface, PixelClass::kOpaque)};
}

ViewAccuracy Measure(const std::string& view, const VariantImages& images, const ViewReference& reference) {
  return {.view = view,
          .froxel_vs_reference = AgainstReference(reference, images.froxel),
          .per_pixel_vs_reference = AgainstReference(reference, images.per_pixel),
          .froxel_vs_per_pixel = AgainstImage(images.froxel, images.per_pixel, images.surface),
          .table_difference_vs_reference = AgainstReference(reference, images.table_difference)};
}

// The froxel path against the per-pixel path in each shadow view, both with the sun's shadows.
void MeasureShadowViews(VariantResult& result, const Tables& tables, Scene& scene, const BenchPlan& plan,
                        const std::vector<std::string>& views, const std::function<void()>& on_view) {
  std::unique_ptr<SceneRenderer> froxel = ImageRenderer(tables, scene, plan, AerialMode::kFroxel, true);
  std::unique_ptr<SceneRenderer> per_pixel = ImageRenderer(tables, scene, plan, AerialMode::kPerPixel, true);
  for (const std::string& view : views) {
    ApplyPresetView(scene, view, tables.atmosphere().bottom_radius_m);
    froxel->Render(scene);
    per_pixel->Render(scene);
    result.accuracy.push_back(
        {.view = view,
         .shadow_view = true,
         .froxel_vs_per_pixel = AgainstImage(froxel->ReadOutput(), per_pixel->ReadOutput(),
                                             ImplOf(*per_pixel).renderer.ReadSurface())});
    if (on_view) on_view();
  }
}

}  // namespace

std::vector<ViewReference> SampleViews(const Tables& tables, Scene& scene, const BenchPlan& plan,
                                       const std::function<void()>& on_pixel) {
  const AtmosphereParameters& atmosphere = tables.atmosphere();
  const PrecomputeOptions& options = tables.options();
  reference::Reference model(atmosphere);
  std::unique_ptr<SceneRenderer> renderer = ImageRenderer(tables, scene, plan, AerialMode::kFroxel);
  ReferenceSampling sampling{.columns = plan.reference_columns,
                             .rows = plan.reference_rows,
                             .orders = options.RepresentedOrders(),
                             .monte_carlo = {.paths_per_query = plan.reference_paths},
                             .terrain_error_px = renderer->options().terrain_error_px};
  std::vector<ViewReference> references;
  for (const std::string& view : plan.views) {
    ApplyPresetView(scene, view, atmosphere.bottom_radius_m);
    renderer->Render(scene);
    const Renderer& frame = ImplOf(*renderer).renderer;
    references.push_back(options.colour == ColourMode::kSpectral
                             ? SampleSpectralReference(atmosphere,
                                                       spectrum::SpectralSampling::ForTables(options.spectral_wavelengths),
                                                       scene, frame.frame_uniforms(), frame.ReadSurface(), sampling,
                                                       on_pixel)
                             : SampleReference(model, scene, frame.frame_uniforms(), frame.ReadSurface(), sampling,
                                               on_pixel));
  }
  return references;
}

void MeasureAccuracy(VariantResult& lut4d, const Tables& tables4d, VariantResult& lut3d,
                     const Tables& tables3d, Scene& scene, const BenchPlan& plan,
                     const std::vector<std::string>& shadow_views,
                     const std::vector<ViewReference>& references, std::vector<FigureImages>* figures,
                     const std::function<void()>& on_view) {
  VariantRenderers renderers4d = MakeRenderers(tables4d, scene, plan);
  VariantRenderers renderers3d = MakeRenderers(tables3d, scene, plan);
  lut4d.accuracy.clear();
  lut3d.accuracy.clear();
  for (size_t v = 0; v < plan.views.size(); ++v) {
    const std::string& view = plan.views[v];
    ApplyPresetView(scene, view, tables4d.atmosphere().bottom_radius_m);
    VariantImages images4d = Render(renderers4d, scene);
    VariantImages images3d = Render(renderers3d, scene);
    lut4d.accuracy.push_back(Measure(view, images4d, references.at(v)));
    lut3d.accuracy.push_back(Measure(view, images3d, references.at(v)));
    lut3d.accuracy.back().vs_4d = AgainstImage(images3d.per_pixel, images4d.per_pixel, images4d.surface);
    if (figures)
      figures->push_back(
          {view, std::move(images3d.per_pixel), std::move(images4d.per_pixel), std::move(images4d.surface)});
    if (on_view) on_view();
  }
  MeasureShadowViews(lut4d, tables4d, scene, plan, shadow_views, on_view);
  MeasureShadowViews(lut3d, tables3d, scene, plan, shadow_views, on_view);
}

}  // namespace aerial::bench
