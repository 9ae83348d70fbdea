
#include <string>

#include "aerial/error.h"
#include "aerial/image.h"

// The implementation lives here and nowhere else in aerial_lib. STATIC keeps its symbols local
// to this file, so another library (or a test) that also compiles stb cannot clash with it.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"  // the BMP/TGA/HDR/JPG writers we do not use
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace aerial {
namespace {

// stb hands the encoded file over in chunks through this callback.
void AppendChunk(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::byte>*>(context);
  const auto* first = static_cast<const std::byte*>(data);
  out->insert(out->end(), first, first + size);
}

}  // namespace

std::vector<std::byte> EncodePng(std::span<const uint8_t> rgba8, int width, int height) {
  CheckImageSize(width, height);
  const size_t expected = size_t{4} * static_cast<size_t>(width) * height;
  if (rgba8.size() != expected)
    throw Error("image size", std::to_string(rgba8.size()) + " bytes",
                std::to_string(expected) + " bytes (RGBA8)");
  std::vector<std::byte> png;
  const int row_bytes = 4 * width;
  if (stbi_write_png_to_func(AppendChunk, &png, width, height, 4, rgba8.data(), row_bytes) == 0)
    throw Error("PNG encoding", std::to_string(width) + "x" + std::to_string(height),
                "an image stb_image_write can encode (it ran out of memory)");
  return png;
}

}  // namespace aerial
