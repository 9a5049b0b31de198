#pragma once
// The debug text's 5x7 font, drawn for Candela. Each glyph is two words: rows 0-3 in the bytes
// of word 0 and rows 4-6 in word 1 (row r in byte r % 4); in a row byte, bit 4 is the leftmost
// column. debug_text.comp reads the same words from its storage buffer.
#include <array>
#include <cstdint>
#include <span>

namespace candela::render {

using GlyphBits = std::array<std::uint32_t, 2>;

// Every glyph, padded to kFontWords / 2 entries (the shader's fixed font array).
inline constexpr std::uint32_t kFontWords = 128;
std::span<const GlyphBits> fontGlyphs();

// The glyph drawing `c`: lower case as upper case, characters without one as a box.
std::uint32_t glyphIndex(char c);

// Whether texel (column, row) of glyph `index` is inked; false outside the 5x7 cell.
bool glyphInked(std::uint32_t index, int column, int row);

}  // namespace candela::render
