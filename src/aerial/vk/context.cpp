#include "aerial/vk/context.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "aerial/error.h"
#include "aerial/vk/loader_files.h"
#include "aerial/vk/pipeline_cache.h"

namespace aerial::vk {
namespace {

std::atomic<int> g_validation_messages{0};

VKAPI_ATTR VkBool32 VKAPI_CALL OnValidationMessage(
    VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  ++g_validation_messages;
  std::fprintf(stderr, "vulkan validation: %s\n", data->pMessage);
  return VK_FALSE;
}

bool EnvironmentFlag(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr && std::string(value) != "0" && std::string(value) != "";
}

std::string Lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

// A real GPU first: discrete, then integrated, then virtual, then CPU (lavapipe).
int DeviceRank(::vk::PhysicalDeviceType type) {
  switch (type) {
    case ::vk::PhysicalDeviceType::eDiscreteGpu: return 0;
    case ::vk::PhysicalDeviceType::eIntegratedGpu: return 1;
    case ::vk::PhysicalDeviceType::eVirtualGpu: return 2;
    case ::vk::PhysicalDeviceType::eCpu: return 3;
    default: return 4;
  }
}

// The Vulkan loader found no driver (ICD): it answers vkCreateInstance with
// ErrorIncompatibleDriver, or lists no device.
[[noreturn]] void ThrowNoDriver(const std::string& symptom) {
  throw Error("Vulkan driver", "none found (" + symptom + ")",
              "an installed Vulkan driver: on Debian, `apt install mesa-vulkan-drivers` gives "
              "lavapipe (any CPU), or install your GPU's driver; if VK_ICD_FILENAMES or "
              "VK_DRIVER_FILES is set, it must name the driver's JSON manifest");
}

bool QueueFamilySuitable(const ::vk::QueueFamilyProperties& family) {
  auto wanted = ::vk::QueueFlagBits::eCompute | ::vk::QueueFlagBits::eGraphics;
  return (family.queueFlags & wanted) == wanted && family.timestampValidBits > 0;
}

bool HasLayer(const ::vk::raii::Context& loader, const char* name) {
  for (const auto& layer : loader.enumerateInstanceLayerProperties())
    if (std::string(layer.layerName.data()) == name) return true;
  return false;
}

}  // namespace

int Context::ValidationMessageCount() { return g_validation_messages.load(); }

Context::Context(const ContextCreateInfo& info) : pipelines_(std::make_unique<PipelineCache>()) {
  CheckLoaderFiles();  // before the loader opens them
  validation_ = info.validation || EnvironmentFlag("AERIAL_VALIDATION");
  const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
  if (validation_ && !HasLayer(loader_, kValidationLayer))
    throw Error("validation layers", kValidationLayer, "installed (package vulkan-validationlayers)");

  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  for (const auto& e : info.window_extensions) extensions.push_back(e.c_str());
  if (validation_) {
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  // Vulkan 1.3 for dynamic rendering; lavapipe (Mesa 22.3) and current GPU drivers have it.
  ::vk::ApplicationInfo app{.pApplicationName = "aerial", .apiVersion = VK_API_VERSION_1_3};
  try {
    instance_ = ::vk::raii::Instance(
        loader_, ::vk::InstanceCreateInfo{.pApplicationInfo = &app,
                                          .enabledLayerCount = uint32_t(layers.size()),
                                          .ppEnabledLayerNames = layers.data(),
                                          .enabledExtensionCount = uint32_t(extensions.size()),
                                          .ppEnabledExtensionNames = extensions.data()});
  } catch (const ::vk::IncompatibleDriverError& e) {
    ThrowNoDriver(e.what());
  } catch (const ::vk::OutOfHostMemoryError& e) {
    BlameDriverManifests(e.what());
    throw;
  }
  // Performance hints (e.g. GENERAL layouts on copies, which aerial uses on purpose) are not
  // validation errors; warnings and errors of the general and validation kinds all count.
  if (validation_) {
    using Severity = ::vk::DebugUtilsMessageSeverityFlagBitsEXT;
    using Type = ::vk::DebugUtilsMessageTypeFlagBitsEXT;
    messenger_.emplace(instance_, ::vk::DebugUtilsMessengerCreateInfoEXT{
                                      .messageSeverity = Severity::eWarning | Severity::eError,
                                      .messageType = Type::eGeneral | Type::eValidation,
                                      .pfnUserCallback = &OnValidationMessage});
  }

  // Device choice: a name given on the command line or in AERIAL_DEVICE, else the best rank.
  std::string wanted = info.device_name;
  if (wanted.empty() && std::getenv("AERIAL_DEVICE")) wanted = std::getenv("AERIAL_DEVICE");
  ::vk::raii::PhysicalDevices devices(instance_);
  if (devices.empty()) ThrowNoDriver("the Vulkan loader lists no device");
  std::string available;
  int best_rank = 1 << 30;
  for (auto& candidate : devices) {
    auto properties = candidate.getProperties();
    std::string name = properties.deviceName.data();
    available += (available.empty() ? "" : ", ") + name;
    bool matches = wanted.empty() || Lowercase(name).find(Lowercase(wanted)) != std::string::npos;
    int rank = DeviceRank(properties.deviceType);
    if (matches && rank < best_rank) {
      best_rank = rank;
      physical_device_ = std::move(candidate);
    }
  }
  if (!*physical_device_)
    throw Error("device", wanted.empty() ? "(any)" : wanted, "one of: " + available);
  timestamp_period_ns_ = physical_device_.getProperties().limits.timestampPeriod;

  queue_family_ = 0;
  auto families = physical_device_.getQueueFamilyProperties();
  auto can_present = [&](uint32_t index) {
    return !info.present_support || info.present_support(*instance_, *physical_device_, index);
  };
  while (queue_family_ < families.size() &&
         !(QueueFamilySuitable(families[queue_family_]) && can_present(queue_family_)))
    ++queue_family_;
  CheckQueueFamily(info.present_support ? std::function<bool(uint32_t)>(can_present) : nullptr);

  float priority = 1.0f;
  ::vk::DeviceQueueCreateInfo queue_info{
      .queueFamilyIndex = queue_family_, .queueCount = 1, .pQueuePriorities = &priority};
  std::vector<const char*> device_extensions(kRequiredDeviceExtensions.begin(), kRequiredDeviceExtensions.end());
  if (!info.window_extensions.empty()) device_extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  RequiredDeviceFeatures features;
  // Optional: fragment-shader counts per pass (GpuTimer), for the bench.
  pipeline_statistics_ = physical_device_.getFeatures().pipelineStatisticsQuery;
  features.core.pipelineStatisticsQuery = pipeline_statistics_ ? VK_TRUE : VK_FALSE;
  device_ = ::vk::raii::Device(
      physical_device_, ::vk::DeviceCreateInfo{.pNext = features.Chain(),
                                               .queueCreateInfoCount = 1,
                                               .pQueueCreateInfos = &queue_info,
                                               .enabledExtensionCount = uint32_t(device_extensions.size()),
                                               .ppEnabledExtensionNames = device_extensions.data(),
                                               .pEnabledFeatures = reinterpret_cast<const ::vk::PhysicalDeviceFeatures*>(&features.core)});
  queue_ = device_.getQueue(queue_family_, 0);
  CreateSubmitObjects();
}

Context::Context(const DeviceHandoff& external)
    : external_(true), pipeline_statistics_(external.pipeline_statistics),
      pipelines_(std::make_unique<PipelineCache>()) {
  if (!external.instance || !external.physical_device || !external.device)
    throw Error("external device", "a null handle", "the caller's instance, physical device and device");
  instance_ = ::vk::raii::Instance(loader_, external.instance);
  // From here on a failure must hand the caller's handles back: the destructor does not run
  // for a constructor that throws, and the members' own would destroy them.
  try {
    physical_device_ = ::vk::raii::PhysicalDevice(instance_, external.physical_device);
    ::vk::PhysicalDeviceProperties properties = physical_device_.getProperties();
    timestamp_period_ns_ = properties.limits.timestampPeriod;
    if (properties.apiVersion < VK_API_VERSION_1_3) {
      throw Error("external device's Vulkan version",
                  std::to_string(VK_API_VERSION_MAJOR(properties.apiVersion)) + "." +
                      std::to_string(VK_API_VERSION_MINOR(properties.apiVersion)),
                  "1.3 or later");
    }
    auto supported = physical_device_.enumerateDeviceExtensionProperties();
    for (const char* wanted : kRequiredDeviceExtensions) {
      bool found = std::any_of(supported.begin(), supported.end(), [&](const ::vk::ExtensionProperties& e) {
        return std::string(e.extensionName.data()) == wanted;
      });
      if (!found) throw Error("external device's extensions", device_name(), std::string("support for ") + wanted);
    }
    queue_family_ = external.queue_family;
    CheckQueueFamily(nullptr);
    device_ = ::vk::raii::Device(physical_device_, external.device);
    queue_ = device_.getQueue(queue_family_, external.queue_index);
    CreateSubmitObjects();
  } catch (...) {
    ReleaseCallersHandles();
    throw;
  }
}

Context::~Context() {
  if (external_) ReleaseCallersHandles();
}

// What aerial made on the caller's device goes; the device and the instance stay the caller's.
void Context::ReleaseCallersHandles() {
  pipelines_->Clear();
  submit_done_.clear();
  submit_buffer_.clear();
  command_pool_.clear();
  queue_.clear();
  device_.release();
  instance_.release();
}

// Throws unless queue_family_ exists and can draw, compute, time and (when asked) present.
void Context::CheckQueueFamily(const std::function<bool(uint32_t)>& can_present) const {
  auto families = physical_device_.getQueueFamilyProperties();
  if (queue_family_ < families.size() && QueueFamilySuitable(families[queue_family_]) &&
      (!can_present || can_present(queue_family_)))
    return;
  throw Error("device queue", device_name() + ", family " + std::to_string(queue_family_),
              std::string("a graphics+compute queue with timestamps") +
                  (can_present ? " that can present to the window" : ""));
}

void Context::CreateSubmitObjects() {
  command_pool_ = ::vk::raii::CommandPool(
      device_, ::vk::CommandPoolCreateInfo{
                   .flags = ::vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                   .queueFamilyIndex = queue_family_});
  submit_buffer_ = std::move(::vk::raii::CommandBuffers(
      device_, ::vk::CommandBufferAllocateInfo{.commandPool = *command_pool_,
                                               .level = ::vk::CommandBufferLevel::ePrimary,
                                               .commandBufferCount = 1})
                                 .front());
  submit_done_ = ::vk::raii::Fence(device_, ::vk::FenceCreateInfo{});
}

DeviceHandoff Context::Handoff() const {
  return {.instance = *instance_, .physical_device = *physical_device_, .device = *device_, .queue_family = queue_family_,
          .pipeline_statistics = pipeline_statistics_};
}

bool Context::cpu_device() const {
  return physical_device_.getProperties().deviceType == ::vk::PhysicalDeviceType::eCpu;
}

std::string Context::device_name() const {
  return physical_device_.getProperties().deviceName.data();
}

void Context::Submit(const std::function<void(const CommandBuffer&)>& record) const {
  const auto& cmd = submit_buffer_;
  cmd.reset();
  cmd.begin(::vk::CommandBufferBeginInfo{.flags = ::vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
  record(cmd);
  cmd.end();
  device_.resetFences(*submit_done_);
  ::vk::CommandBuffer raw = *cmd;
  queue_.submit(::vk::SubmitInfo{.commandBufferCount = 1, .pCommandBuffers = &raw}, *submit_done_);
  if (device_.waitForFences(*submit_done_, VK_TRUE, UINT64_MAX) != ::vk::Result::eSuccess)
    throw Error("vkWaitForFences", "timeout", "completion");
}

uint64_t Context::largest_heap_bytes() const {
  auto memory = physical_device_.getMemoryProperties();
  uint64_t largest = 0;
  for (uint32_t i = 0; i < memory.memoryHeapCount; ++i) {
    if (memory.memoryHeaps[i].flags & ::vk::MemoryHeapFlagBits::eDeviceLocal)
      largest = std::max<uint64_t>(largest, memory.memoryHeaps[i].size);
  }
  return largest;
}

uint32_t Context::FindMemoryType(uint32_t type_bits, ::vk::MemoryPropertyFlags properties) const {
  auto memory = physical_device_.getMemoryProperties();
  for (uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    if ((type_bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & properties) == properties)
      return i;
  }
  throw Error("memory type", std::to_string(type_bits), "a type with the requested properties");
}

}  // namespace aerial::vk
