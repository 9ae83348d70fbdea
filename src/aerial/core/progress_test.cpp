#include "aerial/core/progress.h"

#include <fcntl.h>
#include <poll.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <cstdlib>
#include <memory>
#include <string>

namespace aerial {
namespace {

TEST(ProgressLine, ShowsBarCountAndLabel) {
  EXPECT_EQ(ProgressLine("precompute", 3, 9, "scattering density (order 2)", 9),
            "precompute [###......] 3/9 scattering density (order 2)");
  EXPECT_EQ(ProgressLine("", 0, 4, "", 4), "[....] 0/4");
  EXPECT_EQ(ProgressLine("t", 4, 4, "done", 4), "t [####] 4/4 done");
}

TEST(ProgressLine, ClampsOutOfRangeCounts) {
  EXPECT_EQ(ProgressLine("t", 7, 4, "", 4), "t [####] 4/4");
  EXPECT_EQ(ProgressLine("t", 1, 0, "", 4), "t [####] 1/0");  // no division by zero.
}

// Redirected output (a regular file here) must stay clean: no bar, no newline.
TEST(Progress, PrintsNothingWhenNotATerminal) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::tmpfile(), &std::fclose);
  ASSERT_NE(file, nullptr);
  {
    Progress progress("precompute", 3, file.get());
    EXPECT_FALSE(progress.enabled());
    progress.Advance("transmittance");
    progress.Advance("irradiance");
  }
  EXPECT_EQ(std::ftell(file.get()), 0);
}

// A pseudo-terminal stands in for the user's terminal. Skipped where none can be opened.
TEST(Progress, DrawsOnTerminalUnlessQuiet) {
  int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) {
    if (master >= 0) ::close(master);
    GTEST_SKIP() << "no pseudo-terminal available";
  }
  std::FILE* terminal = std::fopen(::ptsname(master), "w");
  ASSERT_NE(terminal, nullptr);
  // The test sets the variable itself; the caller's value is put back at the end.
  const char* saved = std::getenv("AERIAL_NO_PROGRESS");
  std::string saved_value = saved ? saved : "";
  ::unsetenv("AERIAL_NO_PROGRESS");
  {
    Progress progress("precompute", 2, terminal);
    EXPECT_TRUE(progress.enabled());
    progress.Advance("transmittance");
    progress.Advance("irradiance");
  }
  EXPECT_FALSE(Progress("t", 1, terminal, /*quiet=*/true).enabled());
  ::setenv("AERIAL_NO_PROGRESS", "1", 1);
  EXPECT_FALSE(Progress("t", 1, terminal).enabled());
  if (saved) {
    ::setenv("AERIAL_NO_PROGRESS", saved_value.c_str(), 1);
  } else {
    ::unsetenv("AERIAL_NO_PROGRESS");
  }
  std::fclose(terminal);

  // The pseudo-terminal hands written bytes to its reader asynchronously (a kernel work queue),
  // so on a loaded machine they may arrive late: wait for them, up to a generous 5 s.
  std::string text;
  ::fcntl(master, F_SETFL, O_NONBLOCK);
  for (int waited_ms = 0; text.find("2/2 irradiance") == std::string::npos && waited_ms < 5000;
       waited_ms += 50) {
    pollfd ready{.fd = master, .events = POLLIN, .revents = 0};
    if (::poll(&ready, 1, 50) <= 0) continue;
    char buffer[512];
    ssize_t got = ::read(master, buffer, sizeof buffer);
    if (got > 0) text.append(buffer, static_cast<size_t>(got));
  }
  ::close(master);
  ASSERT_FALSE(text.empty());
  EXPECT_NE(text.find("\rprecompute [##########..........] 1/2 transmittance"), std::string::npos)
      << text;
  EXPECT_NE(text.find("\rprecompute [####################] 2/2 irradiance"), std::string::npos)
      << text;
}

}  // namespace
}  // namespace aerial
