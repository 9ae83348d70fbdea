#include "aerial/image/finite_pixels.h"

#include <cmath>
#include <string>

#include "aerial/error.h"

namespace aerial {

void CheckFinitePixels(const ImageRgbF& image) {
  for (size_t i = 0; i < image.rgba.size(); ++i) {
    if (i % 4 == 3 || std::isfinite(image.rgba[i])) continue;  // radiance only: alpha is not written out
    size_t pixel = i / 4;
    throw Error("frame",
                "NaN or infinity at pixel (" + std::to_string(pixel % image.width) + ", " +
                    std::to_string(pixel / image.width) + ")",
                "finite radiance from the frame's passes (sky, aerial perspective, surfaces); the values "
                "of the scene or atmosphere may be beyond what float arithmetic holds");
  }
}

}  // namespace aerial
