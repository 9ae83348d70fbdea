#include "aerial/bench/picture.h"

#include "aerial/image.h"

namespace aerial::bench {

Rgb Picture::At(int x, int y) const {
  const uint8_t* p = rgba8.data() + (size_t(y) * size_t(width) + size_t(x)) * 4;
  return {p[0], p[1], p[2]};
}

std::vector<std::byte> Picture::EncodePng() const { return aerial::EncodePng(rgba8, width, height); }

}  // namespace aerial::bench
