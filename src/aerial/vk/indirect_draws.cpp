#include "aerial/vk/indirect_draws.h"

#include <algorithm>
#include <stdexcept>

namespace aerial::vk {

void IndirectDraws::Begin(size_t count) {
  count_ = drawn_ = 0;
  if (count <= capacity_) return;
  // Doubling keeps a growing level of detail from making a buffer every frame.
  capacity_ = std::max({count, 2 * capacity_, size_t(256)});
  buffer_.emplace(*context_, BufferCreateInfo{.size = capacity_ * sizeof(::vk::DrawIndexedIndirectCommand),
                                              .usage = ::vk::BufferUsageFlagBits::eIndirectBuffer,
                                              .host_visible = true});
}

void IndirectDraws::Add(uint32_t index_count, uint32_t first_index, int32_t vertex_offset, uint32_t first_instance) {
  if (count_ >= capacity_) throw std::logic_error("IndirectDraws::Add beyond the count given to Begin");
  reinterpret_cast<::vk::DrawIndexedIndirectCommand*>(buffer_->mapped())[count_++] =
      ::vk::DrawIndexedIndirectCommand{.indexCount = index_count,
                                       .instanceCount = 1,
                                       .firstIndex = first_index,
                                       .vertexOffset = vertex_offset,
                                       .firstInstance = first_instance};
}

int IndirectDraws::Draw(const CommandBuffer& cmd) {
  const uint32_t commands = uint32_t(count_ - drawn_);
  if (commands == 0) return 0;
  cmd.drawIndexedIndirect(buffer_->handle(), drawn_ * sizeof(::vk::DrawIndexedIndirectCommand), commands,
                          sizeof(::vk::DrawIndexedIndirectCommand));
  drawn_ = count_;
  return 1;
}

}  // namespace aerial::vk
