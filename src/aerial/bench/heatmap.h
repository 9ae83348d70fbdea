#pragma once
// Heat maps of relative errors: a colour scale, a scale maximum that reads well, and a colour
// bar whose ticks are labelled with numbers.
#include <string>
#include <vector>

#include "aerial/bench/canvas.h"

namespace aerial::bench {

// t in [0, 1] (clamped) to a colour of matplotlib's "inferno" scale (van der Walt & Smith 2015),
// linear between 9 of its samples: black-purple for 0 to pale yellow for 1, monotonic in lightness.
Rgb HeatColor(double t);

// The smallest 1, 2 or 5 x 10^k >= value (value > 0).
double NiceCeiling(double value);

// "5%", "2.5%", "0.05%": a fraction as a percentage with no trailing zeros.
std::string FormatPercent(double fraction);

// values (w x h, row-major) drawn at (x, y), each value / scale_max through HeatColor.
void DrawHeatMap(Canvas& canvas, int x, int y, const std::vector<float>& values, int w, int h,
                 double scale_max);

// A vertical colour bar of w x h pixels at (x, y), scale_max at the top and 0 at the bottom, with
// three labelled ticks (0, half, max) on its right.
void DrawColorBar(Canvas& canvas, int x, int y, int w, int h, double scale_max, int text_scale);
// The width DrawColorBar covers, labels included.
int ColorBarWidth(int w, double scale_max, int text_scale);

}  // namespace aerial::bench
