#include "aerial/viewer/window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "aerial/error.h"
#include "aerial/vk/loader_files.h"

namespace aerial::viewer {
namespace {

std::string g_last_glfw_error;

void OnGlfwError(int code, const char* description) {
  g_last_glfw_error = std::string(description) + " (GLFW error " + std::to_string(code) + ")";
}

}  // namespace

GlfwSession::GlfwSession() {
  vk::CheckLoaderFiles();  // glfwVulkanSupported starts the Vulkan loader
  glfwSetErrorCallback(&OnGlfwError);
  if (!glfwInit())
    throw Error("window system", g_last_glfw_error, "a display (set DISPLAY, or run under xvfb-run)");
  if (!glfwVulkanSupported()) {
    glfwTerminate();
    throw Error("window system", "GLFW without Vulkan", "a Vulkan loader GLFW can find");
  }
}

GlfwSession::~GlfwSession() { glfwTerminate(); }

void GlfwSession::AddWindowSupport(vk::ContextCreateInfo& info) {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) throw Error("window system", g_last_glfw_error, "Vulkan surface extensions");
  info.window_extensions.assign(names, names + count);
  info.present_support = [](::vk::Instance instance, ::vk::PhysicalDevice device, uint32_t family) {
    return glfwGetPhysicalDevicePresentationSupport(instance, device, family) == GLFW_TRUE;
  };
}

Window::Window(const vk::Context& context, int width, int height, const std::string& title) {
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) throw Error("window", std::to_string(width) + "x" + std::to_string(height), g_last_glfw_error);
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  VkResult result = glfwCreateWindowSurface(*context.instance(), window_, nullptr, &surface);
  if (result != VK_SUCCESS) {
    glfwDestroyWindow(window_);
    throw Error("window surface", ::vk::to_string(::vk::Result(result)), g_last_glfw_error);
  }
  surface_ = ::vk::raii::SurfaceKHR(context.instance(), surface);
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, &Window::OnKey);
}

Window::~Window() {
  surface_.clear();  // before the window it belongs to
  glfwDestroyWindow(window_);
}

::vk::Extent2D Window::framebuffer_extent() const {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  return {uint32_t(std::max(width, 0)), uint32_t(std::max(height, 0))};
}

bool Window::should_close() const { return glfwWindowShouldClose(window_); }

std::vector<int> Window::TakeKeyPresses() {
  std::vector<int> presses;
  presses.swap(key_presses_);
  return presses;
}

void Window::OnKey(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS) return;
  static_cast<Window*>(glfwGetWindowUserPointer(window))->key_presses_.push_back(key);
}

}  // namespace aerial::viewer
