#pragma once
// The CPU reference's radiance leaving a Lambertian surface point lit by the sun and the sky, in
// double precision: what the renderer's ShadeLambertian (shaders/include/surface.glsl) computes
// from its tables as albedo / pi (E_sun T(r, mu_s) f_visible(r, mu_s) max(n . sun, 0)
// + E_sky(r, mu_s) (1 + n . up) / 2). Here
//   L = albedo / pi (E_sun <V T>_disc max(n . sun, 0) + E_sky(n)),
//  - the sun: E_sun times the disc-averaged transmittance to the point's radius r with the disc's
//    centre at zenith cosine mu_s there (reference::SunDiscTransmittance: each part of the disc
//    through its own slant, only where it is above the horizon), times the cosine of the disc's
//    centre on the surface. The cosine's variation across the disc (0.27 degree radius) is
//    neglected: the reference's direct irradiance on a horizontal surface
//    (Reference::ComputeDirectIrradiance) averages it and is the same with the disc more than
//    20 degrees above the horizon, 1e-4 to 2.4e-4 higher at 10 degrees and 1e-3 to 5e-3 at
//    3 degrees (lambertian_radiance_test), where the transmittance changes fast across the disc.
//  - the sky: the reference's sky irradiance on the tilted surface itself
//    (Reference::ComputeTiltedSkyIrradiance: the hemisphere about n, its part below the horizon
//    seeing the lit ground through the air), not the horizontal one scaled by (1 + n . up) / 2;
//  - no shadows, and no light from other surfaces of the scene: the renderer has neither.
// Points below the planet's sphere (the valley's hills dip under it in places) are lit as on it, where
// the atmosphere starts; the renderer's table lookups stop at that radius too.
#include <glm/glm.hpp>
#include <vector>

#include "aerial/reference/reference.h"
#include "aerial/terrain/scene_surface.h"

namespace aerial::validation {

using LambertianSurface = SceneSurface;

// sun: unit vector toward the sun; orders and monte_carlo: of the sky irradiance (its std_error
// is the estimate's).
reference::Estimate LambertianRadiance(const reference::Reference& model, const LambertianSurface& surface,
                                       const glm::dvec3& sun, int orders,
                                       const reference::MonteCarloOptions& monte_carlo);

// The same at every group of `model`, the sky irradiance of all groups from the same paths:
// albedos[g] is the surface's albedo at group g's wavelengths (surface.albedo is not read).
reference::GroupEstimates LambertianRadiance(const reference::ReferenceGroups& model,
                                                    const LambertianSurface& surface,
                                                    const std::vector<Spectrum>& albedos, const glm::dvec3& sun,
                                                    int orders, const reference::MonteCarloOptions& monte_carlo);

}  // namespace aerial::validation
