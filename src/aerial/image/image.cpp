#include "aerial/image.h"

#include "aerial/error.h"

namespace aerial {

void CheckImageSize(int width, int height, const std::string& where) {
  if (width <= 0 || height <= 0 || width > kMaxImageSide || height > kMaxImageSide)
    throw Error("image size", std::to_string(width) + "x" + std::to_string(height),
                "1.." + std::to_string(kMaxImageSide) + " pixels per side", where);
}

void CheckImageSize(const ImageRgbF& image) {
  CheckImageSize(image.width, image.height);
  const size_t expected = size_t{4} * static_cast<size_t>(image.width) * image.height;
  if (image.rgba.size() != expected)
    throw Error("image size",
                std::to_string(image.width) + "x" + std::to_string(image.height) + " with " +
                    std::to_string(image.rgba.size()) + " floats",
                std::to_string(expected) + " floats (4 per pixel)");
}

}  // namespace aerial
