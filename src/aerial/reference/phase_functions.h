#pragma once
// Phase functions (per steradian, normalized over the sphere) of nu, the cosine between the view
// ray and the direction towards the light (so nu = 1 is forward scattering), and the inverse CDFs
// that sample nu about a lobe axis.
#include <cmath>
#include <numbers>

namespace aerial::reference {

// Rayleigh: 3 / (16 pi) (1 + nu^2) (Bruneton 2017's RayleighPhaseFunction).
inline double RayleighPhaseFunction(double nu) {
  return 3.0 / (16.0 * std::numbers::pi) * (1.0 + nu * nu);
}

// Cornette-Shanks: 3 / (8 pi) (1 - g^2) / (2 + g^2) (1 + nu^2) / (1 + g^2 - 2 g nu)^(3/2)
// (Cornette & Shanks 1992; Bruneton 2017's MiePhaseFunction).
inline double CornetteShanksPhaseFunction(double g, double nu) {
  double k = 3.0 / (8.0 * std::numbers::pi) * (1.0 - g * g) / (2.0 + g * g);
  return k * (1.0 + nu * nu) / std::pow(1.0 + g * g - 2.0 * g * nu, 1.5);
}

// Henyey-Greenstein, (1 - g^2) / (4 pi (1 + g^2 - 2 g nu)^(3/2)): the proposal used to sample the
// Cornette-Shanks lobe (their ratio is at most 3 / (2 + g^2) <= 1.5, so weights stay bounded).
inline double HenyeyGreensteinPhaseFunction(double g, double nu) {
  return (1.0 - g * g) / (4.0 * std::numbers::pi * std::pow(1.0 + g * g - 2.0 * g * nu, 1.5));
}

// Inverts the Henyey-Greenstein CDF of nu at u in [0, 1].
double SampleHenyeyGreensteinCosine(double g, double u);

// Inverts the Rayleigh CDF (3/8)(nu + nu^3/3 + 4/3) = u: the depressed cubic
// nu^3 + 3 nu + 4 - 8u = 0, whose real root by Cardano is A - 1/A with
// A = cbrt(4u - 2 + sqrt((4u - 2)^2 + 1)).
double SampleRayleighCosine(double u);

}  // namespace aerial::reference
