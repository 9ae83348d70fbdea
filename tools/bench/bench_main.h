#pragma once
// The shared tail of the benchmarks' main(): parse the options, run, and turn every error into a
// message and exit status 1 (CLI11's own errors keep CLI11's exit codes).
#include <cstdio>
#include <exception>
#include <functional>

#include <CLI/CLI.hpp>

namespace aerial::bench {

inline int ParseAndRun(CLI::App& app, int argc, char** argv, const char* tool,
                       const std::function<void()>& run) {
  try {
    app.parse(argc, argv);
    run();
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {  // aerial::Error included: its message names field and value
    std::fprintf(stderr, "%s: error: %s\n", tool, e.what());
    return 1;
  }
  return 0;
}

}  // namespace aerial::bench
