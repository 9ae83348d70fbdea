#pragma once
// The frame as an OpenEXR file: linear radiance in 32-bit float channels R, G, B, and a channel
// "distance" with each pixel's distance to the surface seen (m; infinite on the sky), which
// tells the sky's pixels from the meshes' ones. Reading also takes files without it (aerial
// render's): their distance is infinite.
#include <filesystem>
#include <vector>

struct RgbdImage {
  int width = 0, height = 0;
  std::vector<float> rgbd;  // r, g, b, distance per pixel, top row first
};

void WriteExr(const std::filesystem::path& path, const RgbdImage& image);
RgbdImage ReadExr(const std::filesystem::path& path);
