#pragma once
// A pseudo-terminal standing in for the user's terminal, for what is drawn only on one (progress
// bars).
#include <cstdio>
#include <string>
#include <string_view>

namespace aerial::testing {

class PseudoTerminal {
 public:
  PseudoTerminal();  // available() is false where none can be opened
  ~PseudoTerminal();
  PseudoTerminal(const PseudoTerminal&) = delete;
  PseudoTerminal& operator=(const PseudoTerminal&) = delete;

  bool available() const { return terminal_ != nullptr; }
  std::FILE* file() const { return terminal_; }  // the terminal's side: isatty holds

  // What was written to file() until `until` has arrived, or what arrived within 5 s: the
  // pseudo-terminal hands written bytes to its reader asynchronously (a kernel work queue), so on
  // a loaded machine they may arrive late.
  std::string ReadUntil(std::string_view until);

 private:
  int master_ = -1;
  std::FILE* terminal_ = nullptr;
};

}  // namespace aerial::testing
