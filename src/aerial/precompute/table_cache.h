#pragma once
// Precomputed tables on disk, so that a parameter set pays for its precompute once (tens of
// seconds on a CPU Vulkan driver) and later runs load it in milliseconds.
//
// A cache file is only ever used for the parameters it was made for: its key hashes the
// atmosphere (AtmosphereParameters::Hash) and the precompute options (resolutions, scattering
// orders, precision, 3D/4D variant). Anything unexpected, whether a missing or truncated file,
// a flipped bit, another version or another key, throws aerial::Error and the caller recomputes.
//
// File layout (little-endian; the first 24 bytes keep this layout in every version):
//   0   char[8] magic "AERIALT\0"
//   8   u32 version (kTableCacheVersion)
//   12  u32 header_bytes: size of the header section below
//   16  u64 file_bytes: size of the whole file, so truncation is found before reading tables
//   24  header section: u64 atmosphere_hash, u64 options_hash, string description,
//       u32 table count, then per table: string name, u32 width, height, depth, u32 format,
//       u64 texel_bytes, u64 texel_checksum (strings are a u32 byte count and UTF-8 bytes)
//   24 + header_bytes   u64 header checksum: Checksum() of every byte before it
//   32 + header_bytes   payload: each table's texels in header order, back to back
// Checksums are XXH64 (core/checksum.h). Each table has its own, so an error names the table.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace aerial {

enum class TexelFormat : uint32_t { kRgba32f = 0, kRgba16f = 1 };

// 16 or 8 bytes per texel; 0 for a value outside the enum (e.g. read from a corrupt file).
uint32_t TexelBytes(TexelFormat format);

struct CachedTable {
  std::string name;  // "transmittance", "scattering", ... for messages and lookup.
  uint32_t width = 0, height = 0, depth = 1;
  TexelFormat format = TexelFormat::kRgba32f;
  std::vector<std::byte> texels;  // width * height * depth * TexelBytes(format), x fastest.
};

struct TableCacheKey {
  uint64_t atmosphere_hash = 0;
  uint64_t options_hash = 0;  // resolutions, orders, precision, variant.
  bool operator==(const TableCacheKey&) const = default;
};

struct TableCache {
  TableCacheKey key;
  std::string description;  // human-readable summary, e.g. "earth, 4 orders, rgba32f".
  std::vector<CachedTable> tables;
};

inline constexpr uint32_t kTableCacheVersion = 1;

// Writes atomically (core/atomic_file.h): readers see the old file or the whole new one.
// Throws aerial::Error if a table's extent, format and byte count disagree, or on I/O failure.
void WriteTableCache(const std::filesystem::path& path, const TableCache& cache);

// Reads and verifies a cache made for `expected`. Throws aerial::Error, with where = path and a
// field telling what failed: "cache file" (missing or unreadable), "cache magic" (not a cache),
// "cache version" (unsupported), "cache size" (truncated or trailing bytes), "cache header
// checksum", "cache header" (inconsistent contents), "cache key" (stale: made for another
// parameter set), "cache table \"<name>\"" (bad extent, format or size) and
// "cache table \"<name>\" checksum".
TableCache ReadTableCache(const std::filesystem::path& path, const TableCacheKey& expected);

}  // namespace aerial
