#pragma once
// The GLFW side of the viewer: the library's lifetime, the window and its Vulkan surface, and the
// keys pressed between two frames. Only src/aerial/viewer/ sees GLFW.
#include <string>
#include <vector>

#include "aerial/vk/context.h"

struct GLFWwindow;

namespace aerial::viewer {

// glfwInit and glfwTerminate. Throws Error when there is no display (run under xvfb-run on a
// machine without one) or when GLFW finds no Vulkan loader.
class GlfwSession {
 public:
  GlfwSession();
  ~GlfwSession();
  GlfwSession(const GlfwSession&) = delete;
  GlfwSession& operator=(const GlfwSession&) = delete;

  // Adds what a device needs to present to GLFW windows: the instance extensions and the
  // queue-family presentation check.
  static void AddWindowSupport(vk::ContextCreateInfo& info);
};

class Window {
 public:
  // A resizable window with no client API (Vulkan draws into it) and its surface.
  Window(const vk::Context& context, int width, int height, const std::string& title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  ::vk::SurfaceKHR surface() const { return *surface_; }
  // In pixels; 0x0 while minimized.
  ::vk::Extent2D framebuffer_extent() const;
  bool should_close() const;
  // GLFW key codes pressed since the last call, in order. Collected by a key callback, so a tap
  // shorter than a frame is not lost (polling key state would miss it at a few frames a second).
  std::vector<int> TakeKeyPresses();

 private:
  static void OnKey(GLFWwindow* window, int key, int scancode, int action, int mods);

  GLFWwindow* window_ = nullptr;
  ::vk::raii::SurfaceKHR surface_{nullptr};
  std::vector<int> key_presses_;
};

}  // namespace aerial::viewer
