#include "aerial/image/image_writer.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "aerial/core/atomic_file.h"
#include "aerial/error.h"
#include "aerial/image/exr.h"
#include "aerial/image/finite_pixels.h"
#include "aerial/image.h"

namespace aerial {

ImageFormat ImageFormatFromPath(const std::filesystem::path& path, const std::string& field) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".exr") return ImageFormat::kExr;
  if (extension == ".png") return ImageFormat::kPng;
  throw Error(field, path.string(), ".exr or .png");
}

void CheckImageOutputPath(const std::filesystem::path& path, const std::string& field) {
  ImageFormatFromPath(path, field);
  CheckOutputFile(path, field);
}

void WriteImage(const std::filesystem::path& path, const ImageRgbF& image,
                const ToneMapOptions& tone_map) {
  // Validate everything before touching the disk, and encode fully in memory, so any failure
  // happens before the atomic write starts.
  const ImageFormat format = ImageFormatFromPath(path, "image path");
  CheckImageSize(image);
  CheckFinitePixels(image);
  std::vector<std::byte> bytes;
  switch (format) {
    case ImageFormat::kExr:
      bytes = EncodeExr(image);
      break;
    case ImageFormat::kPng:
      bytes = EncodePng(ToneMapToSrgb8(image, tone_map), image.width, image.height);
      break;
  }
  WriteFileAtomically(path, bytes);
}

ImageRgbF ReadExr(const std::filesystem::path& path) {
  return DecodeExr(ReadFile(path), path.string());
}

}  // namespace aerial
