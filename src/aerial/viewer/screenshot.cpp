#include "aerial/viewer/screenshot.h"

#include <ctime>

#include "aerial/image.h"

namespace aerial::viewer {

std::string SaveScreenshots(const ImageRgbF& frame, const ToneMapOptions& png,
                            const std::filesystem::path& directory) {
  std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char stem[64];
  std::strftime(stem, sizeof stem, "aerial-view-%Y%m%d-%H%M%S", &local);
  std::filesystem::path png_path = directory / (std::string(stem) + ".png");
  std::filesystem::path exr = directory / (std::string(stem) + ".exr");
  WriteImage(png_path, frame, png);
  WriteImage(exr, frame, {});
  return "Saved " + png_path.string() + " and " + exr.string();
}

}  // namespace aerial::viewer
