#include "image_compare.h"

#include <cmath>

namespace aerial::testing {

double RelativeRmse(const ImageRgbF& a, const ImageRgbF& b, const std::vector<bool>* mask) {
  double sum_squared = 0.0, sum_reference = 0.0;
  for (size_t p = 0; p < a.rgba.size() / 4; ++p) {
    if (mask && !(*mask)[p]) continue;
    for (int c = 0; c < 3; ++c) {
      double x = a.rgba[4 * p + c], y = b.rgba[4 * p + c];
      sum_squared += (x - y) * (x - y);
      sum_reference += y * y;
    }
  }
  return std::sqrt(sum_squared / sum_reference);
}

}  // namespace aerial::testing
