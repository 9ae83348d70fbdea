#include "aerial/core/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>

namespace aerial {
namespace {

// AERIAL_NO_PROGRESS set to anything but "" or "0" silences the bar.
bool QuietFromEnvironment() {
  const char* value = std::getenv("AERIAL_NO_PROGRESS");
  return value != nullptr && *value != '\0' && std::string_view(value) != "0";
}

}  // namespace

std::string ProgressLine(std::string_view title, int done_steps, int total_steps,
                         std::string_view step_label, int bar_width) {
  int total = std::max(total_steps, 1);
  int done = std::clamp(done_steps, 0, total);
  int filled = done * bar_width / total;
  std::string line(title);
  if (!line.empty()) line += ' ';
  line += '[';
  line.append(filled, '#');
  line.append(bar_width - filled, '.');
  line += "] " + std::to_string(done) + "/" + std::to_string(total_steps);
  if (!step_label.empty()) line += ' ' + std::string(step_label);
  return line;
}

Progress::Progress(std::string title, int total_steps, std::FILE* out, bool quiet)
    : title_(std::move(title)),
      total_steps_(total_steps),
      out_(out),
      enabled_(!quiet && out != nullptr && !QuietFromEnvironment() && ::isatty(::fileno(out))) {}

Progress::~Progress() { Finish(); }

void Progress::Advance(std::string_view step_label) {
  ++done_steps_;
  if (observer_) observer_(done_steps_, total_steps_, step_label);
  if (!enabled_ || finished_) return;
  std::string line = ProgressLine(title_, done_steps_, total_steps_, step_label);
  size_t length = line.size();
  if (length < last_length_) line.append(last_length_ - length, ' ');
  last_length_ = length;
  std::fprintf(out_, "\r%s", line.c_str());
  std::fflush(out_);
}

void Progress::Finish() {
  if (finished_) return;
  finished_ = true;
  if (enabled_ && last_length_ > 0) {
    std::fputc('\n', out_);
    std::fflush(out_);
  }
}

}  // namespace aerial
