#include "aerial/validation/reference_sampling.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "aerial/terrain/scene_surface.h"
#include "aerial/spectrum/linear_srgb_sum.h"
#include "aerial/spectrum/spectral_atmosphere.h"
#include "aerial/spectrum/spectral_sampling.h"
#include "aerial/probe/spectral_reference.h"
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

namespace {

// One grid pixel at every group of a ReferenceGroups: what ReferencePixel holds, the Monte Carlo
// parts with their chunks (reference::GroupEstimates).
struct GroupPixel {
  int x = 0, y = 0;
  bool sky = false;
  reference::GroupEstimates inscatter, surface;
  std::vector<Spectrum> transmittance;

  ReferencePixel At(int g) const {
    ReferencePixel p{.x = x, .y = y, .sky = sky};
    const reference::Estimate& s = inscatter.groups[size_t(g)];
    const reference::Estimate& l = surface.groups[size_t(g)];
    p.inscatter = s.value;
    p.transmittance = transmittance[size_t(g)];
    p.surface = l.value;
    for (int c = 0; c < 3; ++c) p.std_error[c] = std::hypot(s.std_error[c], p.transmittance[c] * l.std_error[c]);
    return p;
  }
};

struct GroupView {
  std::vector<GroupPixel> pixels;
  int sun_pixels = 0, unmatched_pixels = 0;
};

// SampleReference at every group of `model`. A scene surface's albedo at group g is
// group_albedo(its albedo after sampling.scene_albedo, g) (empty: that albedo).
GroupView SampleGroups(const reference::ReferenceGroups& model, const Scene& scene, const FrameUniforms& frame,
                       const ImageRgbF& surface, const ReferenceSampling& sampling,
                       const std::function<Spectrum(const Spectrum&, int)>& group_albedo,
                       const std::function<void()>& on_pixel) {
  const reference::Reference& geometry = model[0];
  const AtmosphereParameters& atmosphere = geometry.medium().atmosphere();
  const double terrain_tolerance = TerrainTolerancePerM(scene.camera, surface.height, sampling.terrain_error_px);
  glm::dvec3 camera = ToVec3(frame.camera_planet_position);
  glm::dvec3 sun = ToVec3(frame.sun_direction);
  double r = glm::length(camera);
  double mu_s = glm::dot(camera, sun) / r;
  GroupView view;
  for (auto [x, y] : GridPixels(surface.width, surface.height, sampling.columns, sampling.rows)) {
    glm::dvec3 ray = PixelRay(frame, x, y);
    double mu = glm::dot(camera, ray) / r;
    double nu = glm::dot(ray, sun);
    GroupPixel pixel{.x = x, .y = y, .sky = IsSky(surface, x, y)};
    bool ground = geometry.RayIntersectsGround(r, mu);
    // Sky: to the ground or the top of the atmosphere; opaque: to the surface.
    double distance = pixel.sky ? geometry.DistanceToBoundary(r, mu) : double(surface.pixel(x, y)[3]);
    // What ends the ray, lit: the scene's surface, or the bare planet's ground facing up.
    std::optional<LambertianSurface> end;
    std::vector<Spectrum> albedos;
    if (!pixel.sky) {
      end = SurfaceAtDepth(scene, atmosphere.bottom_radius_m, ray, distance, terrain_tolerance);
      if (end) {
        Spectrum albedo = sampling.scene_albedo ? sampling.scene_albedo(end->albedo) : end->albedo;
        for (int g = 0; g < model.size(); ++g) albedos.push_back(group_albedo ? group_albedo(albedo, g) : albedo);
      }
    } else if (ground) {
      glm::dvec3 point = camera + distance * ray;
      end = LambertianSurface{.point = point, .normal = glm::normalize(point)};
      for (int g = 0; g < model.size(); ++g) albedos.push_back(model[g].medium().atmosphere().ground_albedo);
    }
    bool sees_sun = pixel.sky && !ground && nu > std::cos(atmosphere.sun_angular_radius_rad);
    if (sees_sun || (!pixel.sky && !end)) {
      ++(sees_sun ? view.sun_pixels : view.unmatched_pixels);
      if (on_pixel) on_pixel();
      continue;
    }
    pixel.inscatter = model.ComputeRadiance(r, mu, mu_s, nu, sampling.orders, distance, sampling.monte_carlo);
    pixel.surface.groups.resize(size_t(model.size()));
    if (end) pixel.surface = LambertianRadiance(model, *end, albedos, sun, sampling.orders, sampling.monte_carlo);
    for (int g = 0; g < model.size(); ++g) pixel.transmittance.push_back(model[g].Transmittance(r, mu, distance));
    view.pixels.push_back(std::move(pixel));
    if (on_pixel) on_pixel();
  }
  return view;
}

}  // namespace

ViewReference SampleReference(const reference::Reference& model, const Scene& scene, const FrameUniforms& frame,
                              const ImageRgbF& surface, const ReferenceSampling& sampling,
                              const std::function<void()>& on_pixel) {
  GroupView groups = SampleGroups(reference::ReferenceGroups({model.medium().atmosphere()}), scene, frame, surface,
                                  sampling, {}, on_pixel);
  ViewReference view{.sun_pixels = groups.sun_pixels, .unmatched_pixels = groups.unmatched_pixels};
  for (const GroupPixel& p : groups.pixels) view.pixels.push_back(p.At(0));
  view.median_relative_std_error = MedianRelativeStdError(view);
  return view;
}

ViewReference SampleSpectralReference(const AtmosphereParameters& atmosphere,
                                      const spectrum::SpectralSampling& spectral_sampling, const Scene& scene,
                                      const FrameUniforms& frame, const ImageRgbF& surface,
                                      const ReferenceSampling& sampling, const std::function<void()>& on_pixel) {
  const spectrum::SpectralAtmosphere spectral(atmosphere);
  const std::vector<AtmosphereParameters> groups = spectral.AtGroups(spectral_sampling);
  auto group_albedo = [&](const Spectrum& albedo, int g) {
    const std::array<double, 3> nm = spectral_sampling.Group(g);
    Spectrum rho = spectral.ReflectanceForSunlight(albedo, spectral_sampling);
    return Spectrum{spectral.ReflectanceAt(rho, nm[0]), spectral.ReflectanceAt(rho, nm[1]),
                    spectral.ReflectanceAt(rho, nm[2])};
  };
  GroupView parts = SampleGroups(reference::ReferenceGroups(groups), scene, frame, surface, sampling, group_albedo,
                                 on_pixel);
  ViewReference view{.sun_pixels = parts.sun_pixels, .unmatched_pixels = parts.unmatched_pixels};
  for (const GroupPixel& part : parts.pixels) {
    // The converted inscatter, S + T L_surface, sunlit transmittance and sunlight.
    spectrum::LinearSrgbSum inscatter, expected, sunlit, sun;
    reference::Channels transmittance(3 * spectral_sampling.groups());
    for (int g = 0; g < spectral_sampling.groups(); ++g) {
      const spectrum::Matrix3 m = spectral_sampling.GroupToLinearSrgb(g);
      const ReferencePixel p = part.At(g);
      const Spectrum& solar = groups[size_t(g)].solar_irradiance;
      inscatter.Add(m, p.inscatter);
      expected.Add(m, p.Expected());
      sunlit.Add(m, Spectrum{solar[0] * p.transmittance[0], solar[1] * p.transmittance[1],
                             solar[2] * p.transmittance[2]});
      sun.Add(m, solar);
      for (int k = 0; k < 3; ++k) transmittance[3 * g + k] = p.transmittance[k];
    }
    ReferencePixel p{.x = part.x, .y = part.y, .sky = part.sky, .inscatter = inscatter.value};
    // S and T L_surface come from separate paths: their errors add as independent ones.
    Spectrum s_error = LinearSrgbStdError(part.inscatter, spectral_sampling);
    Spectrum l_error = LinearSrgbStdError(part.surface, spectral_sampling, &transmittance);
    for (int c = 0; c < 3; ++c) {
      p.std_error[c] = std::hypot(s_error[c], l_error[c]);
      p.transmittance[c] = sunlit.value[c] / sun.value[c];
      p.surface[c] = p.transmittance[c] > 0.0 ? (expected.value[c] - p.inscatter[c]) / p.transmittance[c] : 0.0;
    }
    view.pixels.push_back(p);
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
