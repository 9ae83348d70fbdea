#pragma once
// The one in-memory image every output path shares: linear radiance as 32-bit floats, so the
// renderer hands over exactly what it computed and each format decides how to encode it (EXR
// keeps the floats, PNG tone maps them).
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace aerial {

// Linear radiance, row-major, top row first, 4 floats (R, G, B, A) per pixel. A is coverage,
// stored straight (not premultiplied into RGB); set it to 1 for an opaque sky.
struct ImageRgbF {
  int width = 0, height = 0;
  std::vector<float> rgba;

  float* pixel(int x, int y) { return rgba.data() + Offset(x, y); }
  const float* pixel(int x, int y) const { return rgba.data() + Offset(x, y); }

 private:
  size_t Offset(int x, int y) const {
    return (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 4;
  }
};

// Largest side an image may have: the maxImageDimension2D of current desktop GPUs, so the
// renderer could not have made anything larger. A bigger value is a units or parsing mistake,
// and would ask for gigabytes (16 bytes per pixel).
inline constexpr int kMaxImageSide = 16384;

// Throws Error("image size", "WxH", ...) unless both sides are in 1..kMaxImageSide. where names
// the source (a path) when there is one.
void CheckImageSize(int width, int height, const std::string& where = "");
// Also requires rgba to hold exactly 4 * width * height floats, so encoders never read past it.
void CheckImageSize(const ImageRgbF& image);

struct ToneMapOptions {
  // Radiance multiplier applied before the curve. The curve is the identity up to 0.76 (but for a
  // small toe), so exposure should map the scene's typical radiance to about mid grey, 0.18.
  double exposure = 1.0;
  // Per-channel gains before the exposure: {1, 1, 1}, or a white balance such as the sun's
  // (aerial render --white-balance). Each finite and > 0.
  std::array<double, 3> white_balance = {1.0, 1.0, 1.0};
  // Triangular noise of one 8-bit step, a fixed function of the pixel, added before rounding so
  // that a smooth sky shows no bands; off gives the plain rounding.
  bool dither = true;
};

// Linear radiance to 8-bit display values, for PNG previews.
// Per pixel: white balance and exposure, then the Khronos PBR Neutral curve (which keeps each
// colour's hue), then the sRGB OETF (IEC 61966-2-1), dithered and rounded to 8 bits. Alpha is coverage, not light: it is only clamped to [0, 1]
// and scaled. Returns RGBA8, row-major, top row first. Throws Error("image size") on a malformed
// image and Error("exposure") unless exposure is finite and > 0.
std::vector<uint8_t> ToneMapToSrgb8(const ImageRgbF& image, const ToneMapOptions& options);

// PNG encoding in memory (stb_image_write), for the caller to write the file as it likes.
// rgba8: width * height pixels of 4 bytes, row-major, top row first (as ToneMapToSrgb8 returns).
// Throws Error("image size") if rgba8 has the wrong length, Error("PNG encoding") if stb fails.
std::vector<std::byte> EncodePng(std::span<const uint8_t> rgba8, int width, int height);

// Image files, in the format the extension names (.exr or .png, any case), written atomically
// (a temporary file, then a rename): a failed, full-disk or killed write leaves the previous file
// or nothing.
// Format, an existing directory and writability, so that a caller fails before spending minutes
// rendering. Errors name `field`: what the caller calls the path (a command line's option, a
// setting's key).
void CheckImageOutputPath(const std::filesystem::path& path, const std::string& field);

// EXR: float R, G, B, A linear radiance; tone_map is ignored. PNG: ToneMapToSrgb8(image,
// tone_map). Throws Error("image size") for sides outside 1..kMaxImageSide, Error("image path")
// for an unknown extension and Error("file", path) for I/O failures; no partial file remains.
void WriteImage(const std::filesystem::path& path, const ImageRgbF& image,
                const ToneMapOptions& tone_map);


}  // namespace aerial
