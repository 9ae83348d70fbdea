#include "aerial/validation/reference_sampling.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "aerial/terrain/scene_surface.h"
#include "aerial/spectrum/linear_srgb_sum.h"
#include "aerial/spectrum/spectral_atmosphere.h"
#include "aerial/spectrum/spectral_sampling.h"
#include "aerial/validation/lambertian_radiance.h"

namespace aerial::validation {
namespace {

glm::dvec3 ToVec3(const std::array<float, 4>& v) { return {v[0], v[1], v[2]}; }

double MedianRelativeStdError(const ViewReference& view) {
  std::vector<double> errors;
  for (const ReferencePixel& p : view.pixels) {
    Spectrum expected = p.Expected();
    double e = 0.0;
    for (int c = 0; c < 3; ++c) e = std::max(e, p.std_error[c] / std::abs(expected[c]));
    errors.push_back(e);
  }
  if (errors.empty()) return 0.0;
  std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(errors.size() / 2), errors.end());
  return errors[errors.size() / 2];
}

}  // namespace

glm::dvec3 PixelRay(const FrameUniforms& frame, int x, int y) {
  return ViewRayFromScreen(frame, glm::dvec2((x + 0.5) / frame.viewport[0], (y + 0.5) / frame.viewport[1]));
}

Spectrum ReferencePixel::Expected() const {
  Spectrum radiance;
  for (int c = 0; c < 3; ++c) radiance[c] = inscatter[c] + transmittance[c] * surface[c];
  return radiance;
}

std::vector<std::array<int, 2>> GridPixels(int width, int height, int columns, int rows) {
  std::vector<std::array<int, 2>> pixels;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i)
      pixels.push_back({int((i + 0.5) * width / columns), int((j + 0.5) * height / rows)});
  return pixels;
}

ViewReference SampleReference(const reference::Reference& model, const Scene& scene, const FrameUniforms& frame,
                              const ImageRgbF& surface, const ReferenceSampling& sampling,
                              const std::function<void()>& on_pixel) {
  const AtmosphereParameters& atmosphere = model.medium().atmosphere();
  const double terrain_tolerance = TerrainTolerancePerM(scene.camera, surface.height, sampling.terrain_error_px);
  glm::dvec3 camera = ToVec3(frame.camera_planet_position);
  glm::dvec3 sun = ToVec3(frame.sun_direction);
  double r = glm::length(camera);
  double mu_s = glm::dot(camera, sun) / r;
  ViewReference view;
  for (auto [x, y] : GridPixels(surface.width, surface.height, sampling.columns, sampling.rows)) {
    glm::dvec3 ray = PixelRay(frame, x, y);
    double mu = glm::dot(camera, ray) / r;
    double nu = glm::dot(ray, sun);
    ReferencePixel pixel{.x = x, .y = y, .sky = IsSky(surface, x, y)};
    bool ground = model.RayIntersectsGround(r, mu);
    // Sky: to the ground or the top of the atmosphere; opaque: to the surface.
    double distance = pixel.sky ? model.DistanceToBoundary(r, mu) : double(surface.pixel(x, y)[3]);
    // What ends the ray, lit: the scene's surface, or the bare planet's ground facing up.
    std::optional<LambertianSurface> end;
    if (!pixel.sky) {
      end = SurfaceAtDepth(scene, atmosphere.bottom_radius_m, ray, distance, terrain_tolerance);
      if (end && sampling.scene_albedo) end->albedo = sampling.scene_albedo(end->albedo);
    } else if (ground) {
      glm::dvec3 point = camera + distance * ray;
      end = LambertianSurface{.point = point, .normal = glm::normalize(point), .albedo = atmosphere.ground_albedo};
    }
    bool sees_sun = pixel.sky && !ground && nu > std::cos(atmosphere.sun_angular_radius_rad);
    if (sees_sun || (!pixel.sky && !end)) {
      ++(sees_sun ? view.sun_pixels : view.unmatched_pixels);
      if (on_pixel) on_pixel();
      continue;
    }
    reference::Estimate s =
        model.ComputeRadiance(r, mu, mu_s, nu, sampling.orders, distance, sampling.monte_carlo);
    pixel.inscatter = s.value;
    pixel.transmittance = model.Transmittance(r, mu, distance);
    reference::Estimate lit;
    if (end) lit = LambertianRadiance(model, *end, sun, sampling.orders, sampling.monte_carlo);
    pixel.surface = lit.value;
    for (int c = 0; c < 3; ++c)
      pixel.std_error[c] = std::hypot(s.std_error[c], pixel.transmittance[c] * lit.std_error[c]);
    view.pixels.push_back(pixel);
    if (on_pixel) on_pixel();
  }
  view.median_relative_std_error = MedianRelativeStdError(view);
  return view;
}

ViewReference SampleSpectralReference(const AtmosphereParameters& atmosphere,
                                      const spectrum::SpectralSampling& spectral_sampling, const Scene& scene,
                                      const FrameUniforms& frame, const ImageRgbF& surface,
                                      const ReferenceSampling& sampling, const std::function<void()>& on_pixel) {
  const spectrum::SpectralAtmosphere spectral(atmosphere);
  ViewReference view;
  // Per pixel: the converted inscatter, S + T L_surface, sunlit transmittance and sunlight, and
  // the variance.
  struct Sums {
    spectrum::LinearSrgbSum inscatter, expected, sunlit, sun, variance;
  };
  std::vector<Sums> sums;
  for (int g = 0; g < spectral_sampling.groups(); ++g) {
    const std::array<double, 3> nm = spectral_sampling.Group(g);
    const AtmosphereParameters group = spectral.At(nm);
    ReferenceSampling at_group = sampling;
    at_group.scene_albedo = [&](const Spectrum& albedo) {
      Spectrum rho = spectral.ReflectanceForSunlight(sampling.scene_albedo ? sampling.scene_albedo(albedo) : albedo,
                                                     spectral_sampling);
      return Spectrum{spectral.ReflectanceAt(rho, nm[0]), spectral.ReflectanceAt(rho, nm[1]),
                      spectral.ReflectanceAt(rho, nm[2])};
    };
    // One pixel in the progress per pixel of the whole spectrum: the last group reports them.
    const bool last = g + 1 == spectral_sampling.groups();
    ViewReference part = SampleReference(reference::Reference(group), scene, frame, surface, at_group,
                                         last ? on_pixel : std::function<void()>());
    if (g == 0) {
      view = part;
      sums.resize(part.pixels.size());
    }
    const spectrum::Matrix3 m = spectral_sampling.GroupToLinearSrgb(g);
    for (size_t i = 0; i < part.pixels.size(); ++i) {
      const ReferencePixel& p = part.pixels[i];
      Spectrum sunlit;
      for (int k = 0; k < 3; ++k) sunlit[k] = group.solar_irradiance[k] * p.transmittance[k];
      sums[i].inscatter.Add(m, p.inscatter);
      sums[i].expected.Add(m, p.Expected());
      sums[i].sunlit.Add(m, sunlit);
      sums[i].sun.Add(m, group.solar_irradiance);
      sums[i].variance.AddVariance(m, p.std_error);
    }
  }
  for (size_t i = 0; i < view.pixels.size(); ++i) {
    ReferencePixel& p = view.pixels[i];
    p.inscatter = sums[i].inscatter.value;
    p.std_error = sums[i].variance.Sqrt();
    for (int c = 0; c < 3; ++c) {
      p.transmittance[c] = sums[i].sunlit.value[c] / sums[i].sun.value[c];
      p.surface[c] =
          p.transmittance[c] > 0.0 ? (sums[i].expected.value[c] - p.inscatter[c]) / p.transmittance[c] : 0.0;
    }
  }
  view.median_relative_std_error = MedianRelativeStdError(view);
  return view;
}

std::vector<PixelSample> ReferenceSamples(const ViewReference& reference, const ImageRgbF& rendered,
                                          PixelClass pixels) {
  std::vector<PixelSample> samples;
  for (const ReferencePixel& p : reference.pixels) {
    if (p.sky != (pixels == PixelClass::kSky)) continue;
    const float* a = rendered.pixel(p.x, p.y);
    samples.push_back({{a[0], a[1], a[2]}, p.Expected(), p.x, p.y});
  }
  return samples;
}

Scene OpaqueScene(const Scene& scene) {
  Scene opaque = scene;
  std::erase_if(opaque.meshes, [](const Mesh& mesh) { return mesh.transparent; });
  return opaque;
}

}  // namespace aerial::validation
