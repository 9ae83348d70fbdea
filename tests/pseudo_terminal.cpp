#include "pseudo_terminal.h"

#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <unistd.h>

namespace aerial::testing {

PseudoTerminal::PseudoTerminal() {
  master_ = ::posix_openpt(O_RDWR | O_NOCTTY);
  if (master_ < 0) return;
  if (::grantpt(master_) == 0 && ::unlockpt(master_) == 0) terminal_ = std::fopen(::ptsname(master_), "w");
  if (terminal_) ::fcntl(master_, F_SETFL, O_NONBLOCK);
}

PseudoTerminal::~PseudoTerminal() {
  if (terminal_) std::fclose(terminal_);
  if (master_ >= 0) ::close(master_);
}

std::string PseudoTerminal::ReadUntil(std::string_view until) {
  std::fflush(terminal_);
  std::string text;
  for (int waited_ms = 0; text.find(until) == std::string::npos && waited_ms < 5000; waited_ms += 50) {
    pollfd ready{.fd = master_, .events = POLLIN, .revents = 0};
    if (::poll(&ready, 1, 50) <= 0) continue;
    char buffer[512];
    ssize_t got = ::read(master_, buffer, sizeof buffer);
    if (got > 0) text.append(buffer, static_cast<size_t>(got));
  }
  return text;
}

}  // namespace aerial::testing
