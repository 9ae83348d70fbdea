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

namespace {

// sum |w_j|: how much of its neighbours' errors (float rounding, the precompute's own) a stencil
// passes on, at most. Within a narrow window log(lambda) and lambda^-4 are nearly collinear: at 24
// wavelengths a four-function fit took weights up to 42 (against 0.6 at 12), which turns 1e-3 of
// rounding in a neighbour into 4%.
double NoiseGain(const std::vector<double>& weights) {
  double gain = 0.0;
  for (double w : weights) gain += std::abs(w);
  return gain;
}
constexpr double kMaxNoiseGain = 2.0;

}  // namespace

std::vector<HigherOrderStencil> HigherOrderStencils(const SpectralSampling& sampling,
                                                    const SpectralAtmosphere& atmosphere) {
  const std::vector<double>& nm = sampling.wavelengths_nm();
  const int count = int(nm.size());
  // 1, log(lambda), the ozone's absorption and Rayleigh's scattering coefficient, the last two
  // scaled to order 1 at 550 nm. Light of the orders >= 2 has crossed the air: its log response is
  // a sum over paths of log(scattering coefficients) - N_R sigma_R(lambda) - N_O sigma_O(lambda)
  // (- N_M sigma_M, nearly flat), so beside the power law in log(lambda) it takes the ozone's and
  // Rayleigh's spectra, in proportion to the path's columns. Rayleigh's matters where the columns
  // are long (the Earth's shadow): without it, twilight's sky on the ground read 0.0031 off in
  // u'v' against the 48-wavelength reference (0.0015 with it; aerial_bench_colour).
  const double ozone_scale = atmosphere.AbsorptionExtinction(550.0);
  auto functions = [&](int index) {
    return std::vector<double>{1.0, std::log(nm[index] / 550.0),
                               ozone_scale > 0.0 ? atmosphere.AbsorptionExtinction(nm[index]) / ozone_scale : 0.0,
                               atmosphere.RayleighScattering(nm[index]) / atmosphere.RayleighScattering(550.0)};
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
    // neighbours, for a line in log(lambda). Rayleigh's coefficient, the fourth, needs four
    // neighbours, and is left out where the fit with it would amplify the neighbours' errors.
    auto fit = [&](size_t used) {
      std::vector<std::vector<double>> rows = basis;
      for (std::vector<double>& row : rows) row.resize(used);
      std::vector<double> point = at;
      point.resize(used);
      return LeastSquaresWeights(rows, point);
    };
    const size_t used = ozone_scale > 0.0 ? std::min<size_t>(stencil.from.size(), 4) : 2;
    stencil.weights = fit(used);
    if (used == 4 && NoiseGain(stencil.weights) > kMaxNoiseGain) stencil.weights = fit(3);
  }
  return stencils;
}

}  // namespace aerial::spectrum
