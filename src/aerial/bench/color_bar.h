#pragma once
// The colour bar beside a heat map (heatmap.h): HeatColor from scale_max at the top to 0 at the
// bottom, with three ticks (0, half and scale_max) labelled in percent on its right.
#include <cairo.h>

namespace aerial::bench {

// The bar is w x h pixels, its top-left corner at (x, y).
void DrawColorBar(cairo_t* cr, int x, int y, int w, int h, double scale_max);
// The width DrawColorBar covers, labels included.
int ColorBarWidth(int w, double scale_max);

}  // namespace aerial::bench
