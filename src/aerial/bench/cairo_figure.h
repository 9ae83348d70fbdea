#pragma once
// A chart or figure drawn with Cairo's C API: an opaque RGB image surface on white paper, its
// context set to the labels' font (figure_label.h), and the few drawing steps the figures share.
// Coordinates are pixels from the top-left corner.
#include <cairo.h>

#include <cstdint>
#include <vector>

#include "aerial/bench/picture.h"

namespace aerial::bench {

class CairoFigure {
 public:
  // Throws aerial::Error if Cairo cannot make a surface of that size.
  CairoFigure(int width, int height);
  ~CairoFigure();
  CairoFigure(const CairoFigure&) = delete;
  CairoFigure& operator=(const CairoFigure&) = delete;

  cairo_t* cr() const { return cr_; }
  // The pixels drawn so far.
  Picture Finish() const;

 private:
  cairo_surface_t* surface_;
  cairo_t* cr_;
};

void SetColor(cairo_t* cr, Rgb color);
// At whole-pixel coordinates a rectangle covers whole pixels: no blended edges.
void FillRect(cairo_t* cr, double x, double y, double w, double h, Rgb color);
// rgba8, w x h pixels (alpha ignored), copied as they are with their top-left corner at (x, y).
void DrawPixels(cairo_t* cr, int x, int y, const std::vector<uint8_t>& rgba8, int w, int h);

}  // namespace aerial::bench
