#pragma once
// A sum over the groups of three wavelengths of a spectral sampling, each group's values taken to
// linear sRGB by its matrix (SpectralSampling::GroupToLinearSrgb).
#include "aerial/spectrum/colour.h"

namespace aerial::spectrum {

struct LinearSrgbSum {
  Spectrum value{};

  void Add(const Matrix3& group_to_srgb, const Spectrum& group) {
    Spectrum colour = Multiply(group_to_srgb, group);
    for (int c = 0; c < 3; ++c) value[c] += colour[c];
  }
};

}  // namespace aerial::spectrum
