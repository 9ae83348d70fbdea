#pragma once
// A sum over the groups of three wavelengths of a spectral sampling, each group's values taken to
// linear sRGB by its matrix (SpectralSampling::GroupToLinearSrgb): of values, or of the variances
// of independent errors.
#include <cmath>

#include "aerial/spectrum/colour.h"

namespace aerial::spectrum {

struct LinearSrgbSum {
  Spectrum value{};

  void Add(const Matrix3& group_to_srgb, const Spectrum& group) {
    Spectrum colour = Multiply(group_to_srgb, group);
    for (int c = 0; c < 3; ++c) value[c] += colour[c];
  }
  // Independent errors: the sum of the squares of each weighted error.
  void AddVariance(const Matrix3& group_to_srgb, const Spectrum& std_error) {
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) value[c] += std::pow(group_to_srgb[c][k] * std_error[k], 2.0);
  }
  Spectrum Sqrt() const { return {std::sqrt(value[0]), std::sqrt(value[1]), std::sqrt(value[2])}; }
};

}  // namespace aerial::spectrum
