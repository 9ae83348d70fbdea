#include "aerial/vk/specialization.h"

namespace aerial::vk {

Specialization::Specialization(std::vector<int32_t> values, TableFiltering filtering) : values_(std::move(values)) {
  for (uint32_t i = 0; i < values_.size(); ++i)
    entries_.push_back({.constantID = i, .offset = uint32_t(i * sizeof(int32_t)), .size = sizeof(int32_t)});
  entries_.push_back({.constantID = kTableFilteringConstantId, .offset = uint32_t(values_.size() * sizeof(int32_t)),
                      .size = sizeof(int32_t)});
  values_.push_back(int32_t(filtering));
  info_ = ::vk::SpecializationInfo{.mapEntryCount = uint32_t(entries_.size()),
                                   .pMapEntries = entries_.data(),
                                   .dataSize = values_.size() * sizeof(int32_t),
                                   .pData = values_.data()};
}

}  // namespace aerial::vk
