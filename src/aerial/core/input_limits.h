#pragma once
// Limits on input files, in one place (README, "### Files"): far above what real inputs need,
// far below what would exhaust memory, time or the stack.
#include <cstddef>

namespace aerial {

inline constexpr size_t kMiB = size_t{1} << 20;

// An atmosphere, scene or camera path TOML file. The largest example is under 4 KiB; 1 MiB is a
// few hundred times that, and toml++ parses it in well under a second.
inline constexpr size_t kMaxTomlFileBytes = 1 * kMiB;

// A glTF model: the .gltf or .glb file and all its external buffers together. Big enough for
// millions of triangles (a vertex takes 24 bytes with its normal); tinygltf takes the file's size
// as a 32-bit unsigned int, so the cap also keeps it well inside that.
inline constexpr size_t kMaxGltfBytes = 256 * kMiB;

// Levels of nested arrays and objects in a JSON text (a glTF's JSON). glTF itself needs about 8
// (extras and extensions may add a few); tinygltf's JSON parser recurses once per level, and
// 100,000 levels overflow the stack.
inline constexpr size_t kMaxJsonDepth = 64;

}  // namespace aerial
