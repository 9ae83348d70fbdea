#include "aerial/core/live_temporary.h"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>
#include <mutex>

namespace aerial {
namespace {

// A slot is free, being filled by its writer's thread, or live (the handler may unlink it).
enum SlotState : int { kFree, kFilling, kLive };

struct Slot {
  std::atomic<int> state{kFree};
  char path[4096];
};

std::array<Slot, 32> slots;
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the states");

void RemoveLiveTemporaries(int signal) {
  for (Slot& slot : slots)
    if (slot.state.load(std::memory_order_acquire) == kLive) ::unlink(slot.path);
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
}

}  // namespace

LiveTemporary::LiveTemporary(const std::filesystem::path& path) {
  static std::once_flag installed;
  std::call_once(installed, InstallHandlers);
  const std::string& text = path.native();
  if (text.size() >= sizeof(Slot::path)) return;
  for (int i = 0; i < int(slots.size()); ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) continue;
    std::memcpy(slots[i].path, text.c_str(), text.size() + 1);
    slots[i].state.store(kLive, std::memory_order_release);
    slot_ = i;
    return;
  }
}

LiveTemporary::~LiveTemporary() {
  if (slot_ >= 0) slots[slot_].state.store(kFree, std::memory_order_release);
}

}  // namespace aerial
