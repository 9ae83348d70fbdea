#include "aerial/core/memory_budget.h"

#include <algorithm>
#include <cstdio>

#include "aerial/error.h"

namespace aerial {
namespace {
constexpr uint64_t kMiB = uint64_t{1} << 20;
}  // namespace

std::string FormatMiB(uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(kMiB));
  return text;
}

void MemoryBudget::Check(const std::vector<MemoryUse>& new_uses) const {
  std::vector<MemoryUse> uses = held;
  uses.insert(uses.end(), new_uses.begin(), new_uses.end());
  uint64_t total = 0;
  const MemoryUse* largest = nullptr;
  std::string parts;
  for (const MemoryUse& use : uses) {
    total = use.bytes > UINT64_MAX - total ? UINT64_MAX : total + use.bytes;
    if (!largest || use.bytes > largest->bytes) largest = &use;
    parts += (parts.empty() ? "" : "; ") + use.field + " " + use.value + ": " + use.what + " " +
             FormatMiB(use.bytes);
  }
  if (total <= bytes || !largest) return;
  throw Error(largest->field, largest->value,
              "sizes whose memory fits the budget: estimated " + FormatMiB(total) + " (" + parts +
                  ") > budget " + FormatMiB(bytes) + " (" + origin + ")");
}

MemoryBudget MemoryBudget::Holding(const std::vector<MemoryUse>& uses) const {
  MemoryBudget budget = *this;
  budget.held.insert(budget.held.end(), uses.begin(), uses.end());
  return budget;
}

void MemoryTally::Add(uint64_t bytes) {
  use_.bytes = bytes > UINT64_MAX - use_.bytes ? UINT64_MAX : use_.bytes + bytes;
  budget_.Check({use_});
}

MemoryBudget MakeMemoryBudget(std::optional<uint64_t> max_memory_mib, uint64_t device_heap_bytes) {
  if (max_memory_mib) return {*max_memory_mib * kMiB, "max_memory_mib " + std::to_string(*max_memory_mib)};
  uint64_t default_bytes = kDefaultMemoryBudgetMiB * kMiB;
  if (device_heap_bytes < default_bytes) return {device_heap_bytes, "the device's largest memory heap"};
  return {default_bytes, "the default"};
}

}  // namespace aerial
