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

}  // namespace
}  // namespace aerial
