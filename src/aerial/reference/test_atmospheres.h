#pragma once
// Simple atmospheres with closed-form answers, for the reference's unit tests.
#include "aerial/atmosphere.h"

namespace aerial::reference::testing {

// Earth's radii, sun and solar irradiance, with no scattering, absorption or ground.
inline AtmosphereParameters Empty() {
  AtmosphereParameters a = AtmosphereParameters::Earth();
  a.name = "empty";
  a.rayleigh_scattering = a.mie_scattering = a.mie_extinction = a.absorption_extinction = {};
  a.ground_albedo = {};
  return a;
}

// Only Rayleigh scattering, exponential with scale height H (Earth's coefficients by default).
inline AtmosphereParameters ExponentialRayleigh(double scale_height_m = 8000.0) {
  AtmosphereParameters a = Empty();
  a.rayleigh_scattering = AtmosphereParameters::Earth().rayleigh_scattering;
  a.rayleigh_density.layers[1] = {0.0, 1.0, -1.0 / scale_height_m, 0.0, 0.0};
  return a;
}

// Only Rayleigh scattering, of density 1 in a layer of thickness `height_m` (the whole
// atmosphere: top_radius = bottom_radius + height_m).
inline AtmosphereParameters UniformRayleigh(const Spectrum& beta, double height_m) {
  AtmosphereParameters a = Empty();
  a.top_radius_m = a.bottom_radius_m + height_m;
  a.rayleigh_scattering = beta;
  a.rayleigh_density.layers[1] = {0.0, 0.0, 0.0, 0.0, 1.0};
  return a;
}

}  // namespace aerial::reference::testing
