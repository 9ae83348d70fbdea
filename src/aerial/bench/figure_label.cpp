#include "aerial/bench/figure_label.h"

#include "aerial/bench/cairo_figure.h"

namespace aerial::bench {
namespace {

constexpr double kFontSize = 15.0;  // pixels per em

// Measures on a figure, whose metrics (hinted, rounded to whole pixels) a figure's labels get.
template <typename Measure>
double Measured(Measure measure) {
  CairoFigure scratch(1, 1);
  return measure(scratch.cr());
}

cairo_font_extents_t FontExtents(cairo_t* cr) {
  cairo_font_extents_t font;
  cairo_font_extents(cr, &font);
  return font;
}

}  // namespace

void UseLabelFont(cairo_t* cr) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, kFontSize);
}

double LabelWidth(const std::string& text) {
  return Measured([&](cairo_t* cr) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    return extents.x_advance;
  });
}

double LabelHeight() {
  return Measured([](cairo_t* cr) {
    cairo_font_extents_t font = FontExtents(cr);
    return font.ascent + font.descent;
  });
}

void DrawLabel(cairo_t* cr, const std::string& text, double x, double y, Anchor anchor) {
  cairo_font_extents_t font = FontExtents(cr);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  SetColor(cr, kInk);
  cairo_move_to(cr, x - anchor.x * extents.x_advance, y - anchor.y * (font.ascent + font.descent) + font.ascent);
  cairo_show_text(cr, text.c_str());
  cairo_new_path(cr);  // show_text leaves the current point at the text's end: a path would start there
}

}  // namespace aerial::bench
