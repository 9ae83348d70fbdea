#include "aerial/spectrum/linear_system.h"

#include <cmath>
#include <utility>

namespace aerial::spectrum {

std::vector<double> SolveLinearSystem(std::vector<std::vector<double>> a, std::vector<double> b) {
  const size_t n = b.size();
  for (size_t k = 0; k < n; ++k) {
    size_t pivot = k;
    for (size_t row = k + 1; row < n; ++row)
      if (std::abs(a[row][k]) > std::abs(a[pivot][k])) pivot = row;
    std::swap(a[k], a[pivot]);
    std::swap(b[k], b[pivot]);
    for (size_t row = 0; row < n; ++row) {
      if (row == k) continue;
      const double factor = a[row][k] / a[k][k];
      for (size_t col = k; col < n; ++col) a[row][col] -= factor * a[k][col];
      b[row] -= factor * b[k];
    }
  }
  for (size_t k = 0; k < n; ++k) b[k] /= a[k][k];
  return b;
}

}  // namespace aerial::spectrum
