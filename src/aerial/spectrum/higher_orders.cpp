#include "aerial/spectrum/higher_orders.h"

#include <cmath>
#include <utility>

#include "aerial/spectrum/linear_system.h"

namespace aerial::spectrum {

std::vector<double> LeastSquaresWeights(const std::vector<std::vector<double>>& basis,
                                        const std::vector<double>& at) {
  // The fit's coefficients are c = (A^T A)^-1 A^T y, read at `at`: at . c = w . y with
  // w = A (A^T A)^-1 at = A z, where (A^T A) z = at.
  const size_t points = basis.size(), functions = at.size();
  std::vector<std::vector<double>> normal(functions, std::vector<double>(functions, 0.0));
  for (size_t k = 0; k < functions; ++k)
    for (size_t l = 0; l < functions; ++l)
      for (size_t j = 0; j < points; ++j) normal[k][l] += basis[j][k] * basis[j][l];
  const std::vector<double> z = SolveLinearSystem(std::move(normal), at);
  std::vector<double> weights(points, 0.0);
  for (size_t j = 0; j < points; ++j)
    for (size_t k = 0; k < functions; ++k) weights[j] += basis[j][k] * z[k];
  return weights;
}

std::vector<HigherOrderStencil> HigherOrderStencils(const SpectralSampling& sampling,
                                                    const SpectralAtmosphere& atmosphere) {
  const std::vector<double>& nm = sampling.wavelengths_nm();
  const int count = int(nm.size());
  // 1, log(lambda) and the ozone's absorption, scaled to order 1 at 550 nm.
  const double ozone_scale = atmosphere.AbsorptionExtinction(550.0);
  auto functions = [&](int index) {
    return std::vector<double>{1.0, std::log(nm[index] / 550.0),
                               ozone_scale > 0.0 ? atmosphere.AbsorptionExtinction(nm[index]) / ozone_scale : 0.0};
  };
  std::vector<HigherOrderStencil> stencils(count);
  for (int w = 0; w < count; ++w) {
    HigherOrderStencil& stencil = stencils[w];
    if (HasAllOrders(w)) {
      stencil = {{w}, {1.0}};
      continue;
    }
    for (int k = w - 3; k <= w + 3; k += 2)
      if (k >= 0 && k < count && HasAllOrders(k)) stencil.from.push_back(k);
    std::vector<std::vector<double>> basis;
    for (int k : stencil.from) basis.push_back(functions(k));
    std::vector<double> at = functions(w);
    // An atmosphere without ozone has no third function to fit; the last wavelength has two
    // neighbours, for a line in log(lambda).
    const size_t used = ozone_scale > 0.0 && stencil.from.size() > 2 ? 3 : 2;
    for (std::vector<double>& row : basis) row.resize(used);
    at.resize(used);
    stencil.weights = LeastSquaresWeights(basis, at);
  }
  return stencils;
}

}  // namespace aerial::spectrum
