#include "gpu_fixture.h"

#include <map>
#include <memory>

namespace aerial::testing {

vk::Context& SharedContext() {
  static vk::Context context(vk::ContextCreateInfo{.validation = true});
  return context;
}

const AtmosphereTables& CachedTables(const PrecomputeOptions& options) {
  // The context first: statics are destroyed in reverse order of construction, and the tables
  // must go before their device.
  vk::Context& context = SharedContext();
  static std::map<uint64_t, LoadedTables> loaded;
  auto it = loaded.find(options.Hash());
  if (it == loaded.end()) {
    it = loaded.emplace(options.Hash(), LoadOrPrecompute(context, AtmosphereParameters::Earth(),
                                                         options, {}))
             .first;
  }
  return *it->second.tables;
}

const AtmosphereTables& FullTables(int orders, LutVariant variant) {
  PrecomputeOptions options = PrecomputeOptions::Default(variant);
  options.orders = orders;
  return CachedTables(options);
}

const AtmosphereTables& SmallTables(LutVariant variant) {
  return CachedTables(PrecomputeOptions::Small(variant));
}

const Device& SharedDevice() {
  static Device device(SharedContext().Handoff());
  return device;
}

const aerial::Tables& SmallPublicTables() {
  static aerial::Tables tables = aerial::Tables::LoadOrPrecompute(
      SharedDevice(), AtmosphereParameters::Earth(), PrecomputeOptions::Small());
  return tables;
}

vk::Image Upload(const ImageRgbF& image) {
  vk::Context& context = SharedContext();
  vk::Image gpu(context, {.extent = {uint32_t(image.width), uint32_t(image.height), 1}});
  vk::Buffer staging(context, {.size = gpu.byte_size(), .usage = ::vk::BufferUsageFlagBits::eTransferSrc,
                               .host_visible = true});
  staging.Write(std::as_bytes(std::span(image.rgba)));
  context.Submit([&](const auto& cmd) {
    gpu.InitializeLayout(cmd);
    gpu.CopyFromBuffer(cmd, staging);
    vk::FullBarrier(cmd);
  });
  return gpu;
}

std::vector<std::byte> ReadBack(const vk::Image& image) {
  return vk::ReadImageBytes(SharedContext(), image);
}

void GpuTest::SetUp() {
  SharedContext();
  validation_messages_before_ = vk::Context::ValidationMessageCount();
}

void GpuTest::TearDown() {
  EXPECT_EQ(vk::Context::ValidationMessageCount(), validation_messages_before_)
      << "the Vulkan validation layers reported messages during this test";
}

}  // namespace aerial::testing
