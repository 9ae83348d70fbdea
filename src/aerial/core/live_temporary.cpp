#include "aerial/core/live_temporary.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <mutex>

namespace aerial {
namespace {

// A slot is free, being filled by its writer's thread, or live (the handler may unlink it).
enum SlotState : int { kFree, kFilling, kLive };

struct Slot {
  std::atomic<int> state{kFree};
  int directory_fd = -1;
  int unlink_flags = 0;  // AT_REMOVEDIR for a directory
  uint64_t order = 0;    // registration order: the newest entry is removed first
  char name[256];
};

constexpr size_t kSlots = 32;
std::array<Slot, kSlots> slots;
std::atomic<uint64_t> next_order{1};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the states");

void RemoveLiveTemporaries(int signal) {
  // Newest first: a temporary before the directory made for it, a directory before its parent.
  bool removed[kSlots] = {};
  for (size_t round = 0; round < kSlots; ++round) {
    int newest = -1;
    for (int i = 0; i < int(kSlots); ++i) {
      if (removed[i] || slots[i].state.load(std::memory_order_acquire) != kLive) continue;
      if (newest < 0 || slots[i].order > slots[newest].order) newest = i;
    }
    if (newest < 0) break;
    removed[newest] = true;
    ::unlinkat(slots[newest].directory_fd, slots[newest].name, slots[newest].unlink_flags);
  }
  // SA_RESETHAND restored the default action: raised again, the signal (blocked while this handler
  // runs) is delivered as it returns and ends the program as it would have.
  ::raise(signal);
}

void InstallHandlers() {
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction current {};
    if (::sigaction(signal, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
    struct sigaction handler {};
    handler.sa_handler = RemoveLiveTemporaries;
    handler.sa_flags = SA_RESETHAND;
    sigemptyset(&handler.sa_mask);
    ::sigaction(signal, &handler, nullptr);
  }
  struct sigaction current {};
  if (::sigaction(SIGXFSZ, nullptr, &current) == 0 && current.sa_handler == SIG_DFL)
    ::signal(SIGXFSZ, SIG_IGN);
}

}  // namespace

LiveTemporary::LiveTemporary(int directory_fd, const std::string& name, bool is_directory) {
  static std::once_flag installed;
  std::call_once(installed, InstallHandlers);
  if (name.size() >= sizeof(Slot::name)) return;
  for (int i = 0; i < int(kSlots); ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) continue;
    std::memcpy(slots[i].name, name.c_str(), name.size() + 1);
    slots[i].directory_fd = directory_fd;
    slots[i].unlink_flags = is_directory ? AT_REMOVEDIR : 0;
    slots[i].order = next_order.fetch_add(1);
    slots[i].state.store(kLive, std::memory_order_release);
    slot_ = i;
    return;
  }
}

LiveTemporary::~LiveTemporary() {
  if (slot_ >= 0) slots[slot_].state.store(kFree, std::memory_order_release);
}

}  // namespace aerial
