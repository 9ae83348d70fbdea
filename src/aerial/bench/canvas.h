#pragma once
// A small RGBA8 raster for the report's figures: filled rectangles, lines, discs and text in the
// built-in 5x7 font (font5x7.h). Coordinates are pixels from the top-left corner; whatever falls
// outside the canvas is clipped.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace aerial::bench {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
};

class Canvas {
 public:
  Canvas(int width, int height, Rgb background);

  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<uint8_t>& rgba8() const { return rgba_; }

  void Set(int x, int y, Rgb color);
  void FillRect(int x, int y, int w, int h, Rgb color);
  // A segment of the given width (pixels), drawn as the pixels within width / 2 of it.
  void Line(double x0, double y0, double x1, double y1, double width, Rgb color);
  void Disc(double cx, double cy, double radius, Rgb color);
  // rgba8 of w x h pixels (alpha ignored) with its top-left corner at (x, y).
  void Blit(int x, int y, const std::vector<uint8_t>& rgba8, int w, int h);

  // Text from (x, y), its top-left corner, each font pixel drawn as scale x scale pixels.
  void Text(int x, int y, std::string_view text, int scale, Rgb color);
  static int TextWidth(std::string_view text, int scale);
  static int TextHeight(int scale);

  std::vector<std::byte> EncodePng() const;

 private:
  int width_, height_;
  std::vector<uint8_t> rgba_;
};

}  // namespace aerial::bench
