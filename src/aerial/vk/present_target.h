#pragma once
// Where the viewer draws its window's picture each frame and how the picture reaches the screen:
// a Vulkan swapchain (swapchain.h), or images the CPU reads and hands to the window system itself
// (viewer/x11_presenter.h). Each frame acquires a target image for the CommandRing's current slot,
// draws it in one render pass (the display pass writes every pixel, then an overlay such as Dear
// ImGui goes on top), and submits and presents it.
#include <functional>

#include "aerial/vk/command_ring.h"
#include "aerial/vk/resources.h"

namespace aerial::vk {

using Recorder = std::function<void(const CommandBuffer&)>;

// Whether a format sRGB-encodes what is stored to it (the _SRGB ones aerial uses).
bool EncodesSrgb(::vk::Format format);

class PresentTarget {
 public:
  virtual ~PresentTarget() = default;

  // Rebuilds the images for a new size (after a resize, or when Acquire or SubmitAndPresent
  // returned false). Waits for the device to be idle first.
  virtual void Recreate(::vk::Extent2D wanted) = 0;
  // Takes the image for the ring's current slot (after CommandRing::Begin). False when the target
  // is out of date: Recreate, and record nothing for this frame.
  virtual bool Acquire(const CommandRing& ring) = 0;
  // Records the render pass over the acquired image: `draw` must write every pixel.
  virtual void RecordDraw(const CommandBuffer& cmd, const Recorder& draw) const = 0;
  // Records a copy of the drawn image (after RecordDraw) into buffer, which holds
  // extent().width * height 4-byte texels of format(), row by row. Only where can_copy_out().
  virtual void RecordCopyToBuffer(const CommandBuffer& cmd, ::vk::Buffer buffer) const = 0;
  // Submits the ring's command buffer and presents the image. False when the target is out of
  // date or suboptimal: Recreate.
  virtual bool SubmitAndPresent(CommandRing& ring) = 0;
  // After every submitted frame has finished (CommandRing::WaitAll): shows those not on the
  // screen yet, where the target shows frames itself.
  virtual void ShowSubmitted() {}

  virtual bool can_copy_out() const = 0;
  virtual ::vk::Extent2D extent() const = 0;
  virtual ::vk::Format format() const = 0;
  virtual uint32_t min_image_count() const = 0;
  virtual uint32_t image_count() const = 0;
  virtual ::vk::RenderPass render_pass() const = 0;
};

}  // namespace aerial::vk
