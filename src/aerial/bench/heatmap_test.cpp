#include "aerial/bench/heatmap.h"

#include <gtest/gtest.h>

#include "aerial/bench/font5x7.h"

namespace aerial::bench {
namespace {

TEST(NiceCeiling, OneTwoFiveSteps) {
  EXPECT_DOUBLE_EQ(NiceCeiling(0.013), 0.02);
  EXPECT_DOUBLE_EQ(NiceCeiling(0.05), 0.05);
  EXPECT_DOUBLE_EQ(NiceCeiling(0.051), 0.1);
  EXPECT_DOUBLE_EQ(NiceCeiling(3.0), 5.0);
}

TEST(FormatPercent, NoTrailingZeros) {
  EXPECT_EQ(FormatPercent(0.025), "2.5%");
  EXPECT_EQ(FormatPercent(0.0), "0%");
  EXPECT_EQ(FormatPercent(2.0), "200%");
}

TEST(HeatColor, EndsOfInfernoAndClamped) {
  Rgb low = HeatColor(0.0), high = HeatColor(1.0), above = HeatColor(7.0);
  EXPECT_EQ((std::array<int, 3>{low.r, low.g, low.b}), (std::array<int, 3>{0, 0, 4}));
  EXPECT_EQ((std::array<int, 3>{high.r, high.g, high.b}), (std::array<int, 3>{252, 255, 164}));
  EXPECT_EQ((std::array<int, 3>{above.r, above.g, above.b}), (std::array<int, 3>{252, 255, 164}));
}

TEST(Font5x7, EveryGlyphIsFiveBySeven) {
  for (char c : std::string(" 0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ.,-+%:/()|=<>_")) {
    const auto* glyph = Glyph5x7(c);
    ASSERT_NE(glyph, nullptr) << c;
    for (const char* row : *glyph) EXPECT_EQ(std::string(row).size(), size_t(kGlyphWidth)) << c;
  }
  EXPECT_EQ(Glyph5x7('a'), Glyph5x7('A'));
  EXPECT_EQ(Glyph5x7('~'), nullptr);
}

TEST(Canvas, TextWidthCountsGlyphsAndGaps) {
  EXPECT_EQ(Canvas::TextWidth("10%", 2), (3 * kGlyphAdvance - 1) * 2);
  Canvas canvas(12, 7, {255, 255, 255});
  canvas.Text(0, 0, "1", 1, {0, 0, 0});
  int lit = 0;
  for (size_t i = 0; i < canvas.rgba8().size(); i += 4) lit += canvas.rgba8()[i] == 0;
  EXPECT_EQ(lit, 10);  // the '1' glyph has 10 lit pixels
}

}  // namespace
}  // namespace aerial::bench
