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

void DrawHeatMap(Canvas& canvas, int x, int y, const std::vector<float>& values, int w, int h,
                 double scale_max) {
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      canvas.Set(x + i, y + j, HeatColor(values[size_t(j) * size_t(w) + size_t(i)] / scale_max));
}

namespace {
constexpr double kTicks[] = {0.0, 0.5, 1.0};  // fractions of the scale
constexpr int kTickLength = 4, kLabelGap = 6;
}  // namespace

int ColorBarWidth(int w, double scale_max, int text_scale) {
  int label = 0;
  for (double t : kTicks)
    label = std::max(label, Canvas::TextWidth(FormatPercent(t * scale_max), text_scale));
  return w + kLabelGap + label;
}

void DrawColorBar(Canvas& canvas, int x, int y, int w, int h, double scale_max, int text_scale) {
  for (int j = 0; j < h; ++j) canvas.FillRect(x, y + j, w, 1, HeatColor(1.0 - (j + 0.5) / h));
  const Rgb ink{20, 20, 20};
  for (double t : kTicks) {
    int tick_y = y + int(std::lround((1.0 - t) * (h - 1)));
    canvas.FillRect(x + w, tick_y, kTickLength, 1, ink);
    canvas.Text(x + w + kLabelGap, tick_y - Canvas::TextHeight(text_scale) / 2, FormatPercent(t * scale_max),
                text_scale, ink);
  }
}

}  // namespace aerial::bench
