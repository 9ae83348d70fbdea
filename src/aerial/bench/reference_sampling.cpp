#include "aerial/bench/reference_sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace aerial::bench {
namespace {

glm::dvec3 ToVec3(const std::array<float, 4>& v) { return {v[0], v[1], v[2]}; }

double MedianRelativeStdError(const ViewReference& view, const ImageRgbF& surface) {
  std::vector<double> errors;
  for (const ReferencePixel& p : view.pixels) {
    Spectrum expected = p.Expected(surface.pixel(p.x, p.y));
    double e = 0.0;
    for (int c = 0; c < 3; ++c) e = std::max(e, p.std_error[c] / std::abs(expected[c]));
    errors.push_back(e);
  }
  if (errors.empty()) return 0.0;
  std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(errors.size() / 2), errors.end());
  return errors[errors.size() / 2];
}

Spectrum Add(const Spectrum& a, const Spectrum& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

// Lambertian ground at the end of a sky pixel's ray: albedo / pi (E_sun + E_sky) on the horizontal
// ground (surface.glsl ShadeLambertian with the normal up); *std_error gets E_sky's error.
Spectrum GroundRadiance(const reference::Reference& model, const glm::dvec3& ground_point,
                        const glm::dvec3& sun, const ReferenceSampling& sampling, Spectrum* std_error) {
  const AtmosphereParameters& atmosphere = model.medium().atmosphere();
  double r = atmosphere.bottom_radius_m;
  double mu_s = std::clamp(glm::dot(glm::normalize(ground_point), sun), -1.0, 1.0);
  reference::Estimate sky = model.ComputeSkyIrradiance(r, mu_s, sampling.orders, sampling.monte_carlo);
  Spectrum irradiance = Add(model.ComputeDirectIrradiance(r, mu_s), sky.value);
  *std_error = sky.std_error;
  Spectrum radiance;
  for (int c = 0; c < 3; ++c) {
    radiance[c] = atmosphere.ground_albedo[c] / std::numbers::pi * irradiance[c];
    (*std_error)[c] *= atmosphere.ground_albedo[c] / std::numbers::pi;
  }
  return radiance;
}

}  // namespace

glm::dvec3 PixelRay(const FrameUniforms& frame, int x, int y) {
  return ViewRayFromScreen(frame, glm::dvec2((x + 0.5) / frame.viewport[0], (y + 0.5) / frame.viewport[1]));
}

Spectrum ReferencePixel::Expected(const float* surface_rgba) const {
  Spectrum radiance;
  for (int c = 0; c < 3; ++c)
    radiance[c] = inscatter[c] + transmittance[c] * (sky ? ground[c] : double(surface_rgba[c]));
  return radiance;
}

std::vector<std::array<int, 2>> GridPixels(int width, int height, int columns, int rows) {
  std::vector<std::array<int, 2>> pixels;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i)
      pixels.push_back({int((i + 0.5) * width / columns), int((j + 0.5) * height / rows)});
  return pixels;
}

ViewReference SampleReference(const reference::Reference& model, const FrameUniforms& frame,
                              const ImageRgbF& surface, const ReferenceSampling& sampling,
                              const std::function<void()>& on_pixel) {
  const AtmosphereParameters& atmosphere = model.medium().atmosphere();
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
    if (pixel.sky && !ground && nu > std::cos(atmosphere.sun_angular_radius_rad)) {
      ++view.sun_pixels;
      if (on_pixel) on_pixel();
      continue;
    }
    // Sky: to the ground or the top of the atmosphere; opaque: to the surface.
    double distance = pixel.sky ? model.DistanceToBoundary(r, mu) : double(surface.pixel(x, y)[3]);
    reference::Estimate s =
        model.ComputeRadiance(r, mu, mu_s, nu, sampling.orders, distance, sampling.monte_carlo);
    pixel.inscatter = s.value;
    pixel.transmittance = model.Transmittance(r, mu, distance);
    Spectrum ground_error{};
    if (pixel.sky && ground)
      pixel.ground = GroundRadiance(model, camera + distance * ray, sun, sampling, &ground_error);
    for (int c = 0; c < 3; ++c)
      pixel.std_error[c] = std::hypot(s.std_error[c], pixel.transmittance[c] * ground_error[c]);
    view.pixels.push_back(pixel);
    if (on_pixel) on_pixel();
  }
  view.median_relative_std_error = MedianRelativeStdError(view, surface);
  return view;
}

std::vector<PixelSample> ReferenceSamples(const ViewReference& reference, const ImageRgbF& rendered,
                                          const ImageRgbF& surface, PixelClass pixels) {
  std::vector<PixelSample> samples;
  for (const ReferencePixel& p : reference.pixels) {
    if (p.sky != (pixels == PixelClass::kSky)) continue;
    const float* a = rendered.pixel(p.x, p.y);
    samples.push_back({{a[0], a[1], a[2]}, p.Expected(surface.pixel(p.x, p.y)), p.x, p.y});
  }
  return samples;
}

}  // namespace aerial::bench
