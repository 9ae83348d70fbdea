#pragma once
// A finished chart or figure of the report: opaque 8-bit sRGB pixels, as its PNG file holds them.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace aerial::bench {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

// Every chart and figure is drawn on this paper, its axes and labels in this ink.
inline constexpr Rgb kPaper{255, 255, 255}, kInk{20, 20, 20};

struct Picture {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba8;  // row-major from the top-left corner, alpha 255

  Rgb At(int x, int y) const;
  std::vector<std::byte> EncodePng() const;
};

}  // namespace aerial::bench
