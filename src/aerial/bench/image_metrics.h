#pragma once
// Relative errors of rendered radiance against expected radiance, over one class of pixels (sky
// or opaque: Renderer::ReadSurface's alpha is negative where no geometry was drawn).
//
// Per pixel and channel c the error is e = |a - b| / max(|b|, floor_c), with a the actual and b
// the expected value, and floor_c = 1e-3 of the mean |b| of channel c over the class: the floor
// only matters for values a thousand times darker than the class's average, where a relative
// error says little (a black pixel next to the sun-lit sky). Over a class, the relative RMSE is
// sqrt(mean e^2) and the maximum is max e, both over every pixel and channel.
#include <array>
#include <vector>

#include "aerial/image.h"

namespace aerial::bench {

enum class PixelClass { kSky, kOpaque };
const char* ToString(PixelClass pixels);  // "sky" / "opaque"
bool IsSky(const ImageRgbF& surface, int x, int y);

struct PixelSample {
  std::array<double, 3> actual, expected;
  int x = 0, y = 0;
};

struct ErrorStats {
  int pixels = 0;  // samples compared; 0: the class is empty in this view
  double rel_rmse = 0.0, rel_max = 0.0;
  int max_x = -1, max_y = -1;  // where the maximum is
};

// floor_c as above; all zero for no samples.
std::array<double, 3> ErrorFloor(const std::vector<PixelSample>& samples);
// max over channels of e.
double PixelError(const PixelSample& sample, const std::array<double, 3>& floor);
ErrorStats CompareSamples(const std::vector<PixelSample>& samples);

// Every pixel of the class, actual and expected images of the same size as surface.
std::vector<PixelSample> ImageSamples(const ImageRgbF& actual, const ImageRgbF& expected,
                                      const ImageRgbF& surface, PixelClass pixels);
ErrorStats CompareImages(const ImageRgbF& actual, const ImageRgbF& expected, const ImageRgbF& surface,
                         PixelClass pixels);

// PixelError of every pixel, with the floor of its class (what the heat maps draw), row-major.
std::vector<float> ErrorMap(const ImageRgbF& actual, const ImageRgbF& expected, const ImageRgbF& surface);

}  // namespace aerial::bench
