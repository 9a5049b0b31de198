#include "passes/debug_text/bitmap_font.h"

#include <string_view>

namespace candela::render {

namespace {

// The characters in table order; the last entry (DEL) is the box for everything else.
constexpr std::string_view kCharacters =
    " 0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ.,:;!?-+=/()%'\"#_<>*[]|\x7f";

// Drawn on a 5x7 grid for Candela; see the header for the packing.
constexpr GlyphBits kGlyphs[] = {
    {0x00000000u, 0x00000000u},  // space
    {0x1513110eu, 0x000e1119u},  // 0
    {0x04040c04u, 0x000e0404u},  // 1
    {0x0201110eu, 0x001f0804u},  // 2
    {0x0e01011eu, 0x001e0101u},  // 3
    {0x120a0602u, 0x0002021fu},  // 4
    {0x011e101fu, 0x000e1101u},  // 5
    {0x1e100806u, 0x000e1111u},  // 6
    {0x0402011fu, 0x00080808u},  // 7
    {0x0e11110eu, 0x000e1111u},  // 8
    {0x0f11110eu, 0x000c0201u},  // 9
    {0x1f11110eu, 0x00111111u},  // A
    {0x1e11111eu, 0x001e1111u},  // B
    {0x1010110eu, 0x000e1110u},  // C
    {0x1111121cu, 0x001c1211u},  // D
    {0x1e10101fu, 0x001f1010u},  // E
    {0x1e10101fu, 0x00101010u},  // F
    {0x1710110eu, 0x000f1111u},  // G
    {0x1f111111u, 0x00111111u},  // H
    {0x0404040eu, 0x000e0404u},  // I
    {0x02020207u, 0x000c1202u},  // J
    {0x18141211u, 0x00111214u},  // K
    {0x10101010u, 0x001f1010u},  // L
    {0x15151b11u, 0x00111111u},  // M
    {0x15191111u, 0x00111113u},  // N
    {0x1111110eu, 0x000e1111u},  // O
    {0x1e11111eu, 0x00101010u},  // P
    {0x1111110eu, 0x000d1215u},  // Q
    {0x1e11111eu, 0x00111214u},  // R
    {0x0e10100fu, 0x001e0101u},  // S
    {0x0404041fu, 0x00040404u},  // T
    {0x11111111u, 0x000e1111u},  // U
    {0x11111111u, 0x00040a11u},  // V
    {0x15111111u, 0x000a1515u},  // W
    {0x040a1111u, 0x0011110au},  // X
    {0x040a1111u, 0x00040404u},  // Y
    {0x0402011fu, 0x001f1008u},  // Z
    {0x00000000u, 0x000c0c00u},  // .
    {0x00000000u, 0x0008040cu},  // ,
    {0x000c0c00u, 0x00000c0cu},  // :
    {0x000c0c00u, 0x0008040cu},  // ;
    {0x04040404u, 0x00040004u},  // !
    {0x0201110eu, 0x00040004u},  // ?
    {0x1f000000u, 0x00000000u},  // -
    {0x1f040400u, 0x00000404u},  // +
    {0x001f0000u, 0x0000001fu},  // =
    {0x04020101u, 0x00101008u},  // /
    {0x08080402u, 0x00020408u},  // (
    {0x02020408u, 0x00080402u},  // )
    {0x04021919u, 0x00131308u},  // %
    {0x00080404u, 0x00000000u},  // '
    {0x000a0a0au, 0x00000000u},  // "
    {0x0a1f0a0au, 0x000a0a1fu},  // #
    {0x00000000u, 0x001f0000u},  // _
    {0x10080402u, 0x00020408u},  // <
    {0x01020408u, 0x00080402u},  // >
    {0x1f0e1500u, 0x0000150eu},  // *
    {0x0808080eu, 0x000e0808u},  // [
    {0x0202020eu, 0x000e0202u},  // ]
    {0x04040404u, 0x00040404u},  // |
    {0x1111111fu, 0x001f1111u},  // unknown
};

static_assert(std::size(kGlyphs) == kCharacters.size());
static_assert(std::size(kGlyphs) * 2 <= kFontWords, "the shader's font array holds them all");

}  // namespace

std::span<const GlyphBits> fontGlyphs() {
    return kGlyphs;
}

std::uint32_t glyphIndex(char c) {
    if (c >= 'a' && c <= 'z') c = char(c - 'a' + 'A');
    const size_t at = kCharacters.find(c);
    return std::uint32_t(at == std::string_view::npos ? kCharacters.size() - 1 : at);
}

bool glyphInked(std::uint32_t index, int column, int row) {
    if (index >= std::size(kGlyphs) || column < 0 || column >= 5 || row < 0 || row >= 7) {
        return false;
    }
    const std::uint32_t bits = (kGlyphs[index][std::size_t(row / 4)] >> (8 * (row % 4))) & 0xffu;
    return ((bits >> (4 - column)) & 1u) != 0;
}

}  // namespace candela::render
