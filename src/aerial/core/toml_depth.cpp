#include "aerial/core/toml_depth.h"

#include <algorithm>

#include "aerial/core/input_limits.h"
#include "aerial/error.h"

namespace aerial {
namespace {

// How many quote characters in a row start at `at`.
size_t QuoteRun(std::string_view toml, size_t at, char quote) {
  size_t end = at;
  while (end < toml.size() && toml[end] == quote) ++end;
  return end - at;
}

// The index just past the string that opens at `at`, by TOML 1.0's four string forms
// (https://toml.io/en/v1.0.0#string), or the end of toml when it is not closed (the parser then
// reports it):
//  - basic "...": a backslash escapes the next character; a newline ends it (an error);
//  - multi-line basic """...""": escapes as in basic; one or two quotes may stand anywhere inside,
//    also just before the closing three, so a run of three or more quotes closes it and the
//    quotes before the last three are content ("""x"""" holds x");
//  - literal '...': no escapes; a newline ends it;
//  - multi-line literal '''...''': no escapes; closed as the multi-line basic form.
// A run of six or more quotes is not valid TOML; it is taken as closing the string, and the
// parser stops at the quote that is left over before it reads anything after it.
size_t StringEnd(std::string_view toml, size_t at) {
  const char quote = toml[at];
  const bool escapes = quote == '"';
  const bool multi_line = QuoteRun(toml, at, quote) >= 3;
  for (size_t i = at + (multi_line ? 3 : 1); i < toml.size();) {
    const char c = toml[i];
    if (escapes && c == '\\') {
      i += 2;  // the backslash and the character it escapes
    } else if (c == quote) {
      size_t run = multi_line ? QuoteRun(toml, i, quote) : 1;
      if (!multi_line || run >= 3) return i + run;
      i += run;  // one or two quotes inside a multi-line string
    } else if (c == '\n' && !multi_line) {
      return i;
    } else {
      ++i;
    }
  }
  return toml.size();
}

}  // namespace

size_t TomlNestingDepth(std::string_view toml) {
  size_t brackets = 0, dots = 0, deepest = 0;
  for (size_t i = 0; i < toml.size();) {
    const char c = toml[i];
    if (c == '"' || c == '\'') {
      i = StringEnd(toml, i);
      continue;
    }
    if (c == '#') {  // a comment, to the end of the line
      i = std::min(toml.find('\n', i), toml.size());
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
    ++i;
  }
  return deepest;
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
