#pragma once
// PNG encoding in memory (stb_image_write), so the caller can write the file atomically.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace aerial {

// rgba8: width * height pixels of 4 bytes, row-major, top row first (as ToneMapToSrgb8 returns).
// Throws Error("image size") if rgba8 has the wrong length, Error("PNG encoding") if stb fails.
std::vector<std::byte> EncodePng(std::span<const uint8_t> rgba8, int width, int height);

}  // namespace aerial
