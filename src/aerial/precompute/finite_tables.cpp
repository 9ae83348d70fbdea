#include "aerial/precompute/finite_tables.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>

#include "aerial/error.h"

namespace aerial {
namespace {

// The passes that write each table last (precomputer.cpp).
const std::map<std::string, std::string> kWriters = {
    {"transmittance", "transmittance"},
    {"irradiance", "indirect irradiance"},
    {"rayleigh", "single scattering / accumulate"},
    {"mie", "single scattering"},
    {"multiple", "accumulate"},
    {"multiple_density", "accumulate density"},
};

// Whether the channel at byte offset is finite: a float32, or a float16 whose exponent is not all
// ones.
bool FiniteAt(const CachedTable& table, size_t offset) {
  if (table.format == TexelFormat::kRgba16f) {
    uint16_t half;
    std::memcpy(&half, table.texels.data() + offset, 2);
    return (half & 0x7C00) != 0x7C00;
  }
  float value;
  std::memcpy(&value, table.texels.data() + offset, 4);
  return std::isfinite(value);
}

}  // namespace

std::optional<NonFiniteTexel> FindNonFiniteTexel(const TableCache& tables) {
  for (const CachedTable& table : tables.tables) {
    size_t channel = TexelBytes(table.format) / 4;
    if (channel == 0 || table.width == 0 || table.height == 0) continue;  // no texels to read
    for (size_t offset = 0; offset + channel <= table.texels.size(); offset += channel) {
      if (FiniteAt(table, offset)) continue;
      size_t texel = offset / TexelBytes(table.format);
      size_t x = texel % table.width, y = texel / table.width % table.height,
             z = texel / (size_t{table.width} * table.height);
      return NonFiniteTexel{table.name, "NaN or infinity in table \"" + table.name + "\" at texel (" +
                                            std::to_string(x) + ", " + std::to_string(y) + ", " +
                                            std::to_string(z) + ")"};
    }
  }
  return std::nullopt;
}

void CheckFiniteTables(const TableCache& tables) {
  std::optional<NonFiniteTexel> bad = FindNonFiniteTexel(tables);
  if (!bad) return;
  auto writer = kWriters.find(bad->table);
  throw Error("precompute pass \"" + (writer == kWriters.end() ? bad->table : writer->second) + "\"",
              bad->description,
              "finite tables (the atmosphere or the orders may be beyond what float arithmetic "
              "holds; fewer PrecomputeOptions::orders or a thinner atmosphere)");
}

}  // namespace aerial
