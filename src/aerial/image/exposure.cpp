#include "aerial/image/exposure.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace aerial {

double LuminanceOfRadiance(const float* rgb) {
  return kLuminancePerChannel[0] * rgb[0] + kLuminancePerChannel[1] * rgb[1] + kLuminancePerChannel[2] * rgb[2];
}

double LogAverageLuminance(const ImageRgbF& image) {
  size_t pixels = size_t(image.width) * size_t(image.height);
  if (pixels == 0) return kMinLuminance;
  std::vector<double> logs(pixels);
  for (size_t i = 0; i < pixels; ++i) {
    double luminance = LuminanceOfRadiance(&image.rgba[4 * i]);
    logs[i] = std::log(std::isfinite(luminance) && luminance > kMinLuminance ? luminance : kMinLuminance);
  }
  std::sort(logs.begin(), logs.end());
  size_t first = size_t(kMeteredLowFraction * double(pixels));
  size_t last = std::max(first + 1, size_t(kMeteredHighFraction * double(pixels)));
  double sum_log = 0.0;
  for (size_t i = first; i < last; ++i) sum_log += logs[i];
  return std::exp(sum_log / double(last - first));
}

double Ev100FromAverageLuminance(double luminance) { return std::log2(luminance * 100.0 / 12.5); }

double RadianceMultiplierFromEv100(double ev100) {
  return kRadiancePerNmToLuminance / (1.2 * std::exp2(ev100));
}

double Ev100FromRadianceMultiplier(double multiplier) {
  return std::log2(kRadiancePerNmToLuminance / (1.2 * multiplier));
}

double Exposure::FixedEv100() const {
  return mode == Mode::kMultiplier ? Ev100FromRadianceMultiplier(value) : value;
}

double Exposure::MultiplierForAverage(double average_luminance) const {
  switch (mode) {
    case Mode::kMultiplier: return value;
    case Mode::kEv100: return RadianceMultiplierFromEv100(value);
    case Mode::kAuto: break;
  }
  return RadianceMultiplierFromEv100(Ev100FromAverageLuminance(average_luminance));
}

double Exposure::MultiplierFor(const ImageRgbF& image) const {
  // Only a metered exposure reads the image.
  return MultiplierForAverage(mode == Mode::kAuto ? LogAverageLuminance(image) : kMinLuminance);
}

std::array<double, 3> WhiteBalanceForSun(const std::array<double, 3>& sun_colour) {
  double mean = (sun_colour[0] + sun_colour[1] + sun_colour[2]) / 3.0;
  if (!(mean > 0.0) || !std::isfinite(mean)) return {1.0, 1.0, 1.0};  // no sunlight to balance
  std::array<double, 3> gains;
  for (int c = 0; c < 3; ++c) gains[c] = mean / std::max(sun_colour[c], mean / kMaxWhiteBalanceGain);
  return gains;
}

}  // namespace aerial
