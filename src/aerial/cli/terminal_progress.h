#pragma once
// The command line's progress bar for the library's long calls, which report progress through a
// callback (aerial/tables.h, ProgressCallback) and draw nothing themselves.
#include <cstdio>
#include <string>

#include "aerial/tables.h"

namespace aerial::cli {

// A callback that draws a one-line bar (core/progress.h: only on a terminal, and not with
// AERIAL_NO_PROGRESS) titled `title` on `out`. Each run of steps (done = 1 starts one) gets its own
// bar, which ends its line at the last step, or when the callback and its copies are destroyed
// (a call that failed part way).
ProgressCallback TerminalProgress(std::string title, std::FILE* out = stderr);

}  // namespace aerial::cli
