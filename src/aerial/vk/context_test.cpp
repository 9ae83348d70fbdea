#include "aerial/vk/context.h"

#include <gtest/gtest.h>

#include <cstring>

#include "aerial/error.h"
#include "aerial/vk/resources.h"

namespace aerial::vk {
namespace {

// A context on a device it did not make (here another context's, as a client's renderer would
// hand its own over) works on it and, when it goes, leaves the device and the instance to their
// owner, which keeps working; the validation layers see nothing wrong on either side.
TEST(DeviceHandoff, WorksOnTheCallersDeviceAndLeavesItAlive) {
  Context owner({.validation = true});
  const int before = Context::ValidationMessageCount();
  {
    Context adopted(owner.Handoff());
    EXPECT_FALSE(adopted.validation_enabled()) << "validation is the caller's instance's";
    EXPECT_EQ(adopted.device_name(), owner.device_name());
    Buffer buffer(adopted, BufferCreateInfo{.size = 4, .usage = ::vk::BufferUsageFlagBits::eTransferDst,
                                            .host_visible = true});
    adopted.Submit([&](const CommandBuffer& cmd) { cmd.fillBuffer(buffer.handle(), 0, 4, 0x2a2a2a2au); });
    uint32_t value = 0;
    std::memcpy(&value, buffer.mapped(), 4);
    EXPECT_EQ(value, 0x2a2a2a2au);
  }
  Buffer after(owner, BufferCreateInfo{.size = 4, .usage = ::vk::BufferUsageFlagBits::eTransferDst,
                                       .host_visible = true});
  owner.Submit([&](const CommandBuffer& cmd) { cmd.fillBuffer(after.handle(), 0, 4, 7u); });
  uint32_t value = 0;
  std::memcpy(&value, after.mapped(), 4);
  EXPECT_EQ(value, 7u) << "the owner's device still works";
  EXPECT_EQ(Context::ValidationMessageCount(), before);
}

// Handles that cannot work are refused with the field and the value named.
TEST(DeviceHandoff, NullHandlesAndAWrongQueueFamilyAreRefused) {
  try {
    Context adopted(DeviceHandoff{});
    FAIL() << "null handles were accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "external device");
    EXPECT_EQ(e.value(), "a null handle");
  }
  Context owner;
  DeviceHandoff wrong = owner.Handoff();
  wrong.queue_family = 99;
  try {
    Context adopted(wrong);
    FAIL() << "queue family 99 was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "device queue");
    EXPECT_NE(e.value().find("family 99"), std::string::npos) << e.value();
  }
}

}  // namespace
}  // namespace aerial::vk
