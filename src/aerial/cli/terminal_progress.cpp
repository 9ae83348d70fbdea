#include "aerial/cli/terminal_progress.h"

#include <memory>

#include "aerial/core/progress.h"

namespace aerial::cli {

ProgressCallback TerminalProgress(std::string title, std::FILE* out) {
  // Shared by the callback's copies (the options that carry it are copied on their way down).
  auto bar = std::make_shared<std::unique_ptr<Progress>>();
  return [title = std::move(title), out, bar](int done, int total, std::string_view step) {
    if (done == 1 || !*bar) *bar = std::make_unique<Progress>(title, total, out);
    (*bar)->Advance(step);
    if (done >= total) bar->reset();
  };
}

}  // namespace aerial::cli
