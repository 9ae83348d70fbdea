#pragma once
// Writing a rendered image to disk, in the format its extension names. Every write is atomic
// (temporary + rename, see core/atomic_file.h): a failed, full-disk or killed export leaves the
// previous file or nothing, never a truncated image.
#include <filesystem>
#include <string>

#include "aerial/image/image.h"
#include "aerial/image/tone_map.h"

namespace aerial {

enum class ImageFormat {
  kExr,  // linear float radiance, for measurement and golden images
  kPng,  // tone-mapped sRGB preview
};

// By extension, case-insensitive (".exr", ".PNG"). Throws Error(field, path, ".exr or .png"); field
// names the option the path came from.
ImageFormat ImageFormatFromPath(const std::filesystem::path& path, const std::string& field = "--out");

// Format, an existing directory and writability, so a command fails before spending minutes
// rendering. Errors name `field`.
void CheckImageOutputPath(const std::filesystem::path& path, const std::string& field = "--out");

// EXR: float R, G, B, A linear radiance; tone_map is ignored. PNG: ToneMapToSrgb8(image,
// tone_map). Throws Error("image size") for sides outside 1..kMaxImageSide, Error("--out") for an
// unknown extension and Error("file", path) for I/O failures; no partial file remains.
void WriteImage(const std::filesystem::path& path, const ImageRgbF& image,
                const ToneMapOptions& tone_map);

// Reads an EXR written by WriteImage (or any EXR with R, G, B). Throws Error naming the path.
ImageRgbF ReadExr(const std::filesystem::path& path);

}  // namespace aerial
