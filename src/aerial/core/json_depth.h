#pragma once
// A cap on how deeply a JSON text nests, checked before a parser sees it: tinygltf's JSON parser
// recurses once per level of arrays and objects, and a file nesting 100,000 levels deep would
// overflow the stack.
#include <cstddef>
#include <string>
#include <string_view>

namespace aerial {

// What a parse of json will build, by one scan of its brackets and commas outside strings: the
// deepest nesting of arrays and objects ("[[]]" is 2) and about how many values it holds (each
// array and object, and one per comma). It does not check that json is valid; the parser does
// that afterwards.
struct JsonShape {
  size_t depth = 0;
  size_t values = 0;
};
JsonShape MeasureJson(std::string_view json);

// MeasureJson(json).depth.
size_t JsonNestingDepth(std::string_view json);

// Throws Error("JSON nesting", "<depth> levels", ..., where) when json nests deeper than
// kMaxJsonDepth (input_limits.h). where names the file.
void CheckJsonDepth(std::string_view json, const std::string& where);

}  // namespace aerial
