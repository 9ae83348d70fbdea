#pragma once
// The memory a command may allocate for its tables, froxels and images, compared with estimates
// made before anything is allocated: a size too large for the machine then fails at once, with a
// message naming what sizes the largest part, the estimate and the budget, instead of ending in
// ErrorOutOfDeviceMemory (or the kernel's OOM killer) after minutes of work. On a CPU driver such
// as lavapipe device memory is host memory, so the host copies made to read images back count too.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace aerial {

// 2 GiB: a default render is estimated at 0.9 GiB, a 3840x2160 one at 1.5 GiB, the viewer at 1.2.
inline constexpr uint64_t kDefaultMemoryBudgetMiB = 2048;

// One part of an estimate, under what sizes it.
struct MemoryUse {
  std::string field;  // an input ("scene file", "glTF model"), or a command's option ("--scattering-size")
  std::string value;  // its value as given or defaulted: "scene.toml", "32,128,40,8", "16384x16384"
  std::string what;    // "tables, precompute scratch and cache copies"
  uint64_t bytes = 0;
};

struct MemoryBudget {
  uint64_t bytes = 0;
  std::string origin;  // where it comes from, for the message: "max_memory_mib 512", "the default"
  // Memory the command already holds when this budget is handed on (the scene's models loaded so
  // far), counted in every Check: one budget for everything a command loads, not one per input.
  std::vector<MemoryUse> held;

  // Throws aerial::Error when the uses, with those held, add up to more than the budget. The
  // error names the field of the largest use and its value, the estimate with its parts, and
  // the budget.
  void Check(const std::vector<MemoryUse>& uses) const;
  // This budget with `uses` held as well.
  MemoryBudget Holding(const std::vector<MemoryUse>& uses) const;
};

// Memory an input's loader allocates as it reads (a glTF model's JSON tree and geometry, whose
// size only the file knows), added up and checked against the budget (with what it holds) before
// each allocation.
class MemoryTally {
 public:
  // field and value name the input in the error, as MemoryUse does; what says what is counted.
  MemoryTally(MemoryBudget budget, std::string field, std::string value, std::string what)
      : budget_(std::move(budget)), use_{std::move(field), std::move(value), std::move(what), 0} {}

  // Throws as MemoryBudget::Check when the total with bytes exceeds the budget.
  void Add(uint64_t bytes);

 private:
  MemoryBudget budget_;
  MemoryUse use_;
};

// max_memory_mib when given (any value >= 1, even above the device's memory: the user knows
// their machine); else the default, or the device's largest heap when that is smaller.
MemoryBudget MakeMemoryBudget(std::optional<uint64_t> max_memory_mib, uint64_t device_heap_bytes);

// "40.3 MiB", for messages.
std::string FormatMiB(uint64_t bytes);

}  // namespace aerial
