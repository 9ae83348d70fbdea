#pragma once
// Relative errors of rendered radiance (a, actual) against expected radiance (b), in the two
// definitions the project quotes, each named for what it is:
//
// EnergyWeightedRelativeRmse = sqrt(sum |a - b|^2 / sum |b|^2) over RGB: the error's energy
// against the image's, so bright pixels weigh most. The tests' image bounds (golden images, froxel
// against per-pixel, kept against fresh shadow tiles...) and the relative RMSE figures that
// docs/design.md quotes from them (examples/embed/compare.cpp, built against the installed package
// alone, sums the same for docs/library.md's).
//
// ErrorStats::per_pixel_rel_rmse (CompareSamples), over one class of pixels (sky or opaque:
// Renderer::ReadSurface's alpha is negative where no geometry was drawn): per pixel and channel c
// the error is e = |a - b| / max(|b|, floor_c), with floor_c = 1e-3 of the mean |b| of channel c
// over the class: the floor only matters for values a thousand times darker than the class's
// average, where a relative error says little (a black pixel next to the sun-lit sky). Over a
// class, per_pixel_rel_rmse = sqrt(mean e^2) and rel_max = max e, both over every pixel and
// channel, so a dark pixel counts as much as a bright one. `aerial bench`'s results, report and
// recommendations (rel_rmse in its files) and the figures of docs/tables-3d-4d.md.
#include <array>
#include <vector>

#include "aerial/image.h"

namespace aerial::validation {

// mask, when given, selects the pixels compared (row-major, one entry per pixel).
double EnergyWeightedRelativeRmse(const ImageRgbF& actual, const ImageRgbF& expected,
                                  const std::vector<bool>* mask = nullptr);

enum class PixelClass { kSky, kOpaque };
const char* ToString(PixelClass pixels);  // "sky" / "opaque"
bool IsSky(const ImageRgbF& surface, int x, int y);

struct PixelSample {
  std::array<double, 3> actual, expected;
  int x = 0, y = 0;
};

struct ErrorStats {
  int pixels = 0;  // samples compared; 0: the class is empty in this view
  double per_pixel_rel_rmse = 0.0, rel_max = 0.0;
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

}  // namespace aerial::validation
