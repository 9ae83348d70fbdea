#include "aerial/core/json_depth.h"

#include <algorithm>

#include "aerial/core/input_limits.h"
#include "aerial/error.h"

namespace aerial {

JsonShape MeasureJson(std::string_view json) {
  JsonShape shape{.values = json.empty() ? 0u : 1u};
  size_t depth = 0;
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
      shape.depth = std::max(shape.depth, ++depth);
      ++shape.values;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    } else if (c == ',') {
      ++shape.values;
    }
  }
  return shape;
}

size_t JsonNestingDepth(std::string_view json) { return MeasureJson(json).depth; }

void CheckJsonDepth(std::string_view json, const std::string& where) {
  size_t depth = JsonNestingDepth(json);
  if (depth > kMaxJsonDepth) {
    throw Error("JSON nesting", std::to_string(depth) + " levels",
                "at most " + std::to_string(kMaxJsonDepth) + " levels of nested arrays and objects",
                where);
  }
}

}  // namespace aerial
