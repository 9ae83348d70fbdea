#include "aerial/precompute/finite_tables.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>

#include "aerial/error.h"

namespace aerial {
namespace {

// A 2x2x1 rgba32f table of ones.
CachedTable Ones(const std::string& name) {
  CachedTable table{.name = name, .width = 2, .height = 2, .depth = 1, .format = TexelFormat::kRgba32f};
  table.texels.resize(2 * 2 * 16);
  for (size_t i = 0; i < table.texels.size(); i += 4) {
    float one = 1.0f;
    std::memcpy(table.texels.data() + i, &one, 4);
  }
  return table;
}

// A thick atmosphere with 16 orders overflows float: the NaN tables must not give a NaN sky and
// exit status 0.
TEST(FiniteTables, ANanIsNamedWithItsTableAndPass) {
  TableCache tables;
  tables.tables = {Ones("transmittance"), Ones("multiple_density")};
  EXPECT_NO_THROW(CheckFiniteTables(tables));
  float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(tables.tables[1].texels.data() + 3 * 16 + 8, &nan, 4);  // texel (1, 1), blue
  try {
    CheckFiniteTables(tables);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "precompute pass \"accumulate density\"");
    EXPECT_EQ(e.value(), "NaN or infinity in table \"multiple_density\" at texel (1, 1, 0)");
  }
}

TEST(FiniteTables, HalfFloatInfinityIsFound) {
  CachedTable table{.name = "rayleigh", .width = 1, .height = 1, .depth = 1, .format = TexelFormat::kRgba16f};
  table.texels.assign(8, std::byte{0});
  table.texels[7] = std::byte{0x7C};  // alpha = +inf
  TableCache tables;
  tables.tables = {table};
  EXPECT_THROW(CheckFiniteTables(tables), Error);
}

}  // namespace
}  // namespace aerial
