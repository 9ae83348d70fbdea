// CTest label "sanitizer": the small tables' precompute: run under the sanitizers too.
// Every precomputed table is finite and non-negative, in every variant and precision the tests
// build: a NaN in one texel spreads through every later order and every frame.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "aerial/precompute/precomputer.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

// IEEE half to float, enough for finiteness and sign checks.
float HalfToFloat(uint16_t h) {
  uint32_t sign = (h >> 15) & 1, exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
  if (exponent == 0x1f) return mantissa ? NAN : (sign ? -INFINITY : INFINITY);
  float value = exponent == 0 ? std::ldexp(float(mantissa), -24)
                              : std::ldexp(float(mantissa | 0x400), int(exponent) - 25);
  return sign ? -value : value;
}

void ExpectFiniteAndNonNegative(const TableCache& cache) {
  for (const CachedTable& table : cache.tables) {
    size_t count = size_t(table.width) * table.height * table.depth * 4;
    size_t bad = 0;
    for (size_t i = 0; i < count; ++i) {
      float value;
      if (table.format == TexelFormat::kRgba16f) {
        uint16_t h;
        std::memcpy(&h, table.texels.data() + 2 * i, 2);
        value = HalfToFloat(h);
      } else {
        std::memcpy(&value, table.texels.data() + 4 * i, 4);
      }
      if (!std::isfinite(value) || value < 0.0f) ++bad;
    }
    EXPECT_EQ(bad, 0u) << table.name << ": " << bad << " texels are NaN, infinite or negative";
  }
}

class TableSanity : public GpuTest {};

TEST_F(TableSanity, DefaultTablesAreFiniteAndNonNegative) {
  ExpectFiniteAndNonNegative(FullTables().Download());
}

TEST_F(TableSanity, SmallHalfPrecisionTablesAreFiniteAndNonNegative) {
  PrecomputeOptions options = PrecomputeOptions::Small();
  options.precision = TablePrecision::kFloat16;
  AtmosphereTables tables(SharedContext(), AtmosphereParameters::Earth(), options);
  Precompute(tables, nullptr);
  TableCache cache = tables.Download();
  EXPECT_EQ(cache.tables[2].format, TexelFormat::kRgba16f);
  ExpectFiniteAndNonNegative(cache);
}

}  // namespace
}  // namespace aerial::testing
