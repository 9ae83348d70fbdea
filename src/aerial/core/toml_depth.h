#pragma once
// A cap on how deeply a TOML text nests, checked before toml++ sees it: toml++ recurses once per
// part of a dotted key ("x.x.x = 1", "[x.x.x]") and per level of inline arrays and tables, and a
// key of 40,000 parts overflows the stack. (json_depth.h does the same for glTF's JSON.)
#include <cstddef>
#include <string>
#include <string_view>

namespace aerial {

// The deepest nesting in toml, by a scan outside strings and comments: open brackets and braces
// plus the parts of the dotted key or number being read ("a.b.c = 1" is 3, "x = [[1]]" is 3).
// Strings are skipped by TOML 1.0's rules for each of its four forms (basic, literal and their
// multi-line forms, with their escapes and the quotes a multi-line string may hold), so that no
// valid string can hide what follows it. It does not check that toml is valid; the parser does
// that afterwards.
size_t TomlNestingDepth(std::string_view toml);

// Throws Error("TOML nesting", "<depth> levels", ..., where) when toml nests deeper than
// kMaxTomlDepth (input_limits.h). where names the file.
void CheckTomlDepth(std::string_view toml, const std::string& where);

}  // namespace aerial
