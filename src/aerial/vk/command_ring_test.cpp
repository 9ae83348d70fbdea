#include "aerial/vk/command_ring.h"

#include <gtest/gtest.h>

#include <cstring>

#include "aerial/vk/resources.h"

namespace aerial::vk {
namespace {

// Slots are used in turn, and a slot is begun again only after its previous frame finished: the
// buffer a frame filled holds that frame's value when the slot comes round again.
TEST(CommandRing, SlotsTakeTurnsAndWaitOnlyForTheirOwnFrame) {
  Context context({.validation = true});
  const int before = Context::ValidationMessageCount();
  {
    CommandRing ring(context, 2);
    std::vector<Buffer> buffers;
    for (int slot = 0; slot < 2; ++slot)
      buffers.emplace_back(context, BufferCreateInfo{.size = 4, .usage = ::vk::BufferUsageFlagBits::eTransferDst,
                                                     .host_visible = true});
    for (uint32_t frame = 0; frame < 6; ++frame) {
      const auto& cmd = ring.Begin();
      ASSERT_EQ(ring.slot(), frame % 2);
      if (frame >= 2) {
        uint32_t previous;
        std::memcpy(&previous, buffers[ring.slot()].mapped(), 4);
        EXPECT_EQ(previous, frame - 2) << "the slot's previous frame has finished";
      }
      cmd.fillBuffer(buffers[ring.slot()].handle(), 0, 4, frame);
      FullBarrier(cmd);
      ring.Submit();
    }
    ring.WaitAll();
  }
  EXPECT_EQ(Context::ValidationMessageCount(), before);
}

}  // namespace
}  // namespace aerial::vk
