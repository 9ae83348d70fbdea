#include "aerial/reference/phase_functions.h"

#include <algorithm>

namespace aerial::reference {

double SampleHenyeyGreensteinCosine(double g, double u) {
  if (std::abs(g) < 1e-3) return 1.0 - 2.0 * u;
  // The CDF (1 - g^2) / (2g) ((1 + g^2 - 2 g nu)^(-1/2) - 1 / (1 + g)) = u, solved for nu.
  double k = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
  return std::clamp((1.0 + g * g - k * k) / (2.0 * g), -1.0, 1.0);
}

double SampleRayleighCosine(double u) {
  double q = 4.0 * u - 2.0;
  double a = std::cbrt(q + std::sqrt(q * q + 1.0));
  return std::clamp(a - 1.0 / a, -1.0, 1.0);
}

}  // namespace aerial::reference
