#pragma once
// AERIAL_TABLE_FILTERING set for the contexts and devices made while it lives (the sampler's
// reads: unset), and unset after.
#include <cstdlib>

#include "aerial/vk/table_filtering.h"

namespace aerial::testing {

class ScopedTableFiltering {
 public:
  explicit ScopedTableFiltering(vk::TableFiltering filtering) {
    if (filtering != vk::TableFiltering::kSampler)
      ::setenv("AERIAL_TABLE_FILTERING", vk::ToString(filtering).c_str(), 1);
  }
  ~ScopedTableFiltering() { ::unsetenv("AERIAL_TABLE_FILTERING"); }
  ScopedTableFiltering(const ScopedTableFiltering&) = delete;
  ScopedTableFiltering& operator=(const ScopedTableFiltering&) = delete;
};

}  // namespace aerial::testing
