#include "aerial/viewer/x11_presenter.h"

#include <algorithm>

#include "aerial/error.h"
#include "aerial/vk/render_pass.h"

// Xlib last: its macros (None, Bool, Status, Success) would rename what the headers above declare.
#include <X11/Xutil.h>

// GLFW's X11 native access (GLFW/glfw3native.h, which also includes Xrandr's headers for the
// monitor functions this file does not use).
extern "C" {
Display* glfwGetX11Display(void);
Window glfwGetX11Window(GLFWwindow* window);
}

namespace aerial::viewer {
namespace {

// Rows per PutImage request: each request within the core protocol's 65535 four-byte units, so
// that the server reads it into its usual request buffer (see the header).
int RowsPerRequest(uint32_t width) {
  constexpr size_t kRequestBytes = 65535 * 4 - 64;  // less the request's header
  return int(std::max<size_t>(1, kRequestBytes / (size_t(width) * 4)));
}

int BitsPerPixel(Display* display, int depth) {
  int count = 0;
  XPixmapFormatValues* formats = XListPixmapFormats(display, &count);
  int bits = 0;
  for (int i = 0; i < count; ++i)
    if (formats[i].depth == depth) bits = formats[i].bits_per_pixel;
  if (formats) XFree(formats);
  return bits;
}

}  // namespace

struct X11Presenter::X11 {
  Display* display;
  Window window;
  GC gc;
  int depth;
};

std::optional<std::string> X11Presenter::Unsupported(GLFWwindow* window) {
  Display* display = glfwGetX11Display();
  Window x_window = display ? glfwGetX11Window(window) : 0;
  if (!x_window) return "not an X11 window";
  XWindowAttributes attributes;
  if (!XGetWindowAttributes(display, x_window, &attributes)) return "its attributes cannot be read";
  const Visual* v = attributes.visual;
  if (v->c_class != TrueColor || v->red_mask != 0xff0000 || v->green_mask != 0xff00 || v->blue_mask != 0xff)
    return "its visual is not 8-bit BGR TrueColor";
  if (BitsPerPixel(display, attributes.depth) != 32) return "its pixels are not 32 bits";
  if (ImageByteOrder(display) != LSBFirst) return "the server's byte order is not LSBFirst";
  return std::nullopt;
}

X11Presenter::X11Presenter(const vk::Context& context, GLFWwindow* window, ::vk::Extent2D extent,
                           uint32_t frames_in_flight)
    : context_(context),
      extent_(extent),
      render_pass_(vk::CreateColorRenderPass(context, kFormat, ::vk::ImageLayout::eGeneral)),
      slots_(frames_in_flight) {
  if (std::optional<std::string> reason = Unsupported(window))
    throw Error("--present", "x11", "an X11 window whose visual takes BGRX texels (" + *reason + ")");
  Display* display = glfwGetX11Display();
  Window x_window = glfwGetX11Window(window);
  XWindowAttributes attributes;
  XGetWindowAttributes(display, x_window, &attributes);
  x11_ = std::make_unique<X11>(X11{display, x_window, XCreateGC(display, x_window, 0, nullptr), attributes.depth});
  Create();
}

X11Presenter::~X11Presenter() {
  context_.device().waitIdle();
  XFreeGC(x11_->display, x11_->gc);
}

void X11Presenter::Recreate(::vk::Extent2D wanted) {
  context_.device().waitIdle();
  extent_ = wanted;
  Create();
}

void X11Presenter::Create() {
  if (extent_.width == 0 || extent_.height == 0)
    throw Error("window extent", "0x0", "a window that is not minimized");
  for (Slot& slot : slots_) {
    slot.image = std::make_unique<vk::Image>(
        context_, vk::ImageCreateInfo{.extent = {extent_.width, extent_.height, 1},
                                      .format = kFormat,
                                      .usage = ::vk::ImageUsageFlagBits::eColorAttachment |
                                               ::vk::ImageUsageFlagBits::eTransferSrc});
    slot.framebuffer = vk::CreateFramebuffer(context_, *render_pass_, slot.image->view(), extent_);
    slot.texels = std::make_unique<vk::Buffer>(
        context_, vk::BufferCreateInfo{.size = 4ull * extent_.width * extent_.height,
                                       .usage = ::vk::BufferUsageFlagBits::eTransferDst,
                                       .host_visible = true});
    slot.submitted = false;
  }
}

bool X11Presenter::Acquire(const vk::CommandRing& ring) {
  slot_ = ring.slot();
  if (slots_[slot_].submitted) Show(slots_[slot_]);
  return true;
}

void X11Presenter::ShowSubmitted() {
  // Oldest first: the slot after the current one was submitted before it.
  for (size_t i = 1; i <= slots_.size(); ++i) {
    Slot& slot = slots_[(slot_ + i) % slots_.size()];
    if (slot.submitted) Show(slot);
  }
}

void X11Presenter::RecordDraw(const vk::CommandBuffer& cmd, const vk::Recorder& draw) const {
  const Slot& slot = slots_[slot_];
  vk::BeginRenderPass(cmd, *render_pass_, *slot.framebuffer, extent_);
  draw(cmd);
  cmd.endRenderPass();
  cmd.pipelineBarrier(::vk::PipelineStageFlagBits::eColorAttachmentOutput, ::vk::PipelineStageFlagBits::eTransfer, {},
                      ::vk::MemoryBarrier{.srcAccessMask = ::vk::AccessFlagBits::eColorAttachmentWrite,
                                          .dstAccessMask = ::vk::AccessFlagBits::eTransferRead},
                      {}, {});
  RecordCopyToBuffer(cmd, slot.texels->handle());
}

void X11Presenter::RecordCopyToBuffer(const vk::CommandBuffer& cmd, ::vk::Buffer buffer) const {
  vk::RecordCopyToHostBuffer(cmd, slots_[slot_].image->handle(), ::vk::ImageLayout::eGeneral, extent_, buffer);
}

bool X11Presenter::SubmitAndPresent(vk::CommandRing& ring) {
  ring.Submit();
  slots_[slot_].submitted = true;
  return true;
}

void X11Presenter::Show(Slot& slot) {
  XImage image{};
  image.width = int(extent_.width);
  image.height = int(extent_.height);
  image.format = ZPixmap;
  image.data = reinterpret_cast<char*>(slot.texels->mapped());
  image.byte_order = LSBFirst;
  image.bitmap_unit = 32;
  image.bitmap_bit_order = LSBFirst;
  image.bitmap_pad = 32;
  image.depth = x11_->depth;
  image.bytes_per_line = int(4 * extent_.width);
  image.bits_per_pixel = 32;
  image.red_mask = 0xff0000;
  image.green_mask = 0xff00;
  image.blue_mask = 0xff;
  XInitImage(&image);
  const int rows = RowsPerRequest(extent_.width);
  for (int y = 0; y < image.height; y += rows)
    XPutImage(x11_->display, x11_->window, x11_->gc, &image, 0, y, 0, y, image.width, std::min(rows, image.height - y));
  XFlush(x11_->display);
  slot.submitted = false;
}

}  // namespace aerial::viewer
