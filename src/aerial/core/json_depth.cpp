#include "aerial/core/json_depth.h"

#include <algorithm>

#include "aerial/core/input_limits.h"
#include "aerial/error.h"

namespace aerial {

size_t JsonNestingDepth(std::string_view json) {
  size_t depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (char c : json) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

void CheckJsonDepth(std::string_view json, const std::string& where) {
  size_t depth = JsonNestingDepth(json);
  if (depth > kMaxJsonDepth) {
    throw Error("JSON nesting", std::to_string(depth) + " levels",
                "at most " + std::to_string(kMaxJsonDepth) + " levels of nested arrays and objects",
                where);
  }
}

}  // namespace aerial
