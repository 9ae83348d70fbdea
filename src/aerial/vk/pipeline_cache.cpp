#include "aerial/vk/pipeline_cache.h"

namespace aerial::vk {

PipelineKey& PipelineKey::Add(const std::string& text) {
  Add(uint64_t(text.size()));
  bytes_ += text;
  return *this;
}

PipelineKey& PipelineKey::Add(uint64_t value) {
  bytes_.append(reinterpret_cast<const char*>(&value), sizeof(value));
  return *this;
}

PipelineKey& PipelineKey::Add(const SlotLayout& slots) {
  Add(uint64_t(slots.size()));
  for (const SlotSpec& slot : slots) Add(slot.name).Add(uint64_t(slot.type));
  return *this;
}

PipelineKey& PipelineKey::Add(const std::vector<int32_t>& values) {
  Add(uint64_t(values.size()));
  for (int32_t value : values) Add(uint64_t(uint32_t(value)));
  return *this;
}

std::shared_ptr<const BuiltPipeline> PipelineCache::Get(
    const PipelineKey& key, const std::function<std::shared_ptr<const BuiltPipeline>()>& build) {
  {
    std::lock_guard lock(mutex_);
    auto found = built_.find(key.bytes());
    if (found != built_.end()) return found->second;
  }
  std::shared_ptr<const BuiltPipeline> built = build();
  std::lock_guard lock(mutex_);
  return built_.emplace(key.bytes(), std::move(built)).first->second;
}

void PipelineCache::Clear() {
  std::lock_guard lock(mutex_);
  built_.clear();
}

size_t PipelineCache::size() const {
  std::lock_guard lock(mutex_);
  return built_.size();
}

}  // namespace aerial::vk
