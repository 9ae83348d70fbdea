#pragma once
// A one-line progress bar for long commands (the precompute takes tens of seconds on a CPU
// Vulkan driver). It draws only on a terminal: redirected output (logs, CI, pipes) stays free of
// carriage returns. Set AERIAL_NO_PROGRESS=1, or pass quiet, to silence it on a terminal too.
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>

namespace aerial {

class Progress {
 public:
  Progress(std::string title, int total_steps, std::FILE* out = stderr, bool quiet = false);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Marks one more step done; step_label names the step that just finished or now runs.
  void Advance(std::string_view step_label);
  // Ends the line. Called by the destructor if not called before.
  void Finish();

  bool enabled() const { return enabled_; }

  // Also tells observer of every step (from Advance, on the caller's thread), drawn or not: a
  // window shows the same progress in its own bar.
  using Observer = std::function<void(int done_steps, int total_steps, std::string_view step_label)>;
  void set_observer(Observer observer) { observer_ = std::move(observer); }

 private:
  std::string title_;
  int total_steps_;
  int done_steps_ = 0;
  std::FILE* out_;
  bool enabled_;
  bool finished_ = false;
  size_t last_length_ = 0;  // to blank the rest of a longer previous line.
  Observer observer_;
};

// The text of one bar update, without the leading \r: "title [#####.....] 3/9 label".
std::string ProgressLine(std::string_view title, int done_steps, int total_steps,
                         std::string_view step_label, int bar_width = 20);

}  // namespace aerial
