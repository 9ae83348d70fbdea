#include "aerial/error.h"

#include <gtest/gtest.h>

#include <string>

namespace aerial {
namespace {

TEST(Shortened, KeepsTextUpToTheCapWhole) {
  std::string text(kMaxShownBytes, 'a');
  EXPECT_EQ(Shortened(text), text);
}

TEST(Shortened, CutsLongerTextAndSaysHowLong) {
  std::string text(kMaxShownBytes + 1, 'a');
  EXPECT_EQ(Shortened(text), std::string(kMaxShownBytes, 'a') + "\u2026 (" +
                                 std::to_string(kMaxShownBytes + 1) + " bytes)");
}

TEST(Shortened, DoesNotSplitAUtf8Character) {
  // "é" is 2 bytes; one byte short of the cap, it would straddle the cut.
  std::string text = std::string(kMaxShownBytes - 1, 'a') + "\u00e9" + "tail";
  EXPECT_EQ(Shortened(text), std::string(kMaxShownBytes - 1, 'a') + "\u2026 (" +
                                 std::to_string(text.size()) + " bytes)");
}

TEST(ErrorMessage, ShowsALongValueShortenedAndKeepsItWhole) {
  std::string uri = "data:application/octet-stream;base64," + std::string(5000, 'A');
  Error e("buffers[0].uri", uri, "a data URI of byteLength bytes", "model.gltf");
  EXPECT_EQ(e.value(), uri);
  EXPECT_EQ(std::string(e.what()), "model.gltf: buffers[0].uri = " + Shortened(uri) +
                                       " is invalid; expected a data URI of byteLength bytes");
}

// Control characters, DEL, C1 controls and bytes outside UTF-8 are escaped; other text, UTF-8
// included, is kept. Before, a glTF URI or a name reached the terminal raw (ESC ] 0 ; sets the
// window's title, ESC [ 2 J clears the screen), and a NUL cut the message short.
TEST(Printable, EscapesWhatATerminalWouldObey) {
  EXPECT_EQ(Printable("plain été …"), "plain été …");
  EXPECT_EQ(Printable(std::string("a\x1b]0;t\x07" "b\0c\x7f\n", 12)), "a\\x1b]0;t\\x07b\\x00c\\x7f\\x0a");
  EXPECT_EQ(Printable("\xc2\x9b" "2J"), "\\u009b2J");        // C1 CSI, as UTF-8
  EXPECT_EQ(Printable("\x9b" "2J\xff\xc3"), "\\x9b2J\\xff\\xc3");  // not UTF-8
  EXPECT_EQ(Printable("\xed\xa0\x80"), "\\xed\\xa0\\x80") << "a UTF-16 surrogate is not UTF-8";
}

TEST(ErrorMessage, EscapesControlCharactersAndKeepsWhatFollowsANul) {
  Error e("buffers[0].uri", std::string("a\0b\x1b[2J", 7), "a file", "m\x1b.gltf");
  EXPECT_EQ(std::string(e.what()), "m\\x1b.gltf: buffers[0].uri = a\\x00b\\x1b[2J is invalid; expected a file");
  EXPECT_EQ(e.value(), std::string("a\0b\x1b[2J", 7)) << "the value itself stays as it was";
}

}  // namespace
}  // namespace aerial
