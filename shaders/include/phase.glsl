// Phase functions, normalized to integrate to 1 over the sphere. They are never baked into the
// scattering tables: the tables are smooth in nu, the phase functions (Mie's forward peak) are not.
#ifndef AERIAL_PHASE_GLSL
#define AERIAL_PHASE_GLSL
#include "definitions.glsl"

// Rayleigh: 3 / (16 pi) (1 + nu^2).
float RayleighPhaseFunction(float nu) {
  return 3.0 / (16.0 * PI) * (1.0 + nu * nu);
}

// Cornette-Shanks (1992): 3 / (8 pi) (1 - g^2) / (2 + g^2) (1 + nu^2) / (1 + g^2 - 2 g nu)^(3/2).
float MiePhaseFunction(float g, float nu) {
  float k = 3.0 / (8.0 * PI) * (1.0 - g * g) / (2.0 + g * g);
  float denominator = 1.0 + g * g - 2.0 * g * nu;
  return k * (1.0 + nu * nu) * inversesqrt(denominator) / denominator;
}

#endif
