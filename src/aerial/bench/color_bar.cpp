#include "aerial/bench/color_bar.h"

#include <algorithm>
#include <cmath>

#include "aerial/bench/cairo_figure.h"
#include "aerial/bench/figure_label.h"
#include "aerial/bench/heatmap.h"

namespace aerial::bench {
namespace {

constexpr double kTicks[] = {0.0, 0.5, 1.0};  // fractions of the scale
constexpr int kTickLength = 4, kLabelGap = 6;

}  // namespace

int ColorBarWidth(int w, double scale_max) {
  double label = 0.0;
  for (double t : kTicks) label = std::max(label, LabelWidth(FormatPercent(t * scale_max)));
  return w + kLabelGap + int(std::ceil(label));
}

void DrawColorBar(cairo_t* cr, int x, int y, int w, int h, double scale_max) {
  for (int j = 0; j < h; ++j) FillRect(cr, x, y + j, w, 1, HeatColor(1.0 - (j + 0.5) / h));
  for (double t : kTicks) {
    int tick_y = y + int(std::lround((1.0 - t) * (h - 1)));
    FillRect(cr, x + w, tick_y, kTickLength, 1, kInk);
    DrawLabel(cr, FormatPercent(t * scale_max), x + w + kLabelGap, tick_y + 0.5, {0.0, 0.5});
  }
}

}  // namespace aerial::bench
