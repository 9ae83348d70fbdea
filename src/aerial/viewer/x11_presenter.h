#pragma once
// The window's picture put on an X11 window by aerial itself, for a device that renders into host
// memory (a CPU device such as lavapipe). Mesa's swapchain on such a device sends each frame to
// the X server in one PutImage request, or through shared memory where the server has DRI3. An X
// server without DRI3 (Xvfb, VNC, remote X) then reads a 3.7 MB request per 1280x720 frame, and
// Xvfb spends about 14 ms a frame growing and filling its request buffer for it; the same picture
// in bands of rows, each request within the core protocol's 256 KB, costs it about 0.4 ms
// (docs/viewer.md).
//
// Each frame slot has its own image and host buffer: the frame draws into the image and copies it
// to the buffer, and when the slot's next frame begins (the CommandRing has waited for the slot's
// fence) the buffer goes to the window, one frame later than a swapchain shows it. Sent as soon as
// the frame is drawn, the picture would reach the X server while the device, the same CPU cores,
// draws the next frame, which made moving frames slower.
#include <memory>
#include <optional>
#include <vector>

#include "aerial/vk/present_target.h"

struct GLFWwindow;

namespace aerial::viewer {

class X11Presenter : public vk::PresentTarget {
 public:
  // Whether the window is an X11 window whose visual takes 32-bit BGRX texels, as this presenter
  // sends them; the reason when it is not.
  static std::optional<std::string> Unsupported(GLFWwindow* window);

  X11Presenter(const vk::Context& context, GLFWwindow* window, ::vk::Extent2D extent, uint32_t frames_in_flight);
  ~X11Presenter() override;

  void Recreate(::vk::Extent2D wanted) override;
  // Shows the slot's last frame, which the ring has waited for.
  bool Acquire(const vk::CommandRing& ring) override;
  // The draw, then the copy of the image into the slot's host buffer.
  void RecordDraw(const vk::CommandBuffer& cmd, const vk::Recorder& draw) const override;
  void RecordCopyToBuffer(const vk::CommandBuffer& cmd, ::vk::Buffer buffer) const override;
  bool SubmitAndPresent(vk::CommandRing& ring) override;
  // Oldest first.
  void ShowSubmitted() override;

  bool can_copy_out() const override { return true; }
  ::vk::Extent2D extent() const override { return extent_; }
  ::vk::Format format() const override { return kFormat; }
  uint32_t min_image_count() const override { return uint32_t(slots_.size()); }
  uint32_t image_count() const override { return uint32_t(slots_.size()); }
  ::vk::RenderPass render_pass() const override { return *render_pass_; }

 private:
  // Byte for byte what a 24-bit TrueColor X visual with 32 bits per pixel and the server's byte
  // order LSBFirst holds: blue, green, red, unused.
  static constexpr ::vk::Format kFormat = ::vk::Format::eB8G8R8A8Srgb;
  struct Slot {
    std::unique_ptr<vk::Image> image;
    ::vk::raii::Framebuffer framebuffer{nullptr};
    std::unique_ptr<vk::Buffer> texels;
    bool submitted = false;  // holds a frame not shown yet
  };
  void Create();
  void Show(Slot& slot);

  const vk::Context& context_;
  struct X11;  // the display, window and graphics context (Xlib), kept out of this header
  std::unique_ptr<X11> x11_;
  ::vk::Extent2D extent_;
  ::vk::raii::RenderPass render_pass_;
  std::vector<Slot> slots_;
  uint32_t slot_ = 0;
};

}  // namespace aerial::viewer
