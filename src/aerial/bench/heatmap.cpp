#include "aerial/bench/heatmap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace aerial::bench {

Rgb HeatColor(double t) {
  // matplotlib's inferno at t = 0, 1/8, ..., 1.
  static constexpr std::array<std::array<double, 3>, 9> kInferno = {{{0, 0, 4},
                                                                     {31, 12, 72},
                                                                     {85, 15, 109},
                                                                     {136, 34, 106},
                                                                     {186, 54, 85},
                                                                     {227, 89, 51},
                                                                     {249, 140, 10},
                                                                     {249, 201, 50},
                                                                     {252, 255, 164}}};
  double s = std::clamp(std::isnan(t) ? 1.0 : t, 0.0, 1.0) * 8.0;
  int i = std::min(int(s), 7);
  double f = s - i;
  auto mix = [&](int c) { return uint8_t(std::lround(kInferno[i][c] * (1.0 - f) + kInferno[i + 1][c] * f)); };
  return {mix(0), mix(1), mix(2)};
}

double NiceCeiling(double value) {
  double decade = std::pow(10.0, std::floor(std::log10(value)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= value * (1.0 - 1e-12)) return m * decade;
  return 10.0 * decade;
}

std::string FormatPercent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%g%%", 100.0 * fraction);
  return text;
}

std::vector<uint8_t> HeatMapRgba8(const std::vector<float>& values, double scale_max) {
  std::vector<uint8_t> rgba8;
  rgba8.reserve(values.size() * 4);
  for (float value : values) {
    Rgb color = HeatColor(value / scale_max);
    rgba8.insert(rgba8.end(), {color.r, color.g, color.b, 255});
  }
  return rgba8;
}

}  // namespace aerial::bench
