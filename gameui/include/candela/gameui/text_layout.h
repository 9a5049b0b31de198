#pragma once
// Lays text out in a box: UTF-8 decoded, lines broken at spaces to fit the box's width (a word
// wider than the box is broken between letters), '\n' starting a new line, each line aligned
// left, centred or right, kerned. The result is glyphs with pen positions in pixels (origin at
// the box's top-left, y down), for a renderer to place atlas quads at.
//
//   TextStyle style{.pixelSize = 24, .align = TextAlign::Center};
//   TextLayout layout = layoutText(*font, "Press Start", style, 300.0f);
#include <cstdint>
#include <string_view>
#include <vector>

#include "candela/gameui/font.h"

namespace candela::gameui {

enum class TextAlign : std::uint8_t { Left, Center, Right };

struct TextStyle {
    float pixelSize = 16.0f;  // the em height in pixels
    TextAlign align = TextAlign::Left;
    float lineSpacing = 1.0f;  // multiplies the font's line height
};

struct PlacedGlyph {
    std::uint32_t glyph = 0;  // the font's glyph index
    char32_t codepoint = 0;
    float x = 0;         // the pen on the baseline, pixels from the box's left
    float baseline = 0;  // pixels from the box's top
};

struct TextLayout {
    std::vector<PlacedGlyph> glyphs;  // spaces and line breaks left out
    std::vector<float> lineWidths;    // pixels, one per line
    float width = 0;                  // the widest line
    float height = 0;                 // all lines, top of the first to the bottom of the last
};

// `maxWidth` <= 0: no wrapping (lines break only at '\n').
TextLayout layoutText(const Font& font, std::string_view utf8, const TextStyle& style,
                      float maxWidth);

}  // namespace candela::gameui
