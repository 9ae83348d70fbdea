#pragma once
// GPU timestamps around passes. Begin/End record timestamps into a command buffer; Collect reads
// them after the submission completed. On lavapipe a command buffer runs synchronously on the CPU,
// so the timestamps equal wall-clock time of the pass. Where the context allows pipeline
// statistics, each pass also counts its fragment-shader invocations (a pass is then begun and
// ended in the same raster scope, or both outside one, and passes do not nest).
#include <optional>
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
  std::optional<::vk::raii::QueryPool> statistics_;  // fragment-shader invocations, one query a pass
  uint32_t capacity_;
  std::vector<std::string> passes_;
};

}  // namespace aerial::vk
