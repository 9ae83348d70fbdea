#include "aerial/vk/table_filtering.h"

#include <cstdlib>

#include "aerial/error.h"

namespace aerial::vk {

std::string ToString(TableFiltering filtering) {
  switch (filtering) {
    case TableFiltering::kSampler: return "sampler";
    case TableFiltering::kShader: return "shader";
    case TableFiltering::kEmulatedHardware: return "emulated-hardware";
  }
  return std::to_string(int(filtering));
}

TableFiltering ParseTableFiltering(const std::string& text, const std::string& field) {
  for (TableFiltering f : {TableFiltering::kSampler, TableFiltering::kShader, TableFiltering::kEmulatedHardware})
    if (text == ToString(f)) return f;
  throw Error(field, text, "sampler, shader or emulated-hardware");
}

TableFiltering TableFilteringFromEnvironment() {
  const char* value = std::getenv("AERIAL_TABLE_FILTERING");
  if (value == nullptr || *value == '\0') return TableFiltering::kSampler;
  return ParseTableFiltering(value, "AERIAL_TABLE_FILTERING");
}

}  // namespace aerial::vk
