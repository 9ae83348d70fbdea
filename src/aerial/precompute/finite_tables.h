#pragma once
// A NaN or an infinity in precomputed tables is an error naming the pass that wrote the table, never
// a sky of NaN pixels with exit status 0: checked on the texels read back after a precompute (the
// read-back the cache write needs anyway), before they are used or cached, and on the texels of a
// cache file as it is read (ReadTableCache), whose checksums only say the file is as written.
#include <optional>
#include <string>

#include "aerial/precompute/table_cache.h"

namespace aerial {

// The first texel with a NaN or infinite channel: its table and position, as
// "NaN or infinity in table \"<name>\" at texel (x, y, z)".
struct NonFiniteTexel {
  std::string table;
  std::string description;
};
std::optional<NonFiniteTexel> FindNonFiniteTexel(const TableCache& tables);

// Throws Error("precompute pass \"<pass>\"", "NaN or infinity in table \"<name>\" at texel
// (x, y, z)", ...) for the first non-finite texel.
void CheckFiniteTables(const TableCache& tables);

}  // namespace aerial
