#include "aerial/image/resample.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "aerial/error.h"

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

ImageRgbF DownsampleBox(const ImageRgbF& image, int factor) {
  CheckImageSize(image);
  if (factor < 1 || image.width % factor != 0 || image.height % factor != 0)
    throw Error("image size", std::to_string(image.width) + "x" + std::to_string(image.height),
                "sides that are multiples of the supersampling factor " + std::to_string(factor));
  ImageRgbF out{image.width / factor, image.height / factor,
                std::vector<float>(size_t(image.width / factor) * size_t(image.height / factor) * 4)};
  const double weight = 1.0 / (double(factor) * factor);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      double sum[4] = {0.0, 0.0, 0.0, 0.0};
      for (int j = 0; j < factor; ++j)
        for (int i = 0; i < factor; ++i)
          for (int c = 0; c < 4; ++c) sum[c] += image.pixel(x * factor + i, y * factor + j)[c];
      for (int c = 0; c < 4; ++c) out.pixel(x, y)[c] = float(sum[c] * weight);
    }
  }
  return out;
}

}  // namespace aerial
