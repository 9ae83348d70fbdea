// aerial::Device (include/aerial/device.h) over the Vulkan layer's Context.
#include "aerial/api/impl.h"

namespace aerial {

Device::Device(const DeviceOptions& options)
    : impl_(new Impl{std::make_unique<vk::Context>(
          vk::ContextCreateInfo{.device_name = options.device_name, .validation = options.validation})}) {}

Device::Device(const DeviceHandoff& handoff) : impl_(new Impl{std::make_unique<vk::Context>(handoff)}) {}

Device::~Device() = default;
Device::Device(Device&&) noexcept = default;
Device& Device::operator=(Device&&) noexcept = default;

std::string Device::name() const { return impl_->context->device_name(); }
bool Device::validation_enabled() const { return impl_->context->validation_enabled(); }
uint64_t Device::largest_heap_bytes() const { return impl_->context->largest_heap_bytes(); }
int Device::ValidationMessageCount() { return vk::Context::ValidationMessageCount(); }

}  // namespace aerial
