#pragma once
// A cap on how deeply a JSON text nests, checked before a parser sees it: tinygltf's JSON parser
// recurses once per level of arrays and objects, and a file nesting 100,000 levels deep would
// overflow the stack.
#include <cstddef>
#include <string>
#include <string_view>

namespace aerial {

// The deepest nesting of arrays and objects in json ("[[]]" is 2), by one scan of its brackets
// outside strings. It does not check that json is valid; the parser does that afterwards.
size_t JsonNestingDepth(std::string_view json);

// Throws Error("JSON nesting", "<depth> levels", ..., where) when json nests deeper than
// kMaxJsonDepth (input_limits.h). where names the file.
void CheckJsonDepth(std::string_view json, const std::string& where);

}  // namespace aerial
