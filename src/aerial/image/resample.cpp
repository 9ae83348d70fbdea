#include "aerial/image/resample.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace aerial {

ImageRgbF ResizeBilinear(const ImageRgbF& image, int width, int height) {
  CheckImageSize(image);
  CheckImageSize(width, height);
  ImageRgbF out{width, height, std::vector<float>(size_t(width) * height * 4)};
  // The source texel coordinate of a destination texel center, and its two neighbours' weights.
  auto taps = [](int i, int to, int from) {
    double x = (i + 0.5) * from / to - 0.5;
    double x0 = std::floor(x);
    int a = std::clamp(int(x0), 0, from - 1), b = std::clamp(int(x0) + 1, 0, from - 1);
    return std::tuple{a, b, x - x0};
  };
  for (int y = 0; y < height; ++y) {
    auto [y0, y1, ty] = taps(y, height, image.height);
    for (int x = 0; x < width; ++x) {
      auto [x0, x1, tx] = taps(x, width, image.width);
      float* o = out.pixel(x, y);
      for (int c = 0; c < 4; ++c) {
        double top = (1 - tx) * image.pixel(x0, y0)[c] + tx * image.pixel(x1, y0)[c];
        double bottom = (1 - tx) * image.pixel(x0, y1)[c] + tx * image.pixel(x1, y1)[c];
        o[c] = float((1 - ty) * top + ty * bottom);
      }
    }
  }
  return out;
}

}  // namespace aerial
