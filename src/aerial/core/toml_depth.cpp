#include "aerial/core/toml_depth.h"

#include <algorithm>

#include "aerial/core/input_limits.h"
#include "aerial/error.h"

namespace aerial {
namespace {

// The index just past the string that opens at `at` (a basic or literal string, on one line or
// multi-line), or the end of toml when it is not closed.
size_t SkipString(std::string_view toml, size_t at) {
  char quote = toml[at];
  bool multi_line = toml.substr(at, 3) == std::string(3, quote);
  std::string_view close = multi_line ? toml.substr(at, 3) : toml.substr(at, 1);
  for (size_t i = at + close.size(); i < toml.size(); ++i) {
    if (quote == '"' && toml[i] == '\\') {
      ++i;  // the escaped character
    } else if (toml.substr(i, close.size()) == close) {
      return i + close.size();
    } else if (!multi_line && toml[i] == '\n') {
      return i;
    }
  }
  return toml.size();
}

}  // namespace

size_t TomlNestingDepth(std::string_view toml) {
  size_t brackets = 0, dots = 0, deepest = 0;
  for (size_t i = 0; i < toml.size(); ++i) {
    char c = toml[i];
    if (c == '"' || c == '\'') {
      i = SkipString(toml, i) - 1;
      continue;
    }
    if (c == '#') {
      i = std::min(toml.find('\n', i), toml.size()) - 1;
      continue;
    }
    if (c == '[' || c == '{') {
      ++brackets;
      dots = 0;
    } else if (c == ']' || c == '}') {
      brackets -= brackets > 0;
      dots = 0;
    } else if (c == '=' || c == ',' || c == '\n') {
      dots = 0;
    } else if (c == '.') {
      ++dots;
    }
    deepest = std::max(deepest, brackets + dots + 1);
  }
  return toml.empty() ? 0 : deepest;
}

void CheckTomlDepth(std::string_view toml, const std::string& where) {
  size_t depth = TomlNestingDepth(toml);
  if (depth > kMaxTomlDepth) {
    throw Error("TOML nesting", std::to_string(depth) + " levels",
                "at most " + std::to_string(kMaxTomlDepth) +
                    " levels of dotted key parts and nested arrays and tables",
                where);
  }
}

}  // namespace aerial
