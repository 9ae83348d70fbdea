#include "aerial/bench/canvas.h"

#include <algorithm>
#include <cmath>

#include "aerial/bench/font5x7.h"
#include "aerial/image.h"

namespace aerial::bench {

Canvas::Canvas(int width, int height, Rgb background)
    : width_(width), height_(height), rgba_(size_t(width) * size_t(height) * 4) {
  FillRect(0, 0, width, height, background);
}

void Canvas::Set(int x, int y, Rgb color) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  uint8_t* p = rgba_.data() + (size_t(y) * size_t(width_) + size_t(x)) * 4;
  p[0] = color.r;
  p[1] = color.g;
  p[2] = color.b;
  p[3] = 255;
}

void Canvas::FillRect(int x, int y, int w, int h, Rgb color) {
  for (int j = std::max(y, 0); j < std::min(y + h, height_); ++j)
    for (int i = std::max(x, 0); i < std::min(x + w, width_); ++i) Set(i, j, color);
}

void Canvas::Line(double x0, double y0, double x1, double y1, double width, Rgb color) {
  double dx = x1 - x0, dy = y1 - y0, length2 = dx * dx + dy * dy;
  double half = 0.5 * width;
  int left = int(std::floor(std::min(x0, x1) - half)), right = int(std::ceil(std::max(x0, x1) + half));
  int top = int(std::floor(std::min(y0, y1) - half)), bottom = int(std::ceil(std::max(y0, y1) + half));
  for (int y = top; y <= bottom; ++y)
    for (int x = left; x <= right; ++x) {
      // Distance from the pixel center to the segment.
      double px = x + 0.5 - x0, py = y + 0.5 - y0;
      double t = length2 > 0.0 ? std::clamp((px * dx + py * dy) / length2, 0.0, 1.0) : 0.0;
      if (std::hypot(px - t * dx, py - t * dy) <= half) Set(x, y, color);
    }
}

void Canvas::Disc(double cx, double cy, double radius, Rgb color) {
  Line(cx, cy, cx, cy, 2.0 * radius, color);
}

void Canvas::Blit(int x, int y, const std::vector<uint8_t>& rgba8, int w, int h) {
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const uint8_t* p = rgba8.data() + (size_t(j) * size_t(w) + size_t(i)) * 4;
      Set(x + i, y + j, {p[0], p[1], p[2]});
    }
}

void Canvas::Text(int x, int y, std::string_view text, int scale, Rgb color) {
  for (char c : text) {
    const auto* glyph = Glyph5x7(c);
    if (!glyph) glyph = Glyph5x7('_');  // a character the font lacks shows as an underscore
    for (int row = 0; row < kGlyphHeight; ++row)
      for (int column = 0; column < kGlyphWidth; ++column)
        if ((*glyph)[row][column] == '#') FillRect(x + column * scale, y + row * scale, scale, scale, color);
    x += kGlyphAdvance * scale;
  }
}

int Canvas::TextWidth(std::string_view text, int scale) {
  return text.empty() ? 0 : (int(text.size()) * kGlyphAdvance - 1) * scale;
}

int Canvas::TextHeight(int scale) { return kGlyphHeight * scale; }

std::vector<std::byte> Canvas::EncodePng() const { return aerial::EncodePng(rgba_, width_, height_); }

}  // namespace aerial::bench
