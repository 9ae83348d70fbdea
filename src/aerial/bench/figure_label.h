#pragma once
// The figures' labels: Cairo's toy text API, one sans-serif font at one size. A label is placed
// by a point of its box, whose width is the text's advance and whose height the font's ascent
// plus descent, so labels on one line share a baseline whatever their letters.
#include <cairo.h>

#include <string>

namespace aerial::bench {

// Which point of the box (x, y) names: {0, 0} its top-left corner, {0.5, 1} the middle of its
// bottom edge, {1, 0.5} the middle of its right edge.
struct Anchor {
  double x = 0.0, y = 0.0;
};

// CairoFigure selects it on every figure.
void UseLabelFont(cairo_t* cr);

// The box's size in pixels, measured as on a figure.
double LabelWidth(const std::string& text);
double LabelHeight();

// In kInk (picture.h); no current point is left behind.
void DrawLabel(cairo_t* cr, const std::string& text, double x, double y, Anchor anchor = {});

}  // namespace aerial::bench
