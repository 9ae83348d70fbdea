#pragma once
// A 5x7 bitmap font for the figures' labels: digits, capital letters and the punctuation numbers
// and units need. Lower-case letters are drawn as capitals.
#include <array>

namespace aerial::bench {

inline constexpr int kGlyphWidth = 5, kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = 6;  // one column of space between characters

// Rows from the top; in each row '#' marks a lit pixel. nullptr for a character the font lacks.
const std::array<const char*, kGlyphHeight>* Glyph5x7(char c);

}  // namespace aerial::bench
