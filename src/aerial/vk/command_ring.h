#pragma once
// Command buffers and fences reused frame after frame, for frames submitted without waiting for
// them: with n slots, the CPU records frame k + n - 1 while the GPU may still run frame k. Begin
// waits only for the slot's previous frame (n frames ago), never for the device to be idle.
#include <span>
#include <vector>

#include "aerial/vk/context.h"

namespace aerial::vk {

class CommandRing {
 public:
  CommandRing(const Context& context, uint32_t slots);
  ~CommandRing();  // waits for every submitted frame
  CommandRing(const CommandRing&) = delete;
  CommandRing& operator=(const CommandRing&) = delete;

  // Moves to the next slot, waits for its previous frame to finish and begins its command buffer.
  const CommandBuffer& Begin();
  // Ends the current slot's command buffer and submits it, waiting on `wait` (each at its stage)
  // and signalling `signal` and the slot's fence.
  void Submit(std::span<const ::vk::Semaphore> wait = {},
              std::span<const ::vk::PipelineStageFlags> wait_stages = {},
              std::span<const ::vk::Semaphore> signal = {});
  // Waits for every submitted frame (before resources they use are destroyed or read back).
  void WaitAll() const;

  uint32_t slot() const { return slot_; }
  uint32_t slots() const { return uint32_t(buffers_.size()); }

 private:
  const Context& context_;
  ::vk::raii::CommandPool pool_;
  std::vector<::vk::raii::CommandBuffer> buffers_;
  std::vector<::vk::raii::Fence> done_;  // signalled at creation: no frame is pending
  uint32_t slot_ = 0;
};

}  // namespace aerial::vk
