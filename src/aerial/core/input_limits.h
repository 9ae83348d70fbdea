#pragma once
// Limits on input files, in one place (docs/usage.md, "Files"): far above what real inputs need,
// far below what would exhaust memory, time or the stack.
#include <cstddef>
#include <cstdint>

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

// Levels of a TOML text: dotted key parts plus nested arrays and inline tables. Aerial's files
// need 4; toml++ recurses once per level, and 40,000 overflow the stack.
inline constexpr size_t kMaxTomlDepth = 64;

// A table cache file. The largest tables the size caps allow (precompute_options.cpp: 2^22
// scattering texels in each of two 4D tables, 2^20 transmittance and 2^14 irradiance texels, 16
// bytes each) take about 145 MiB; a bigger file is not one aerial wrote, and reading it would
// allocate its size.
inline constexpr uint64_t kMaxTableCacheBytes = 1024 * kMiB;

}  // namespace aerial
