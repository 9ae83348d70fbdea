#pragma once
// GPU timestamps around passes. Begin/End record timestamps into a command buffer; Collect reads
// them after the submission completed. On lavapipe a command buffer runs synchronously on the CPU,
// so the timestamps equal wall-clock time of the pass.
#include <string>
#include <vector>

#include "aerial/vk/context.h"

namespace aerial::vk {

using PassTime = aerial::PassTime;  // aerial/device.h

class GpuTimer {
 public:
  explicit GpuTimer(const Context& context, uint32_t max_passes = 256);
  // Resets the queries; call at the start of a command buffer, before any Begin.
  void Reset(const CommandBuffer& cmd);
  void Begin(const CommandBuffer& cmd, std::string pass);
  void End(const CommandBuffer& cmd);
  // Times of the passes recorded since Reset, in recording order.
  std::vector<PassTime> Collect() const;

 private:
  const Context& context_;
  ::vk::raii::QueryPool pool_;
  uint32_t capacity_;
  std::vector<std::string> passes_;
};

}  // namespace aerial::vk
