#include "aerial/core/progress.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "tests/pseudo_terminal.h"

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
  testing::PseudoTerminal terminal;
  if (!terminal.available()) GTEST_SKIP() << "no pseudo-terminal available";
  // The test sets the variable itself; the caller's value is put back at the end.
  const char* saved = std::getenv("AERIAL_NO_PROGRESS");
  std::string saved_value = saved ? saved : "";
  ::unsetenv("AERIAL_NO_PROGRESS");
  {
    Progress progress("precompute", 2, terminal.file());
    EXPECT_TRUE(progress.enabled());
    progress.Advance("transmittance");
    progress.Advance("irradiance");
  }
  EXPECT_FALSE(Progress("t", 1, terminal.file(), /*quiet=*/true).enabled());
  ::setenv("AERIAL_NO_PROGRESS", "1", 1);
  EXPECT_FALSE(Progress("t", 1, terminal.file()).enabled());
  if (saved) {
    ::setenv("AERIAL_NO_PROGRESS", saved_value.c_str(), 1);
  } else {
    ::unsetenv("AERIAL_NO_PROGRESS");
  }

  const std::string text = terminal.ReadUntil("2/2 irradiance");
  ASSERT_FALSE(text.empty());
  EXPECT_NE(text.find("\rprecompute [##########..........] 1/2 transmittance"), std::string::npos)
      << text;
  EXPECT_NE(text.find("\rprecompute [####################] 2/2 irradiance"), std::string::npos)
      << text;
}

}  // namespace
}  // namespace aerial
