#pragma once
// A private X server for tests that open windows in this process: Xvfb on a display number it
// picks itself (-displayfd), DISPLAY pointed at it while the object lives. Destroy every window
// (and terminate GLFW) before it.
#include <string>

#include <sys/types.h>

namespace aerial::testing {

// Why the tests that need an X server cannot run on this machine: "" when `program` (Xvfb, or
// xvfb-run for the command's tests) is on PATH, else "no X server: <program> is not on PATH", for
// GTEST_SKIP. CI installs it (tools/setup.sh), so there they run; a machine without one (a bare
// GPU node) says so instead of failing.
std::string MissingXServer(const std::string& program);

class XvfbDisplay {
 public:
  XvfbDisplay();
  ~XvfbDisplay();
  XvfbDisplay(const XvfbDisplay&) = delete;
  XvfbDisplay& operator=(const XvfbDisplay&) = delete;

  // ":N", or empty if Xvfb could not be started (error() says why).
  const std::string& display() const { return display_; }
  const std::string& error() const { return error_; }

 private:
  pid_t pid_ = -1;
  std::string display_, error_, previous_display_;
  bool had_display_ = false;
};

}  // namespace aerial::testing
