#include "aerial/viewer/imgui_layer.h"

#include <cmath>

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include "aerial/error.h"

namespace aerial::viewer {
namespace {

void CheckImGuiVulkanResult(VkResult result) {
  if (result < 0)
    throw Error("Dear ImGui Vulkan backend", ::vk::to_string(::vk::Result(result)), "VK_SUCCESS");
}

// Dear ImGui's colors are sRGB-encoded values; an _SRGB target encodes what it is given, so they
// are decoded first (IEC 61966-2-1) to look the same.
void LinearizeStyleColors(ImGuiStyle& style) {
  auto decode = [](float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
  };
  for (ImVec4& color : style.Colors) {
    color.x = decode(color.x);
    color.y = decode(color.y);
    color.z = decode(color.z);
  }
}

}  // namespace

ImGuiLayer::ImGuiLayer(const vk::Context& context, GLFWwindow* window,
                       const vk::PresentTarget& target) {
  // The backend allocates one descriptor set: the font texture.
  ::vk::DescriptorPoolSize size{.type = ::vk::DescriptorType::eCombinedImageSampler, .descriptorCount = 4};
  pool_ = ::vk::raii::DescriptorPool(
      context.device(),
      ::vk::DescriptorPoolCreateInfo{.flags = ::vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                     .maxSets = 4,
                                     .poolSizeCount = 1,
                                     .pPoolSizes = &size});
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the working directory
  ImGui::StyleColorsDark();
  if (vk::EncodesSrgb(target.format())) LinearizeStyleColors(ImGui::GetStyle());
  ImGui_ImplGlfw_InitForVulkan(window, true);
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = *context.instance();
  info.PhysicalDevice = *context.physical_device();
  info.Device = *context.device();
  info.QueueFamily = context.queue_family();
  info.Queue = *context.queue();
  info.DescriptorPool = *pool_;
  info.MinImageCount = target.min_image_count();
  info.ImageCount = target.image_count();
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = &CheckImGuiVulkanResult;
  ImGui_ImplVulkan_Init(&info, target.render_pass());
  context.Submit([](const vk::CommandBuffer& cmd) { ImGui_ImplVulkan_CreateFontsTexture(*cmd); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

ImGuiLayer::~ImGuiLayer() {
  ImGui_ImplVulkan_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ImGuiLayer::OnTargetRecreated(const vk::PresentTarget& target) {
  ImGui_ImplVulkan_SetMinImageCount(target.min_image_count());
}

void ImGuiLayer::NewFrame() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ImGuiLayer::EndFrame() { ImGui::Render(); }

void ImGuiLayer::Record(const vk::CommandBuffer& cmd) {
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), *cmd);
}

bool ImGuiLayer::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wants_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace aerial::viewer
