#include "aerial/core/json_depth.h"

#include <gtest/gtest.h>

#include <string>

#include "aerial/core/input_limits.h"
#include "aerial/error.h"

namespace aerial {
namespace {

std::string Nested(size_t levels) { return std::string(levels, '[') + std::string(levels, ']'); }

TEST(JsonDepth, CountsNestedArraysAndObjects) {
  EXPECT_EQ(JsonNestingDepth("42"), 0u);
  EXPECT_EQ(JsonNestingDepth("[]"), 1u);
  EXPECT_EQ(JsonNestingDepth(R"({"a": [1, {"b": []}], "c": {}})"), 4u);
  EXPECT_EQ(JsonNestingDepth("[[]][[[]]]"), 3u) << "the deepest, not the sum";
}

TEST(JsonDepth, IgnoresBracketsInStrings) {
  EXPECT_EQ(JsonNestingDepth(R"(["[[[{{{", "\"[[[", "\\", []])"), 2u);
}

TEST(JsonDepth, CapIsInclusive) {
  EXPECT_NO_THROW(CheckJsonDepth(Nested(kMaxJsonDepth), "x.gltf"));
  try {
    CheckJsonDepth(Nested(kMaxJsonDepth + 1), "x.gltf");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "JSON nesting");
    EXPECT_EQ(e.value(), std::to_string(kMaxJsonDepth + 1) + " levels");
    EXPECT_EQ(e.where(), "x.gltf");
  }
}

}  // namespace
}  // namespace aerial
