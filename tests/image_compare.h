#pragma once
// Image comparisons shared by the render tests.
#include <vector>

#include "aerial/image.h"

namespace aerial::testing {

// sqrt(sum |a - b|^2 / sum |b|^2) over the RGB channels of the pixels mask selects (all without
// a mask): the error of a relative to the reference b.
double RelativeRmse(const ImageRgbF& a, const ImageRgbF& b, const std::vector<bool>* mask = nullptr);

}  // namespace aerial::testing
