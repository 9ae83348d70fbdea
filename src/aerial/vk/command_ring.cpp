#include "aerial/vk/command_ring.h"

#include "aerial/error.h"

namespace aerial::vk {

CommandRing::CommandRing(const Context& context, uint32_t slots)
    : context_(context),
      pool_(context.device(), ::vk::CommandPoolCreateInfo{
                                  .flags = ::vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                  .queueFamilyIndex = context.queue_family()}) {
  buffers_ = ::vk::raii::CommandBuffers(
      context.device(), ::vk::CommandBufferAllocateInfo{.commandPool = *pool_,
                                                        .level = ::vk::CommandBufferLevel::ePrimary,
                                                        .commandBufferCount = slots});
  for (uint32_t i = 0; i < slots; ++i)
    done_.emplace_back(context.device(), ::vk::FenceCreateInfo{.flags = ::vk::FenceCreateFlagBits::eSignaled});
  slot_ = slots - 1;  // the first Begin moves to slot 0
}

CommandRing::~CommandRing() {
  // A destructor must not throw; a lost device has nothing left to wait for.
  try {
    WaitAll();
  } catch (const std::exception&) {
  }
}

const CommandBuffer& CommandRing::Begin() {
  slot_ = (slot_ + 1) % slots();
  if (context_.device().waitForFences(*done_[slot_], VK_TRUE, UINT64_MAX) != ::vk::Result::eSuccess)
    throw Error("vkWaitForFences", "timeout", "completion");
  const auto& cmd = buffers_[slot_];
  cmd.reset();
  cmd.begin(::vk::CommandBufferBeginInfo{.flags = ::vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
  return cmd;
}

void CommandRing::Submit(std::span<const ::vk::Semaphore> wait,
                         std::span<const ::vk::PipelineStageFlags> wait_stages,
                         std::span<const ::vk::Semaphore> signal) {
  if (wait.size() != wait_stages.size())
    throw Error("wait stages", std::to_string(wait_stages.size()), std::to_string(wait.size()));
  const auto& cmd = buffers_[slot_];
  cmd.end();
  context_.device().resetFences(*done_[slot_]);
  ::vk::CommandBuffer raw = *cmd;
  context_.queue().submit(::vk::SubmitInfo{.waitSemaphoreCount = uint32_t(wait.size()),
                                           .pWaitSemaphores = wait.data(),
                                           .pWaitDstStageMask = wait_stages.data(),
                                           .commandBufferCount = 1,
                                           .pCommandBuffers = &raw,
                                           .signalSemaphoreCount = uint32_t(signal.size()),
                                           .pSignalSemaphores = signal.data()},
                          *done_[slot_]);
}

void CommandRing::WaitAll() const {
  std::vector<::vk::Fence> fences;
  for (const auto& fence : done_) fences.push_back(*fence);
  if (context_.device().waitForFences(fences, VK_TRUE, UINT64_MAX) != ::vk::Result::eSuccess)
    throw Error("vkWaitForFences", "timeout", "completion");
}

}  // namespace aerial::vk
