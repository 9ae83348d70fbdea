#pragma once
// The accuracy tests' recorded figures are tables of regions, each named by a quantity, a band of
// sun angles and the camera's altitude in km (physical_sky_test.cpp, colour_reference_test.cpp).
#include <string>

namespace aerial::testing {

// The row of `table` recorded for a region, or null.
template <typename Row, size_t N, typename Quantity>
const Row* FindMeasuredRegion(const Row (&table)[N], Quantity quantity, const std::string& band, double altitude_m) {
  for (const Row& row : table)
    if (row.quantity == quantity && band == row.band && altitude_m == row.altitude_km * 1000.0) return &row;
  return nullptr;
}

}  // namespace aerial::testing
