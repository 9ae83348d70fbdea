#include "aerial/core/toml_depth.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "aerial/core/input_limits.h"
#include "aerial/core/toml_reader.h"
#include "aerial/error.h"

namespace aerial {
namespace {

// "x.x.x = 1" (as a key) or "[x.x.x]" (as a header) with parts key parts.
std::string DottedKey(size_t parts, bool header = false) {
  std::string text = header ? "[x" : "x";
  for (size_t i = 1; i < parts; ++i) text += ".x";
  text += header ? "]\n" : " = 1\n";
  return text;
}

TEST(TomlDepth, CountsKeyPartsAndBrackets) {
  EXPECT_EQ(TomlNestingDepth(""), 0u);
  EXPECT_EQ(TomlNestingDepth("a = 1\n"), 1u);
  EXPECT_EQ(TomlNestingDepth("a.b.c = 1\n"), 3u);
  EXPECT_EQ(TomlNestingDepth("x = [[1]]\n"), 3u);
  EXPECT_EQ(TomlNestingDepth("[a.b]\nc = {d = [1]}\n"), 3u) << "the deepest, not the sum";
  EXPECT_EQ(TomlNestingDepth("c = {d = [1.5]}\n"), 4u) << "a number's dot counts too";
}

TEST(TomlDepth, IgnoresStringsAndComments) {
  EXPECT_EQ(TomlNestingDepth(R"(a = "[[[...\"[[" # [[[...)"), 1u);
  EXPECT_EQ(TomlNestingDepth("a = '[[[...'\nb = '''\n[[[\n'''\nc = \"\"\"\n[[[\\\"\"\"\"\n"), 1u);
  EXPECT_EQ(TomlNestingDepth("\"a.b\".\"c.d\" = 1\n"), 2u) << "dots between quoted parts count";
}

TEST(TomlDepth, CapIsInclusive) {
  EXPECT_NO_THROW(CheckTomlDepth(DottedKey(kMaxTomlDepth), "x.toml"));
  try {
    CheckTomlDepth(DottedKey(kMaxTomlDepth + 1), "x.toml");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "TOML nesting");
    EXPECT_EQ(e.value(), std::to_string(kMaxTomlDepth + 1) + " levels");
    EXPECT_EQ(e.where(), "x.toml");
  }
}

// 40,000 dotted parts (80 KB) overflow toml++'s stack (SIGSEGV) if a reader parses them.
TEST(TomlDepth, ReaderRefusesAHugeDottedKeyBeforeParsing) {
  for (const std::string& text : {DottedKey(40000), DottedKey(40000, true)}) {
    try {
      TomlReader("deep.toml").Parse(text);
      FAIL() << "parsed";
    } catch (const Error& e) {
      EXPECT_EQ(e.field(), "TOML nesting");
      EXPECT_EQ(e.where(), "deep.toml");
    }
  }
}

// "x.x.x" with parts parts.
std::string KeyParts(size_t parts) {
  std::string key = "x";
  for (size_t i = 1; i < parts; ++i) key += ".x";
  return key;
}

// The strings of TOML 1.0's four forms, each valid, with the quotes and escapes that end them.
const std::vector<std::string> kStrings = {
    R"("x")",          R"("x\"")",         R"("x\\")",        R"('x\')",          R"("")",
    R"('')",           R"("""x""")",       R"("""x"""")",     R"("""x""""")",     R"("""x""y""")",
    R"("""x\"""")",    "\"\"\"x\n\"\n\"\"\n\"\"\"", R"("""""")", R"('''x''')",    R"('''x'''')",
    R"('''x''''')",    R"('''x''y\''')",   R"('''''')",       "'''x\n'\n''\n'''"};

// Each string form ends where the parser ends it, so that what follows it is counted. Before, a
// multi-line string closed by four quotes ("""x"""", which holds x") left a quote that hid the
// rest of its line from the count (depth 2 here instead of 4).
TEST(TomlDepth, EveryStringFormEndsWhereTheParserEndsIt) {
  for (const std::string& string : kStrings) {
    std::string text = "t = { a = " + string + ", " + KeyParts(3) + " = 1 }\n";
    EXPECT_EQ(TomlNestingDepth(text), 4u) << text;
    EXPECT_NO_THROW(TomlReader("s.toml").Parse(text)) << text << ": the case must be valid TOML";
  }
}

// Before: a dotted key of 400,000 parts after """x"""" on the same line crashed (SIGSEGV) every
// reader again.
TEST(TomlDepth, ReaderRefusesADeepKeyAfterAnyString) {
  for (const std::string& string : kStrings) {
    std::string text = "t = { a = " + string + ", " + KeyParts(400000) + " = 1 }\n";
    try {
      TomlReader("deep.toml").Parse(text);
      FAIL() << "parsed after " << string;
    } catch (const Error& e) {
      EXPECT_EQ(e.field(), "TOML nesting") << string;
    }
  }
}

}  // namespace
}  // namespace aerial
