#pragma once
// Dear ImGui on the viewer's window: the context, the GLFW and Vulkan backends (Debian's
// libimgui-dev 1.86, whose libimgui.a holds both), and the draw into the window target's overlay
// render pass. Panels are built between NewFrame and Record with plain ImGui calls.
#include "aerial/vk/present_target.h"

struct GLFWwindow;

namespace aerial::viewer {

class ImGuiLayer {
 public:
  // Install after the window's own callbacks: the GLFW backend chains to them.
  ImGuiLayer(const vk::Context& context, GLFWwindow* window, const vk::PresentTarget& target);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  void OnTargetRecreated(const vk::PresentTarget& target);
  void NewFrame();
  // Ends the frame (ImGui::Render): its draw data is then ready, whether or not it gets drawn.
  void EndFrame();
  // Records the ended frame's draw; call inside the window target's render pass.
  void Record(const vk::CommandBuffer& cmd);

  // True while the pointer is over a panel or a widget has the keyboard: the 3D view ignores them.
  bool wants_mouse() const;
  bool wants_keyboard() const;

 private:
  ::vk::raii::DescriptorPool pool_{nullptr};
};

}  // namespace aerial::viewer
