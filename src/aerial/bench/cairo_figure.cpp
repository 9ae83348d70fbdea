#include "aerial/bench/cairo_figure.h"

#include <string>

#include "aerial/bench/figure_label.h"
#include "aerial/error.h"

namespace aerial::bench {
namespace {

// A pixel of a CAIRO_FORMAT_RGB24 surface: 0x00RRGGBB, in the machine's byte order.
uint32_t* Row(cairo_surface_t* surface, int y) {
  unsigned char* data = cairo_image_surface_get_data(surface);
  return reinterpret_cast<uint32_t*>(data + size_t(y) * size_t(cairo_image_surface_get_stride(surface)));
}

cairo_surface_t* NewSurface(int width, int height) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  if (cairo_status_t status = cairo_surface_status(surface); status != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface);
    throw Error("figure size", std::to_string(width) + "x" + std::to_string(height),
                std::string("a surface Cairo can make (") + cairo_status_to_string(status) + ")");
  }
  return surface;
}

}  // namespace

CairoFigure::CairoFigure(int width, int height) : surface_(NewSurface(width, height)), cr_(cairo_create(surface_)) {
  FillRect(cr_, 0, 0, width, height, kPaper);
  UseLabelFont(cr_);
}

CairoFigure::~CairoFigure() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
}

Picture CairoFigure::Finish() const {
  cairo_surface_flush(surface_);
  Picture picture{cairo_image_surface_get_width(surface_), cairo_image_surface_get_height(surface_), {}};
  picture.rgba8.reserve(size_t(picture.width) * size_t(picture.height) * 4);
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < picture.width; ++x) {
      uint32_t p = Row(surface_, y)[x];
      picture.rgba8.insert(picture.rgba8.end(), {uint8_t(p >> 16), uint8_t(p >> 8), uint8_t(p), 255});
    }
  return picture;
}

void SetColor(cairo_t* cr, Rgb color) { cairo_set_source_rgb(cr, color.r / 255.0, color.g / 255.0, color.b / 255.0); }

void FillRect(cairo_t* cr, double x, double y, double w, double h, Rgb color) {
  SetColor(cr, color);
  cairo_rectangle(cr, x, y, w, h);
  cairo_fill(cr);
}

void DrawPixels(cairo_t* cr, int x, int y, const std::vector<uint8_t>& rgba8, int w, int h) {
  cairo_surface_t* image = NewSurface(w, h);
  cairo_surface_flush(image);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const uint8_t* p = rgba8.data() + (size_t(j) * size_t(w) + size_t(i)) * 4;
      Row(image, j)[i] = uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2];
    }
  cairo_surface_mark_dirty(image);
  cairo_set_source_surface(cr, image, x, y);
  cairo_rectangle(cr, x, y, w, h);
  cairo_fill(cr);
  cairo_surface_destroy(image);
}

}  // namespace aerial::bench
