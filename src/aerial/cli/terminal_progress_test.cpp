#include "aerial/cli/terminal_progress.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <regex>
#include <string>

#include "aerial/cli/common_options.h"
#include "tests/pseudo_terminal.h"

namespace aerial::cli {
namespace {

// The library's callback drives the command line's bar: one bar per run of steps, its line ended
// at the last step, and a run that failed part way does not carry its count into the next.
TEST(TerminalProgress, DrawsOneBarPerRunOfStepsOnATerminal) {
  testing::PseudoTerminal terminal;
  if (!terminal.available()) GTEST_SKIP() << "no pseudo-terminal available";
  if (const char* quiet = std::getenv("AERIAL_NO_PROGRESS"); quiet && *quiet && std::string(quiet) != "0")
    GTEST_SKIP() << "AERIAL_NO_PROGRESS silences the bar";
  ProgressCallback progress = TerminalProgress("precompute 4d", terminal.file());
  progress(1, 2, "transmittance");
  progress(2, 2, "irradiance");
  progress(1, 3, "failed");  // a run that ends here, with an error
  progress(1, 2, "again");
  progress(2, 2, "end");
  std::fputs("|", terminal.file());
  const std::string text = terminal.ReadUntil("|");
  EXPECT_NE(text.find("\rprecompute 4d [##########..........] 1/2 transmittance"), std::string::npos) << text;
  EXPECT_NE(text.find("\rprecompute 4d [##########..........] 1/2 again"), std::string::npos) << text;
  // Each last step ends its line: spaces blank what is left of a longer line before it, and the
  // terminal writes the newline as \r\n.
  EXPECT_TRUE(std::regex_search(text, std::regex(R"(\rprecompute 4d \[#{20}\] 2/2 irradiance *\r\n)"))) << text;
  EXPECT_TRUE(std::regex_search(text, std::regex(R"(\rprecompute 4d \[#{20}\] 2/2 end *\r\n)"))) << text;
}

// --quiet leaves the callback out; the library then reports to no one and draws nothing.
TEST(TerminalProgress, QuietCommandsHaveNoProgressCallback) {
  TableOptions options;
  EXPECT_TRUE(options.MakeLoadOptions().progress);
  options.quiet = true;
  EXPECT_FALSE(options.MakeLoadOptions().progress);
}

}  // namespace
}  // namespace aerial::cli
