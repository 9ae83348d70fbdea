#include "aerial/validation/lambertian_radiance.h"

#include <algorithm>
#include <numbers>

#include "aerial/reference/solar_disc.h"

namespace aerial::validation {

reference::Estimate LambertianRadiance(const reference::Reference& model, const LambertianSurface& surface,
                                       const glm::dvec3& sun, int orders,
                                       const reference::MonteCarloOptions& monte_carlo) {
  const reference::Medium& medium = model.medium();
  double r = std::max(glm::length(surface.point), medium.bottom_radius());
  glm::dvec3 up = glm::normalize(surface.point);
  double mu_s = std::clamp(glm::dot(up, sun), -1.0, 1.0);
  double mu_n = std::clamp(glm::dot(up, surface.normal), -1.0, 1.0);
  double nu_n = std::clamp(glm::dot(surface.normal, sun), -1.0, 1.0);
  Spectrum sun_transmittance = reference::SunDiscTransmittance(medium, reference::Accuracy::kReference, r, mu_s);
  reference::Estimate sky = model.ComputeTiltedSkyIrradiance(r, mu_s, mu_n, nu_n, orders, monte_carlo);
  reference::Estimate radiance;
  for (int c = 0; c < 3; ++c) {
    double direct = medium.atmosphere().solar_irradiance[c] * sun_transmittance[c] * std::max(nu_n, 0.0);
    double reflectance = surface.albedo[c] / std::numbers::pi;
    radiance.value[c] = reflectance * (direct + sky.value[c]);
    radiance.std_error[c] = reflectance * sky.std_error[c];
  }
  return radiance;
}

}  // namespace aerial::validation
