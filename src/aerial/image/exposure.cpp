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

MeterReading ReadMeter(const ImageRgbF& image, const std::array<double, 3>& white_balance) {
  MeterReading reading{.average_luminance = LogAverageLuminance(image)};
  size_t pixels = size_t(image.width) * size_t(image.height);
  if (pixels == 0) return reading;
  std::vector<double> brightest(pixels);
  for (size_t i = 0; i < pixels; ++i) {
    const float* rgb = &image.rgba[4 * i];
    double value = kRadiancePerNmToLuminance *
                   std::max({rgb[0] * white_balance[0], rgb[1] * white_balance[1], rgb[2] * white_balance[2]});
    brightest[i] = std::isfinite(value) && value > kMinLuminance ? value : kMinLuminance;
  }
  size_t rank = std::min(pixels - 1, size_t(kHighlightFraction * double(pixels)));
  std::nth_element(brightest.begin(), brightest.begin() + rank, brightest.end());
  reading.highlight = brightest[rank];
  return reading;
}

double Ev100FromMeter(const MeterReading& reading) {
  // The multipliers that take the average to mid grey and the highlight to the white point; the
  // EV100 of a multiplier m is Ev100FromRadianceMultiplier(m), and a multiplier in luminance units
  // is one in radiance units divided by kRadiancePerNmToLuminance.
  double grey = kMeteredGrey * kRadiancePerNmToLuminance / std::max(reading.average_luminance, kMinLuminance);
  double white = kHighlightWhite * kRadiancePerNmToLuminance / std::max(reading.highlight, kMinLuminance);
  double multiplier = std::max(std::min(grey, white), grey * std::exp2(-kMaxHighlightStops));
  return Ev100FromRadianceMultiplier(multiplier);
}

double RadianceMultiplierFromEv100(double ev100) {
  return kRadiancePerNmToLuminance / (1.2 * std::exp2(ev100));
}

double Ev100FromRadianceMultiplier(double multiplier) {
  return std::log2(kRadiancePerNmToLuminance / (1.2 * multiplier));
}

double Exposure::FixedEv100() const {
  return mode == Mode::kMultiplier ? Ev100FromRadianceMultiplier(value) : value;
}

double Exposure::MultiplierForReading(const MeterReading& reading) const {
  switch (mode) {
    case Mode::kMultiplier: return value;
    case Mode::kEv100: return RadianceMultiplierFromEv100(value);
    case Mode::kAuto: break;
  }
  return RadianceMultiplierFromEv100(Ev100FromMeter(reading));
}

double Exposure::MultiplierFor(const ImageRgbF& image, const std::array<double, 3>& white_balance) const {
  // Only a metered exposure reads the image.
  return MultiplierForReading(mode == Mode::kAuto ? ReadMeter(image, white_balance) : MeterReading{});
}

std::array<double, 3> WhiteBalanceForSun(const std::array<double, 3>& sun_colour) {
  double mean = (sun_colour[0] + sun_colour[1] + sun_colour[2]) / 3.0;
  if (!(mean > 0.0) || !std::isfinite(mean)) return {1.0, 1.0, 1.0};  // no sunlight to balance
  std::array<double, 3> gains;
  for (int c = 0; c < 3; ++c) gains[c] = mean / std::max(sun_colour[c], mean / kMaxWhiteBalanceGain);
  return gains;
}

}  // namespace aerial
