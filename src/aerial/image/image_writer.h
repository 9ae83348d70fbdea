#pragma once
// Writing a rendered image to disk, in the format its extension names. Every write is atomic
// (temporary + rename, see core/atomic_file.h): a failed, full-disk or killed export leaves the
// previous file or nothing, never a truncated image.
#include <filesystem>
#include <string>

#include "aerial/image.h"

// WriteImage and CheckImageOutputPath, the public calls, are declared in aerial/image.h.

namespace aerial {

enum class ImageFormat {
  kExr,  // linear float radiance, for measurement and golden images
  kPng,  // tone-mapped sRGB preview
};

// By extension, case-insensitive (".exr", ".PNG"). Throws Error(field, path, ".exr or .png"); field
// names where the path came from.
ImageFormat ImageFormatFromPath(const std::filesystem::path& path, const std::string& field);

// Reads an EXR written by WriteImage (or any EXR with R, G, B). Throws Error naming the path.
ImageRgbF ReadExr(const std::filesystem::path& path);

}  // namespace aerial
