#pragma once
// Screen-space debug text the renderer draws over the tonemapped image (after tonemapping,
// before the capture copy and the window blit), so windowed runs and headless captures show
// it alike. The font is the engine's own 5x7 bitmap: digits, A-Z (lower case drawn as upper
// case), space and . , : ; ! ? - + = / ( ) % ' " # _ < > * [ ] |; anything else draws a box.
#include <array>
#include <cstdint>
#include <string>

namespace candela::render {

struct TextLine {
    std::int32_t x = 8;  // top-left pixel of the first character
    std::int32_t y = 8;
    std::uint32_t scale = 2;              // pixels per font texel, 1..8
    std::array<float, 3> color{1, 1, 1};  // display (sRGB-encoded) values in 0..1
    std::string text;                     // '\n' starts a new line below
};

// Pixel metrics at scale 1: a character is 5x7 texels, advances 6, lines advance 9; each
// character also gets a one-texel black outline so it reads on any background.
inline constexpr std::int32_t kTextAdvance = 6;
inline constexpr std::int32_t kTextLineAdvance = 9;
inline constexpr std::uint32_t kTextMaxScale = 8;

}  // namespace candela::render
