#include "aerial/validation/image_metrics.h"

#include <algorithm>
#include <cmath>

namespace aerial::validation {

double EnergyWeightedRelativeRmse(const ImageRgbF& actual, const ImageRgbF& expected,
                                  const std::vector<bool>* mask) {
  double sum_squared = 0.0, sum_reference = 0.0;
  for (size_t p = 0; p < actual.rgba.size() / 4; ++p) {
    if (mask && !(*mask)[p]) continue;
    for (int c = 0; c < 3; ++c) {
      double a = actual.rgba[4 * p + c], b = expected.rgba[4 * p + c];
      sum_squared += (a - b) * (a - b);
      sum_reference += b * b;
    }
  }
  return std::sqrt(sum_squared / sum_reference);
}

const char* ToString(PixelClass pixels) { return pixels == PixelClass::kSky ? "sky" : "opaque"; }

bool IsSky(const ImageRgbF& surface, int x, int y) { return surface.pixel(x, y)[3] < 0.0f; }

std::array<double, 3> ErrorFloor(const std::vector<PixelSample>& samples) {
  std::array<double, 3> floor{};
  if (samples.empty()) return floor;
  for (const PixelSample& s : samples)
    for (int c = 0; c < 3; ++c) floor[c] += std::abs(s.expected[c]);
  for (double& f : floor) f *= 1e-3 / double(samples.size());
  return floor;
}

namespace {

// e of one channel; a NaN (0 / 0 where the whole class is black) counts as infinite.
double ChannelError(const PixelSample& s, int c, const std::array<double, 3>& floor) {
  double e = std::abs(s.actual[c] - s.expected[c]) / std::max(std::abs(s.expected[c]), floor[c]);
  return std::isnan(e) ? INFINITY : e;
}

}  // namespace

double PixelError(const PixelSample& sample, const std::array<double, 3>& floor) {
  double error = 0.0;
  for (int c = 0; c < 3; ++c) error = std::max(error, ChannelError(sample, c, floor));
  return error;
}

ErrorStats CompareSamples(const std::vector<PixelSample>& samples) {
  ErrorStats stats{.pixels = int(samples.size())};
  if (samples.empty()) return stats;
  std::array<double, 3> floor = ErrorFloor(samples);
  double sum_squares = 0.0;
  for (const PixelSample& s : samples) {
    for (int c = 0; c < 3; ++c) sum_squares += ChannelError(s, c, floor) * ChannelError(s, c, floor);
    double e = PixelError(s, floor);
    if (e > stats.rel_max) {
      stats.rel_max = e;
      stats.max_x = s.x;
      stats.max_y = s.y;
    }
  }
  stats.per_pixel_rel_rmse = std::sqrt(sum_squares / (3.0 * double(samples.size())));
  return stats;
}

std::vector<PixelSample> ImageSamples(const ImageRgbF& actual, const ImageRgbF& expected,
                                      const ImageRgbF& surface, PixelClass pixels) {
  std::vector<PixelSample> samples;
  for (int y = 0; y < surface.height; ++y)
    for (int x = 0; x < surface.width; ++x) {
      if (IsSky(surface, x, y) != (pixels == PixelClass::kSky)) continue;
      const float* a = actual.pixel(x, y);
      const float* b = expected.pixel(x, y);
      samples.push_back({{a[0], a[1], a[2]}, {b[0], b[1], b[2]}, x, y});
    }
  return samples;
}

ErrorStats CompareImages(const ImageRgbF& actual, const ImageRgbF& expected, const ImageRgbF& surface,
                         PixelClass pixels) {
  return CompareSamples(ImageSamples(actual, expected, surface, pixels));
}

std::vector<float> ErrorMap(const ImageRgbF& actual, const ImageRgbF& expected, const ImageRgbF& surface) {
  std::vector<float> map(size_t(surface.width) * size_t(surface.height), 0.0f);
  for (PixelClass pixels : {PixelClass::kSky, PixelClass::kOpaque}) {
    std::vector<PixelSample> samples = ImageSamples(actual, expected, surface, pixels);
    std::array<double, 3> floor = ErrorFloor(samples);
    for (const PixelSample& s : samples)
      map[size_t(s.y) * size_t(surface.width) + size_t(s.x)] = float(PixelError(s, floor));
  }
  return map;
}

}  // namespace aerial::validation
