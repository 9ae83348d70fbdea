#pragma once
// The pipelines a context has built, shared by every pass that asks for one made of the same
// shaders, layout, fixed state and specialization. A renderer builds about a dozen, and on a CPU
// driver (lavapipe) building them, and compiling their first draws, is most of what a new renderer
// costs; a program makes several renderers on one device (the viewer after a resize or a change of
// mode, the bench per variant, a test per preset). A built pipeline stays until its context goes:
// their number is bounded by the passes' variants.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "aerial/vk/descriptors.h"

namespace aerial::vk {

struct BuiltPipeline {
  PushDescriptorLayout layout;
  ::vk::raii::Pipeline pipeline{nullptr};
};

// Everything that makes a pipeline, as bytes: each value appended with its size, so that no two
// different lists of values give the same key.
class PipelineKey {
 public:
  PipelineKey& Add(const std::string& text);
  PipelineKey& Add(uint64_t value);
  PipelineKey& Add(const SlotLayout& slots);
  PipelineKey& Add(const std::vector<int32_t>& values);
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class PipelineCache {
 public:
  // The pipeline of `key`, built by `build` the first time it is asked for. Safe from several
  // threads; a build runs outside the lock, so that one thread's build (seconds on lavapipe) does
  // not hold up another's look-up, and when two threads build the same pipeline at once the first
  // one stored is the one kept.
  std::shared_ptr<const BuiltPipeline> Get(const PipelineKey& key,
                                           const std::function<std::shared_ptr<const BuiltPipeline>()>& build);
  // Lets go of every pipeline: each is destroyed once no pass holds it.
  void Clear();
  // The number of pipelines held.
  size_t size() const;

 private:
  mutable std::mutex mutex_;
  std::unordered_map<std::string, std::shared_ptr<const BuiltPipeline>> built_;
};

}  // namespace aerial::vk
