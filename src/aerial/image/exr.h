#pragma once
// OpenEXR encoding in memory. Encoding to bytes rather than to a path lets the caller write the
// file atomically (WriteFileAtomically), so a failed or killed export never leaves half an EXR.
#include <array>
#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "aerial/image.h"

namespace aerial {

// Header attributes beside the standard ones: OpenEXR's string, float and v3f types, and its
// "envmap" attribute, which marks a lat-long or cube environment map (ImfEnvmap.h).
struct ExrHeaderExtras {
  enum class Envmap { kNone, kLatLong, kCube };
  Envmap envmap = Envmap::kNone;
  std::map<std::string, std::variant<std::string, float, std::array<float, 3>>> attributes;
};

// Scanline EXR with 32-bit FLOAT channels R, G, B, A (not half: half keeps 11 bits of mantissa
// and overflows at 65504, too coarse for radiance used as reference data). ZIP compression is
// lossless, so the floats come back bit-identical.
std::vector<std::byte> EncodeExr(const ImageRgbF& image, const ExrHeaderExtras& extras = {});

// Decodes any EXR that has R, G and B channels; a missing A reads as 1 (opaque), and half
// channels are widened to float. where names the source in errors (usually the path).
ImageRgbF DecodeExr(std::span<const std::byte> bytes, const std::string& where);

}  // namespace aerial
