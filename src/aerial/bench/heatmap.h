#pragma once
// Heat maps of relative errors: a colour scale, a scale maximum that reads well, the map's pixels
// and the percentages that label its colour bar (color_bar.h).
#include <cstdint>
#include <string>
#include <vector>

#include "aerial/bench/picture.h"

namespace aerial::bench {

// t in [0, 1] (clamped) to a colour of matplotlib's "inferno" scale (van der Walt & Smith 2015),
// linear between 9 of its samples: black-purple for 0 to pale yellow for 1, monotonic in lightness.
Rgb HeatColor(double t);

// The smallest 1, 2 or 5 x 10^k >= value (value > 0).
double NiceCeiling(double value);

// "5%", "2.5%", "0.05%": a fraction as a percentage with no trailing zeros.
std::string FormatPercent(double fraction);

// RGBA8 pixels of the heat map of values (row-major): each value / scale_max through HeatColor.
std::vector<uint8_t> HeatMapRgba8(const std::vector<float>& values, double scale_max);

}  // namespace aerial::bench
