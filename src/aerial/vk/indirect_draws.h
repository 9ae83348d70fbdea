#pragma once
// Indexed draws recorded as indirect draws: the CPU writes their commands
// (VkDrawIndexedIndirectCommand) into a host-visible buffer, and a pass records one
// vkCmdDrawIndexedIndirect per run of commands that share their state, however many commands the
// run holds. So a frame records a fixed number of draw calls whatever its terrain's level of
// detail draws, and a selection made on the GPU can fill the same commands. The commands' first
// instance is the draw's number for its shaders (as DrawIndexed's).
//
// One per frame in flight: a frame refills it (Begin), so no frame still in flight may read it.
#include <cstdint>
#include <optional>

#include "aerial/vk/resources.h"

namespace aerial::vk {

class IndirectDraws {
 public:
  explicit IndirectDraws(const Context& context) : context_(&context) {}

  // Starts a frame's commands with room for `count` of them (the buffer grows to hold them; the
  // commands of the frame before are dropped).
  void Begin(size_t count);
  // Adds a command to the run that the next Draw records; at most Begin's count in all.
  void Add(uint32_t index_count, uint32_t first_index, int32_t vertex_offset, uint32_t first_instance);
  // Records one indirect draw of the commands added since the last Draw, inside a Rendering scope
  // with the pipeline and mesh bound; returns the draw calls recorded: 1, or 0 without commands.
  int Draw(const CommandBuffer& cmd);

 private:
  const Context* context_;
  std::optional<Buffer> buffer_;
  size_t capacity_ = 0, count_ = 0, drawn_ = 0;
};

}  // namespace aerial::vk
