#pragma once
// A small log-log chart: each series' points joined in x order, with markers, 1-2-5 ticks on
// both axes with their numbers, light grid lines and a legend.
#include <array>
#include <string>
#include <vector>

#include "aerial/bench/picture.h"

namespace aerial::bench {

struct ChartSeries {
  std::string label;
  Rgb color;
  bool square_markers = false;                // else round
  std::vector<std::array<double, 2>> points;  // (x, y), both > 0
};

struct ChartSpec {
  std::string title, x_label, y_label;
  std::vector<ChartSeries> series;
};

// Throws aerial::Error if a point is not positive and finite, or if there are no points.
Picture LogLogChart(const ChartSpec& spec, int width, int height);

}  // namespace aerial::bench
