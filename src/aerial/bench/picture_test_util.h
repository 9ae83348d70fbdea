#pragma once
// Reading a chart or figure in tests: where a colour is, what was drawn in a box, and where two
// drawings differ.
#include <algorithm>
#include <ostream>

#include "aerial/bench/picture.h"

namespace aerial::bench {

inline void PrintTo(const Rgb& c, std::ostream* os) {
  *os << "rgb(" << int(c.r) << ", " << int(c.g) << ", " << int(c.b) << ")";
}

// The pixels x0 <= x < x1, y0 <= y < y1.
struct Box {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  bool Empty() const { return x1 <= x0 || y1 <= y0; }
  int Width() const { return Empty() ? 0 : x1 - x0; }
  int Height() const { return Empty() ? 0 : y1 - y0; }
  bool operator==(const Box&) const = default;
  // May be true of an empty box.
  bool Inside(const Box& outer) const {
    return x0 >= outer.x0 && y0 >= outer.y0 && x1 <= outer.x1 && y1 <= outer.y1;
  }
  // Grows to hold the pixel (x, y).
  void Add(int x, int y) {
    if (Empty()) {
      *this = {x, y, x + 1, y + 1};
      return;
    }
    x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x + 1), y1 = std::max(y1, y + 1);
  }
};

inline std::ostream& operator<<(std::ostream& os, const Box& b) {
  return os << "[" << b.x0 << ", " << b.x1 << ") x [" << b.y0 << ", " << b.y1 << ")";
}

// Calls f(x, y) for each pixel of box that p has.
template <typename F>
void ForEachPixel(const Picture& p, const Box& box, F f) {
  for (int y = std::max(box.y0, 0); y < std::min(box.y1, p.height); ++y)
    for (int x = std::max(box.x0, 0); x < std::min(box.x1, p.width); ++x) f(x, y);
}

inline Box Whole(const Picture& p) { return {0, 0, p.width, p.height}; }

// The smallest box around the pixels of color within `within`.
inline Box BoxOf(const Picture& p, Rgb color, const Box& within) {
  Box box;
  ForEachPixel(p, within, [&](int x, int y) {
    if (p.At(x, y) == color) box.Add(x, y);
  });
  return box;
}
inline Box BoxOf(const Picture& p, Rgb color) { return BoxOf(p, color, Whole(p)); }

// How many pixels of color are in box.
inline int Count(const Picture& p, const Box& box, Rgb color) {
  int count = 0;
  ForEachPixel(p, box, [&](int x, int y) { count += p.At(x, y) == color; });
  return count;
}

// Pixels in box that are not the paper's colour: something is drawn there.
inline int Drawn(const Picture& p, const Box& box) {
  int drawn = 0;
  ForEachPixel(p, box, [&](int x, int y) { drawn += p.At(x, y) != kPaper; });
  return drawn;
}

// Where a and b (of one size) differ.
inline Box Changed(const Picture& a, const Picture& b) {
  Box box;
  ForEachPixel(a, Whole(a), [&](int x, int y) {
    if (a.At(x, y) != b.At(x, y)) box.Add(x, y);
  });
  return box;
}

}  // namespace aerial::bench
